import { type ArcModel, deriveArc } from './arcModel';
import { type PlaneCurve, type PlaneModel, deriveCurve, derivePlane } from './planeModel';
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

/**
 * The last plane curve and what it was made from: moving t (the slider, Play,
 * the plot's cursor) keeps src, p and d, so the curve, its plot and comb are
 * not computed again; only the frame at t is.
 */
let last: {
  src: CurvatureState['src'];
  p: CurvatureState['p'];
  d: CurvatureState['d'];
  curve: PlaneCurve;
} | null = null;

function planeCurve(state: CurvatureState): PlaneCurve {
  if (last && last.src === state.src && last.p === state.p && last.d === state.d) return last.curve;
  const curve = deriveCurve(piecewiseCurve(state.src, state.p, state.d));
  last = { src: state.src, p: state.p, d: state.d, curve };
  return curve;
}

export function derive(state: CurvatureState): CurvatureModel {
  const plane = state.part === 'space' ? null : derivePlane(planeCurve(state), state.t);
  return {
    state,
    plane,
    space: deriveSpace(state, plane),
    arc: state.part === 'arc' ? deriveArc(state.p, state.n, state.t) : null,
  };
}
