import type { Handle, Point } from '../../app/lesson';
import { nearestOnBezierPieces } from '../../math';
import type { RoadModel } from './model';
import { type RoadState, roundCoordinate } from './state';

/**
 * What can be moved on the map besides the villages: the chosen gradients
 * (from the step that builds with them) and the marker p̄ on a built road.
 */
export function roadHandles(m: RoadModel): Handle[] {
  const handles: Handle[] = [];
  // Step 0 shows the villages alone: the chosen gradients come with the construction.
  const aids = !m.shown.is('villages');
  if (aids && m.usesQuadraticHandle)
    handles.push({ id: 'q', label: 'B_0', position: m.quadraticControl, shape: 'square' });
  if (aids && m.usesEndGradients) {
    handles.push({ id: 'a', label: 'D_0', position: m.endHandles[0], shape: 'square' });
    handles.push({
      id: 'b',
      label: `D_{${m.state.villages.length - 1}}`,
      position: m.endHandles[1],
      shape: 'square',
    });
  }
  // The global view has no marker: its roads are compared whole.
  const marker = m.globalChange ? null : m.visible?.marker;
  if (marker)
    handles.push({
      id: 's',
      label: 'p̄',
      position: marker.point,
      shape: 'diamond',
      showLabel: false,
    });
  return handles;
}

/** The gradient whose tip (scaled by 1/k) is at `to`, kept to 0.01. */
const gradient = (to: Point, from: Point, k: number) => [
  roundCoordinate((to[0] - from[0]) * k),
  roundCoordinate((to[1] - from[1]) * k),
];

export function moveRoadHandle(state: RoadState, id: string, to: Point, m: RoadModel): RoadState {
  const v = state.villages;
  switch (id) {
    case 'q':
      return { ...state, quadraticGradient: gradient(to, v[0], 2) };
    case 'a':
      return { ...state, startGradient: gradient(to, v[0], 3) };
    case 'b':
      return { ...state, endGradient: gradient(to, v[v.length - 1], 3) };
    case 's': {
      // The p̄ of the road point nearest to `to`, to 0.01.
      const visible = m.visible;
      const near = visible && nearestOnBezierPieces(visible.pieces, to, { boxes: visible.boxes });
      return near ? { ...state, pBar: Math.round((near.piece + near.t) * 100) / 100 } : state;
    }
    default:
      return state;
  }
}
