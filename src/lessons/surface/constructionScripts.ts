import { texResidue } from '../../kit/format';
import { script, step } from '../../kit/script';
import type { SurfaceModel } from './model';
import { DOUBLE_SUM, num, point, pointAt } from './notation';
import type { SurfaceState } from './state';

// The patch built up from its net, then its point P(u, v) built two ways:
// from the row curves, and by de Casteljau in either order.

export type PatchReveal = 'points' | 'net' | 'corners' | 'edges' | 'isoCurves' | 'patch';

const doubleSum = () => `\\mathbf{P}(u,v)=${DOUBLE_SUM}`;

/** The patch from its 16 control points: the net, its corners and edges, the patch. */
export const patchScript = script<SurfaceState, SurfaceModel, PatchReveal>(
  step(
    'points',
    'The 16 control points Pₘ,ₙ of a bicubic patch: m runs along u, n along v',
    doubleSum,
  ),
  step(
    'net',
    'The control net: every row and every column is the control polygon of a cubic',
    doubleSum,
  ),
  step(
    'corners',
    'The four corners of the net lie on the patch: P(0,0) = P₀,₀ and so on',
    ({ state: { net } }) =>
      `\\begin{aligned}\\mathbf{P}(0,0)&=\\mathbf{P}_{0,0}=${point(net[0][0])}, & \\mathbf{P}(1,0)&=\\mathbf{P}_{3,0}=${point(net[3][0])},\\\\ \\mathbf{P}(0,1)&=\\mathbf{P}_{0,3}=${point(net[0][3])}, & \\mathbf{P}(1,1)&=\\mathbf{P}_{3,3}=${point(net[3][3])}\\end{aligned}`,
  ),
  step(
    'edges',
    'Each edge of the patch is the Bézier curve of the edge row or column of the net',
    () => '\\mathbf{P}(u,0)=\\sum_{m=0}^{3} f_m(u)\\,\\mathbf{P}_{m,0}',
  ),
  step(
    'isoCurves',
    'Fix u or v: the iso-curves, each a cubic Bézier curve in the other parameter',
    doubleSum,
  ),
  step(
    'patch',
    ({ state }) => `The patch, and the point P(${num(state.u)}, ${num(state.v)}) on it`,
    ({ state, model }) => `${pointAt(state)} = ${point(model.point)}`,
  ),
);

export type RowsReveal = 'net' | 'rowCurves' | 'rowPoints' | 'isoV' | 'point' | 'isoU';

const onRowCurve = ({ state, model }: { state: SurfaceState; model: SurfaceModel }) =>
  `${pointAt(state)}=\\sum_{m=0}^{3} f_m(${num(state.u)})\\,\\mathbf{r}_m = ${point(model.point)}`;

/** Choose v, then u: the row curves give the iso-curve v = const, and on it the point. */
export const rowsScript = script<SurfaceState, SurfaceModel, RowsReveal>(
  step('net', ({ state }) => `Choose v = ${num(state.v)}; start from the control net`),
  step(
    'rowCurves',
    'Each row m of the net is the control polygon of a curve in v',
    () => '\\mathbf{r}_m(v)=\\sum_{n=0}^{3} f_n(v)\\,\\mathbf{P}_{m,n}',
  ),
  step(
    'rowPoints',
    ({ state }) => `At v = ${num(state.v)} the four row curves give four points r₀ … r₃`,
    ({ model }) => model.rowPoints.map((p, m) => `\\mathbf{r}_${m}=${point(p)}`).join(',\\ '),
  ),
  step(
    'isoV',
    ({ state }) =>
      `r₀ … r₃ are the control points of a curve in u, 0 ≤ u ≤ 1: the iso-curve v = ${num(state.v)}`,
    () => '\\mathbf{P}(u,v)=\\sum_{m=0}^{3} f_m(u)\\,\\mathbf{r}_m(v)',
  ),
  step(
    'point',
    ({ state }) =>
      `Choose u = ${num(state.u)}: the point P(u, v) on that curve is the point on the surface`,
    onRowCurve,
  ),
  step(
    'isoU',
    ({ state }) => `The iso-curve u = ${num(state.u)} passes through the same point`,
    onRowCurve,
  ),
);

export type CasteljauReveal =
  'net' | 'columns' | 'columnPoints' | 'uThenV' | 'rows' | 'rowPoints' | 'vThenU';

/** The same point by de Casteljau: u first (columns), then v first (rows). */
export const casteljauScript = script<SurfaceState, SurfaceModel, CasteljauReveal>(
  step('net', 'The same point by de Casteljau, in either order; start from the net'),
  step(
    'columns',
    ({ state }) => `u first: de Casteljau at u = ${num(state.u)} along each of the four columns`,
  ),
  step(
    'columnPoints',
    ({ state }) =>
      `The columns give c₀ … c₃, the control points of the iso-curve u = ${num(state.u)}`,
    ({ model }) =>
      model.uThenV.intermediate.map((p, n) => `\\mathbf{c}_${n}=${point(p)}`).join(',\\ '),
  ),
  step(
    'uThenV',
    ({ state }) => `de Casteljau at v = ${num(state.v)} on c₀ … c₃ gives P(u, v)`,
    ({ state, model }) => `\\text{u, then v: } ${pointAt(state)} = ${point(model.uThenV.point)}`,
  ),
  step(
    'rows',
    ({ state }) => `v first: de Casteljau at v = ${num(state.v)} along each of the four rows`,
  ),
  step(
    'rowPoints',
    ({ state }) => `The rows give r₀ … r₃, the control points of the iso-curve v = ${num(state.v)}`,
    ({ model }) =>
      model.vThenU.intermediate.map((p, m) => `\\mathbf{r}_${m}=${point(p)}`).join(',\\ '),
  ),
  step(
    'vThenU',
    ({ state }) =>
      `de Casteljau at u = ${num(state.u)} on r₀ … r₃: the same point, to the last digit`,
    ({ model: { uThenV, vThenU } }) => {
      const a = uThenV.point;
      const b = vThenU.point;
      const gap = Math.max(...a.map((value, d) => Math.abs(value - b[d])));
      return `\\text{u, then v: } ${point(a)},\\quad \\text{v, then u: } ${point(b)},\\quad \\text{largest difference } ${texResidue(gap)}`;
    },
  ),
);
