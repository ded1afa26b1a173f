import type { StepsSpec } from '../../app/lesson';
import { trimmed } from '../../kit/format';
import type { Continuity } from '../../math';
import { texNumber } from '../../render/formula';
import { type JoinReport, type SurfaceModel, joinReport } from './model';
import type { SurfaceMode, SurfaceState } from './state';

// The script of each scene: what step k shows, said in one sentence, and the
// step's formula with the current numbers for presenter view.

/** The last step of each scene's construction. */
export const STEP_COUNT: Record<SurfaceMode, number> = {
  patch: 5,
  rows: 5,
  casteljau: 6,
  matrix: 3,
  weights: 4,
  normal: 4,
  join: 3,
};

const num = (value: number) => trimmed(value, 2);
/** A point with up to three decimals, trailing zeros dropped: (0.9, 1.8, 0.895). */
const point = (p: readonly number[]) => `(${p.map((value) => trimmed(value, 3)).join(',\\ ')})`;
const list = (values: readonly number[], digits = 4) =>
  values.map((value) => texNumber(value, digits)).join(' & ');
const matrix = (rows: readonly (readonly number[])[], digits = 4) =>
  `\\begin{bmatrix}${rows.map((row) => list(row, digits)).join('\\\\')}\\end{bmatrix}`;

/** A continuity class as the lecture writes it. */
export const continuityName = (c: Continuity): string =>
  ({ none: 'gap', C0: 'C⁰', G1: 'G¹', C1: 'C¹', G2: 'G²', C2: 'C²' })[c];

/** In words, how the joined patches meet. */
export function joinVerdict(report: JoinReport): string {
  switch (report.weakest) {
    case 'none':
      return 'the edges no longer meet: not even C⁰, there is a gap';
    case 'C0':
      return 'the legs across the edge are not collinear: C⁰ only, a crease';
    case 'G1':
      return 'the legs are collinear but of unequal length: G¹, smooth but not C¹';
    default:
      return 'the legs are collinear and equally long: C¹, the surface is smooth across';
  }
}

function describe(state: SurfaceState, k: number): string {
  const u = num(state.u);
  const v = num(state.v);
  const c = state.c;
  switch (state.s) {
    case 'patch':
      return [
        'The 16 control points xₘ,ₙ of a bicubic patch: m runs along u, n along v',
        'The control net: every row and every column is the control polygon of a cubic',
        'The four corners of the net lie on the patch: x(0,0) = x₀,₀ and so on',
        'Each edge of the patch is the Bézier curve of the edge row or column of the net',
        'Fix u or v: the iso-curves, each a cubic Bézier curve in the other parameter',
        `The patch, and the point x(${u}, ${v}) on it`,
      ][k];
    case 'rows':
      return [
        `Choose v = ${v}; start from the control net`,
        'Each row m of the net is the control polygon of a curve in v',
        `At v = ${v} the four row curves give four points r₀ … r₃`,
        `r₀ … r₃ are the control points of a curve in u: the iso-curve v = ${v}`,
        `Choose u = ${u}: the point x(u, v) on that curve is the point on the surface`,
        `The iso-curve u = ${u} passes through the same point`,
      ][k];
    case 'casteljau':
      return [
        'The same point by de Casteljau, in either order; start from the net',
        `u first: de Casteljau at u = ${u} along each of the four columns`,
        `The columns give c₀ … c₃, the control points of the iso-curve u = ${u}`,
        `de Casteljau at v = ${v} on c₀ … c₃ gives x(u, v)`,
        `v first: de Casteljau at v = ${v} along each of the four rows`,
        `The rows give r₀ … r₃, the control points of the iso-curve v = ${v}`,
        `de Casteljau at u = ${u} on r₀ … r₃: the same point, to the last digit`,
      ][k];
    case 'matrix':
      return [
        `B: the ${c} coordinates of the 16 control points`,
        `U·M: the four Bernstein values fₘ(u) at u = ${u}`,
        `Mᵀ·Vᵀ: the four Bernstein values fₙ(v) at v = ${v}`,
        `${c}(u, v) = U·M·B·Mᵀ·Vᵀ: one number from four matrices`,
      ][k];
    case 'weights':
      return [
        'How much each control point pulls: start from the net',
        `fₘ(u) at u = ${u}: the share of each row of the net`,
        `fₙ(v) at v = ${v}: the share of each column`,
        'The 16 weights fₘ(u)·fₙ(v): none is negative and together they make 1',
        'x(u, v) is the weighted average of the net, so the patch stays inside its convex hull',
      ][k];
    case 'normal':
      return [
        `The patch and the point x(${u}, ${v})`,
        `The iso-curve v = ${v} and its tangent ∂x/∂u`,
        `The iso-curve u = ${u} and its tangent ∂x/∂v`,
        'Their cross product ∂x/∂u × ∂x/∂v is normal to the surface',
        'The tangent plane: spanned by ∂x/∂u and ∂x/∂v, perpendicular to the normal',
      ][k];
    case 'join':
      return [
        'Two patches side by side: the nets x and y',
        'They share an edge: y₀,ₙ = x₃,ₙ, the last row of x is the first row of y',
        'Both patches: drag a point near the edge and watch the join',
        `Across the edge, x₂,ₙ → x₃,ₙ = y₀,ₙ → y₁,ₙ: ${joinVerdict(joinReport(state.x, state.y))}`,
      ][k];
  }
}

