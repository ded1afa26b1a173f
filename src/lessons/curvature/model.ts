import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import { type ArcCurve, type ArcModel, deriveArc, deriveArcCurve } from './arcModel';
import { type JoinsModel, deriveJoins } from './joinsModel';
import { type PlaneCurve, type PlaneModel, deriveCurve, derivePlane } from './planeModel';
import type { Reveal } from './scripts';
import { piecewiseCurve } from './sources';
import {
  type SpaceCurveFields,
  type SpaceCurveModel,
  type SpaceModel,
  deriveSpace,
  deriveSpaceCurve,
  liftedSpace,
} from './spaceModel';
import type { CurvatureState } from './state';

/** Everything the figures and the panel show, computed once per state. */
export interface CurvatureModel {
  state: CurvatureState;
  /** What the steps so far reveal (the part's own names: the tangent, the comb, the table, …). */
  shown: Revealed<Reveal>;
  /** The plane curve, any source as Bézier pieces (parts plane and arc). */
  plane: PlaneModel | null;
  /** The space curve (part space), or the plane curve lying in z = 0. */
  space: SpaceModel;
  /** Arc length against parameter (part arc). */
  arc: ArcModel | null;
  /** Both sides of the natural spline's joins, and the Catmull-Rom spline of the same points (part joins). */
  joins: JoinsModel | null;
  /** The Catmull-Rom spline's κ at the cursor (part joins; null where P′ = 0). */
  catmullKappa: number | null;
}

type Fields<K extends keyof CurvatureState> = Pick<CurvatureState, K>;

// Each piece is kept while the fields it reads are the same: moving t (the
// slider, Play, the plot's cursor) keeps the curve, its plot and comb, and
// computes only the frame at t; a step of the clicker computes nothing.
const planeCurve = memoOn<
  Fields<'source' | 'points' | 'gradients'>,
  'source' | 'points' | 'gradients',
  PlaneCurve
>(['source', 'points', 'gradients'], ({ source, points, gradients }) =>
  deriveCurve(piecewiseCurve(source, points, gradients)),
);
const planeAt = memoOn<
  Fields<'source' | 'points' | 'gradients' | 't'>,
  'source' | 'points' | 'gradients' | 't',
  PlaneModel
>(['source', 'points', 'gradients', 't'], (s) => derivePlane(planeCurve(s), s.t));
const lifted = memoOn<{ plane: PlaneModel }, 'plane', SpaceModel>(['plane'], ({ plane }) =>
  liftedSpace(plane),
);
const spaceCurve = memoOn<SpaceCurveFields, keyof SpaceCurveFields, SpaceCurveModel>(
  ['spaceCurve', 'radius', 'rise', 'spacePoints'],
  deriveSpaceCurve,
);
const spaceAt = memoOn<SpaceCurveFields & Fields<'t'>, keyof SpaceCurveFields | 't', SpaceModel>(
  ['spaceCurve', 'radius', 'rise', 'spacePoints', 't'],
  (s) => deriveSpace(spaceCurve(s), s, s.t),
);
const arcCurve = memoOn<Fields<'points' | 'equalSteps'>, 'points' | 'equalSteps', ArcCurve>(
  ['points', 'equalSteps'],
  ({ points, equalSteps }) => deriveArcCurve(points, equalSteps),
);
const arcAt = memoOn<
  Fields<'points' | 'equalSteps' | 't'>,
  'points' | 'equalSteps' | 't',
  ArcModel
>(['points', 'equalSteps', 't'], (s) => deriveArc(arcCurve(s), s.points, s.t));

const joinsOf = memoOn<
  { points: CurvatureState['points']; pieces: PlaneModel['pieces'] },
  'points' | 'pieces',
  JoinsModel
>(['points', 'pieces'], ({ points, pieces }) => deriveJoins(points, pieces.segments));

/** The Catmull-Rom spline's κ at t: its curve kept, only the point at t computed. */
const catmullAt = memoOn<{ joins: JoinsModel; t: number }, 'joins' | 't', number | null>(
  ['joins', 't'],
  ({ joins, t }) => derivePlane(joins.catmull, t).at.curvature,
);

export function derive(state: CurvatureState, shown: Revealed<Reveal>): CurvatureModel {
  const plane = state.part === 'space' ? null : planeAt(state);
  const joins =
    state.part === 'joins' && plane
      ? joinsOf({ points: state.points, pieces: plane.pieces })
      : null;
  return {
    state,
    shown,
    plane,
    space: plane ? lifted({ plane }) : spaceAt(state),
    arc: state.part === 'arc' ? arcAt(state) : null,
    joins,
    catmullKappa: joins ? catmullAt({ joins, t: state.t }) : null,
  };
}
