import { pointButtons } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import { type PointList, pointList } from '../../kit/pointList';
import { keepShownToEnd } from './script';
import { MAX_VILLAGES, type RoadState, roundPoint } from './state';

/** Up to this many villages every one is labelled and decorated; beyond, the map stays legible. */
export const LABEL_VILLAGES = 40;

const name = (i: number) => `P_{${i}}`;

const declared = pointList<RoadState>({
  id: 'p',
  get: (s) => s.villages,
  set: (s, villages) => ({ ...s, villages }),
  label: name,
  min: 2,
  max: MAX_VILLAGES,
  // Village coordinates are kept to 0.01.
  constrain: (_state, _index, to) => roundPoint(to),
  // A road shown to its end stays shown to its end.
  after: keepShownToEnd,
  addLabel: 'Add a village',
  removeLabel: 'Remove the last village',
});

/**
 * The villages P0 … Pm: dragged, moved by keyboard, added and removed. Three
 * things differ from the kit's list, and are kept from before:
 * - each village keeps its own label, even on one spot as another (the notes
 *   say what villages on one spot do); with many villages none is labelled
 *   and each is a dot inside the road's width. (The kit's labels for points on one spot compare
 *   every pair: 150 ms for the 500 villages of the valley, on every edit.)
 * - a new village, wherever it comes from, is kept to 0.01 like a dragged one;
 * - "Add a village" puts the new one beyond the last into the nearest
 *   stretch of road, as a double-click does.
 */
export const villagePoints: PointList<RoadState> = {
  ...declared,
  handles: (state) => {
    const few = state.villages.length <= LABEL_VILLAGES;
    return state.villages.map((position, i) => ({
      id: `${declared.id}${i}`,
      label: name(i),
      position,
      showLabel: few,
      dot: !few,
    }));
  },
  add: (state, at) => declared.add(state, roundPoint(at)),
  buttons: (api) =>
    pointButtons(api, {
      addLabel: 'Add a village',
      removeLabel: 'Remove the last village',
      count: (s) => s.villages.length,
      min: 2,
      max: MAX_VILLAGES,
      add: (s) => villagePoints.add(s, extendPolygon(s.villages)) ?? s,
      remove: (s) => declared.remove(s, s.villages.length - 1) ?? s,
    }),
};