function formula(model: SurfaceModel, state: SurfaceState): string | null {
  const k = state.k;
  const u = num(state.u);
  const v = num(state.v);
  const at = `\\mathbf{x}(${u},${v})`;
  const sum = '\\sum_{m=0}^{3}\\sum_{n=0}^{3} f_m(u)\\,f_n(v)\\,\\mathbf{x}_{m,n}';
  switch (state.s) {
    case 'patch': {
      const x = state.x;
      if (k === 2)
        return `\\begin{aligned}\\mathbf{x}(0,0)&=\\mathbf{x}_{0,0}=${point(x[0][0])}, & \\mathbf{x}(1,0)&=\\mathbf{x}_{3,0}=${point(x[3][0])},\\\\ \\mathbf{x}(0,1)&=\\mathbf{x}_{0,3}=${point(x[0][3])}, & \\mathbf{x}(1,1)&=\\mathbf{x}_{3,3}=${point(x[3][3])}\\end{aligned}`;
      if (k === 3) return '\\mathbf{x}(u,0)=\\sum_{m=0}^{3} f_m(u)\\,\\mathbf{x}_{m,0}';
      if (k === 5) return `${at} = ${point(model.point)}`;
      return `\\mathbf{x}(u,v)=${sum}`;
    }
    case 'rows':
      if (k === 1) return '\\mathbf{r}_m(v)=\\sum_{n=0}^{3} f_n(v)\\,\\mathbf{x}_{m,n}';
      if (k === 2)
        return model.rowPoints.map((p, m) => `\\mathbf{r}_${m}=${point(p)}`).join(',\\ ');
      if (k === 3) return '\\mathbf{x}(u,v)=\\sum_{m=0}^{3} f_m(u)\\,\\mathbf{r}_m(v)';
      if (k >= 4) return `${at}=\\sum_{m=0}^{3} f_m(${u})\\,\\mathbf{r}_m = ${point(model.point)}`;
      return null;
    case 'casteljau': {
      const a = model.uThenV;
      const b = model.vThenU;
      if (k === 2) return a.intermediate.map((p, n) => `\\mathbf{c}_${n}=${point(p)}`).join(',\\ ');
      if (k === 3) return `\\text{u, then v: } ${at} = ${point(a.point)}`;
      if (k === 5) return b.intermediate.map((p, m) => `\\mathbf{r}_${m}=${point(p)}`).join(',\\ ');
      if (k === 6) {
        const gap = Math.max(...a.point.map((value, d) => Math.abs(value - b.point[d])));
        return `\\text{u, then v: } ${point(a.point)},\\quad \\text{v, then u: } ${point(b.point)},\\quad \\text{largest difference } ${gap === 0 ? '0' : gap.toExponential(1)}`;
      }
      return null;
    }
    case 'matrix': {
      const m = model.matrix;
      const c = state.c;
      if (k === 0) return `B_${c} = ${matrix(m.B, 2)}`;
      if (k === 1)
        return `U M = \\begin{bmatrix}${list(m.U)}\\end{bmatrix}${matrix(m.M, 0)} = \\begin{bmatrix}${list(m.UM)}\\end{bmatrix}`;
      if (k === 2)
        return `M^{\\mathsf T} V^{\\mathsf T} = \\begin{bmatrix}${list(m.VM)}\\end{bmatrix}^{\\mathsf T}`;
      return `${c}(${u},${v}) = \\begin{bmatrix}${list(m.UM)}\\end{bmatrix}${matrix(m.B, 2)}\\begin{bmatrix}${m.VM.map((value) => texNumber(value, 4)).join('\\\\')}\\end{bmatrix} = ${texNumber(m.value, 4)}`;
    }
    case 'weights': {
      const fu = model.weights.map((row) => row.reduce((s, w) => s + w, 0));
      const fv = model.weights[0].map((_, n) => model.weights.reduce((s, row) => s + row[n], 0));
      if (k === 1) return `f_m(${u}) = ${fu.map((w) => texNumber(w, 4)).join(',\\ ')}`;
      if (k === 2) return `f_n(${v}) = ${fv.map((w) => texNumber(w, 4)).join(',\\ ')}`;
      if (k === 3)
        return `\\sum_m\\sum_n f_m(u)\\,f_n(v) = \\Big(\\sum_m f_m(u)\\Big)\\Big(\\sum_n f_n(v)\\Big) = 1`;
      if (k === 4) return `${at} = ${sum} = ${point(model.point)}`;
      return null;
    }
    case 'normal':
      if (k === 1) return `\\partial\\mathbf{x}/\\partial u = ${point(model.du)}`;
      if (k === 2) return `\\partial\\mathbf{x}/\\partial v = ${point(model.dv)}`;
      if (k >= 3)
        return `\\frac{\\partial\\mathbf{x}}{\\partial u}\\times\\frac{\\partial\\mathbf{x}}{\\partial v} = ${point(model.crossProduct)}${model.normal ? `,\\quad \\mathbf{n} = ${point(model.normal)}` : ''}`;
      return `${at} = ${point(model.point)}`;
    case 'join':
      if (k === 3)
        return '\\mathbf{x}_{3,n}-\\mathbf{x}_{2,n} = \\mathbf{y}_{1,n}-\\mathbf{y}_{0,n}\\ \\text{for every } n \\iff C^1';
      if (k >= 1) return '\\mathbf{y}_{0,n} = \\mathbf{x}_{3,n},\\ n = 0,\\dots,3 \\iff C^0';
      return null;
  }
}

export const steps: StepsSpec<SurfaceState, SurfaceModel> = {
  key: 'k',
  count: (state) => STEP_COUNT[state.s],
  describe,
  formula,
};
