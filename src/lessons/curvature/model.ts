import { type ArcModel, deriveArc } from './arcModel';
import { type PlaneModel, derivePlane } from './planeModel';
import { piecewiseCurve } from './sources';
import { type SpaceModel, deriveSpace } from './spaceModel';
import type { CurvatureState } from './state';

/** Everything the figures and the panel show, computed once per state. */
export interface CurvatureModel {
  state: CurvatureState;
  /** The plane curve, any source as Bézier pieces (parts plane and arc). */
  plane: PlaneModel | null;
  /** The space curve (part space), or the plane curve lying in z = 0. */
  space: SpaceModel;
  /** Arc length against parameter (part arc). */
  arc: ArcModel | null;
}

export function derive(state: CurvatureState): CurvatureModel {
  const plane =
    state.part === 'space'
      ? null
      : derivePlane(piecewiseCurve(state.src, state.p, state.d), state.t);
  return {
    state,
    plane,
    space: deriveSpace(state, plane),
    arc: state.part === 'arc' ? deriveArc(state.p, state.n, state.t) : null,
  };
}
