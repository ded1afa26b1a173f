import { script, step } from '../../kit/script';
import { texNumber } from '../../render/formula';
import type { SurfaceModel } from './model';
import { DOUBLE_SUM, joinVerdict, list, matrix, num, point, pointAt } from './notation';
import type { SurfaceState } from './state';

// What the patch is made of and what it has: its matrix form, its 16 weights,
// its tangents and normal, and two patches joined along an edge.

export type MatrixReveal = 'coordinates' | 'rowFactors' | 'columnFactors' | 'product';

/** One coordinate of P(u, v), x(u, v) = U·M·B·Mᵀ·Vᵀ (or y, z), one factor at a time. */
export const matrixScript = script<SurfaceState, SurfaceModel, MatrixReveal>(
  step(
    'coordinates',
    ({ state }) => `B: the ${state.coordinate} coordinates of the 16 control points`,
    ({ state, model }) => `B_${state.coordinate} = ${matrix(model.matrix.B, 2)}`,
  ),
  step(
    'rowFactors',
    ({ state }) => `U·M: the four Bernstein values fₘ(u) at u = ${num(state.u)}`,
    ({ model: { matrix: m } }) =>
      `U M = \\begin{bmatrix}${list(m.U)}\\end{bmatrix}${matrix(m.M, 0)} = \\begin{bmatrix}${list(m.UM)}\\end{bmatrix}`,
  ),
  step(
    'columnFactors',
    ({ state }) => `Mᵀ·Vᵀ: the four Bernstein values fₙ(v) at v = ${num(state.v)}`,
    ({ model: { matrix: m } }) =>
      `M^{\\mathsf T} V^{\\mathsf T} = \\begin{bmatrix}${list(m.VM)}\\end{bmatrix}^{\\mathsf T}`,
  ),
  step(
    'product',
    ({ state }) => `${state.coordinate}(u, v) = U·M·B·Mᵀ·Vᵀ: one number from four matrices`,
    ({ state, model: { matrix: m } }) =>
      `${state.coordinate}(${num(state.u)},${num(state.v)}) = \\begin{bmatrix}${list(m.UM)}\\end{bmatrix}${matrix(m.B, 2)}\\begin{bmatrix}${m.VM.map((value) => texNumber(value, 4)).join('\\\\')}\\end{bmatrix} = ${texNumber(m.value, 4)}`,
  ),
);

export type WeightsReveal = 'net' | 'rowShares' | 'columnShares' | 'products' | 'average';

const shares = (values: readonly number[]) => values.map((w) => texNumber(w, 4)).join(',\\ ');

/** How much each control point pulls: the row shares, the column shares, their products. */
export const weightsScript = script<SurfaceState, SurfaceModel, WeightsReveal>(
  step('net', 'How much each control point pulls: start from the net'),
  step(
    'rowShares',
    ({ state }) => `fₘ(u) at u = ${num(state.u)}: the share of each row of the net`,
    ({ state, model }) => `f_m(${num(state.u)}) = ${shares(model.rowShares)}`,
  ),
  step(
    'columnShares',
    ({ state }) => `fₙ(v) at v = ${num(state.v)}: the share of each column`,
    ({ state, model }) => `f_n(${num(state.v)}) = ${shares(model.columnShares)}`,
  ),
  step(
    'products',
    'The 16 weights fₘ(u)·fₙ(v): none is negative and together they make 1',
    () =>
      `\\sum_m\\sum_n f_m(u)\\,f_n(v) = \\Big(\\sum_m f_m(u)\\Big)\\Big(\\sum_n f_n(v)\\Big) = 1`,
  ),
  step(
    'average',
    'P(u, v) is the weighted average of the net, so the patch stays inside its convex hull',
    ({ state, model }) => `${pointAt(state)} = ${DOUBLE_SUM} = ${point(model.point)}`,
  ),
);

export type NormalReveal = 'point' | 'uTangent' | 'vTangent' | 'normal' | 'tangentPlane';

export const crossFormula = ({ model }: { model: SurfaceModel }) =>
  `\\frac{\\partial\\mathbf{P}}{\\partial u}\\times\\frac{\\partial\\mathbf{P}}{\\partial v} = ${point(model.crossProduct)}${model.normal ? `,\\quad \\mathbf{n} = ${point(model.normal)}` : ''}`;

/** The two tangents at P(u, v), their cross product, the tangent plane. */
export const normalScript = script<SurfaceState, SurfaceModel, NormalReveal>(
  step(
    'point',
    ({ state }) => `The patch and the point P(${num(state.u)}, ${num(state.v)})`,
    ({ state, model }) => `${pointAt(state)} = ${point(model.point)}`,
  ),
  step(
    'uTangent',
    ({ state }) => `The iso-curve v = ${num(state.v)} and its tangent ∂P/∂u`,
    ({ model }) => `\\partial\\mathbf{P}/\\partial u = ${point(model.du)}`,
  ),
  step(
    'vTangent',
    ({ state }) => `The iso-curve u = ${num(state.u)} and its tangent ∂P/∂v`,
    ({ model }) => `\\partial\\mathbf{P}/\\partial v = ${point(model.dv)}`,
  ),
  step('normal', 'Their cross product ∂P/∂u × ∂P/∂v is normal to the surface', crossFormula),
  step(
    'tangentPlane',
    'The tangent plane: spanned by ∂P/∂u and ∂P/∂v, perpendicular to the normal',
    crossFormula,
  ),
);

export type JoinReveal = 'nets' | 'edge' | 'patches' | 'legs';

const sharedEdge = () => '\\mathbf{Q}_{0,n} = \\mathbf{P}_{3,n},\\ n = 0,\\dots,3 \\iff C^0';

/** Two patches side by side: the shared edge (C⁰), then the legs across it (C¹). */
export const joinScript = script<SurfaceState, SurfaceModel, JoinReveal>(
  step('nets', 'Two patches side by side: the nets P and Q'),
  step(
    'edge',
    'They share an edge: Q₀,ₙ = P₃,ₙ, the last row of P is the first row of Q',
    sharedEdge,
  ),
  step('patches', 'Both patches: drag a point near the edge and watch the join', sharedEdge),
  step(
    'legs',
    ({ model }) =>
      `Across the edge, P₂,ₙ → P₃,ₙ = Q₀,ₙ → Q₁,ₙ: ${model.join ? joinVerdict(model.join) : 'the patches are not joined'}`,
    () =>
      '\\mathbf{P}_{3,n}-\\mathbf{P}_{2,n} = \\mathbf{Q}_{1,n}-\\mathbf{Q}_{0,n}\\ \\text{for every } n \\iff C^1',
  ),
);
