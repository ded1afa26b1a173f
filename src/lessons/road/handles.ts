import type { Handle, Point } from '../../app/lesson';
import { nearestOnBezierPieces } from '../../math';
import type { RoadModel } from './model';
import {
  MAX_VILLAGES,
  type RoadState,
  insertVillage,
  keepStepEnd,
  roundCoordinate,
  roundPoint,
} from './state';

/** Up to this many villages every one is labelled and decorated; beyond, the map stays legible. */
export const LABEL_VILLAGES = 40;

/** What can be moved on the map: the chosen gradients, the marker p̄ and the villages. */
export function roadHandles(m: RoadModel): Handle[] {
  const v = m.state.v;
  const handles: Handle[] = [];
  // Step 0 shows the villages alone: the chosen gradients come with the construction.
  const aids = !m.stage.bare;
  if (aids && m.usesQuadraticHandle)
    handles.push({ id: 'q', label: 'B_0', position: m.quadraticControl, shape: 'square' });
  if (aids && m.usesEndGradients) {
    handles.push({ id: 'a', label: 'D_0', position: m.endHandles[0], shape: 'square' });
    handles.push({
      id: 'b',
      label: `D_{${v.length - 1}}`,
      position: m.endHandles[1],
      shape: 'square',
    });
  }
  const marker = m.shown?.marker;
  if (marker)
    handles.push({
      id: 's',
      label: 'p̄',
      position: marker.point,
      shape: 'diamond',
      showLabel: false,
    });
  const few = v.length <= LABEL_VILLAGES;
  v.forEach((village, i) =>
    handles.push({
      id: `p${i}`,
      label: `P_{${i}}`,
      position: village,
      showLabel: few,
      small: !few,
    }),
  );
  return handles;
}

/** The gradient whose tip (scaled by 1/k) is at `to`, kept to 0.01. */
const gradient = (to: Point, from: Point, k: number) => [
  roundCoordinate((to[0] - from[0]) * k),
  roundCoordinate((to[1] - from[1]) * k),
];

export function moveRoadHandle(state: RoadState, id: string, to: Point, m: RoadModel): RoadState {
  const v = state.v;
  switch (id) {
    case 'q':
      return { ...state, q: gradient(to, v[0], 2) };
    case 'a':
      return { ...state, a: gradient(to, v[0], 3) };
    case 'b':
      return { ...state, b: gradient(to, v[v.length - 1], 3) };
    case 's': {
      // The p̄ of the road point nearest to `to`, to 0.01.
      const shown = m.shown;
      const near = shown && nearestOnBezierPieces(shown.pieces, to, { boxes: shown.boxes });
      return near ? { ...state, s: Math.round((near.piece + near.t) * 100) / 100 } : state;
    }
    default: {
      const i = Number(id.slice(1));
      return { ...state, v: v.map((p, k) => (k === i ? roundPoint(to) : p)) };
    }
  }
}

export function addVillage(state: RoadState, at: Point): RoadState | null {
  if (state.v.length >= MAX_VILLAGES) return null;
  return keepStepEnd(state, { ...state, v: insertVillage(state.v, at) });
}

export function removeVillage(state: RoadState, id: string): RoadState | null {
  if (!id.startsWith('p') || state.v.length <= 2) return null;
  const i = Number(id.slice(1));
  return keepStepEnd(state, { ...state, v: state.v.filter((_, k) => k !== i) });
}
