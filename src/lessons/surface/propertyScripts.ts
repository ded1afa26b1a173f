import { script, step } from '../../kit/script';
import { texNumber } from '../../render/formula';
import type { SurfaceModel } from './model';
import { DOUBLE_SUM, joinVerdict, list, matrix, num, point, pointAt } from './notation';
import type { SurfaceState } from './state';

// What the patch is made of and what it has: its matrix form, its 16 weights,
// its tangents and normal, and two patches joined along an edge.

export type MatrixReveal = 'coordinates' | 'rowFactors' | 'columnFactors' | 'product';

/** x(u, v) = U·M·B·Mᵀ·Vᵀ for one coordinate, one factor at a time. */
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
    'x(u, v) is the weighted average of the net, so the patch stays inside its convex hull',
    ({ state, model }) => `${pointAt(state)} = ${DOUBLE_SUM} = ${point(model.point)}`,
  ),
);

export type NormalReveal = 'point' | 'uTangent' | 'vTangent' | 'normal' | 'tangentPlane';

export const crossFormula = ({ model }: { model: SurfaceModel }) =>
  `\\frac{\\partial\\mathbf{x}}{\\partial u}\\times\\frac{\\partial\\mathbf{x}}{\\partial v} = ${point(model.crossProduct)}${model.normal ? `,\\quad \\mathbf{n} = ${point(model.normal)}` : ''}`;

/** The two tangents at x(u, v), their cross product, the tangent plane. */
export const normalScript = script<SurfaceState, SurfaceModel, NormalReveal>(
  step(
    'point',
    ({ state }) => `The patch and the point x(${num(state.u)}, ${num(state.v)})`,
    ({ state, model }) => `${pointAt(state)} = ${point(model.point)}`,
  ),
  step(
    'uTangent',
    ({ state }) => `The iso-curve v = ${num(state.v)} and its tangent ∂x/∂u`,
    ({ model }) => `\\partial\\mathbf{x}/\\partial u = ${point(model.du)}`,
  ),
  step(
    'vTangent',
    ({ state }) => `The iso-curve u = ${num(state.u)} and its tangent ∂x/∂v`,
    ({ model }) => `\\partial\\mathbf{x}/\\partial v = ${point(model.dv)}`,
  ),
  step('normal', 'Their cross product ∂x/∂u × ∂x/∂v is normal to the surface', crossFormula),
  step(
    'tangentPlane',
    'The tangent plane: spanned by ∂x/∂u and ∂x/∂v, perpendicular to the normal',
    crossFormula,
  ),
);

export type JoinReveal = 'nets' | 'edge' | 'patches' | 'legs';

const sharedEdge = () => '\\mathbf{y}_{0,n} = \\mathbf{x}_{3,n},\\ n = 0,\\dots,3 \\iff C^0';

/** Two patches side by side: the shared edge (C⁰), then the legs across it (C¹). */
export const joinScript = script<SurfaceState, SurfaceModel, JoinReveal>(
  step('nets', 'Two patches side by side: the nets x and y'),
  step(
    'edge',
    'They share an edge: y₀,ₙ = x₃,ₙ, the last row of x is the first row of y',
    sharedEdge,
  ),
  step('patches', 'Both patches: drag a point near the edge and watch the join', sharedEdge),
  step(
    'legs',
    ({ model }) =>
      `Across the edge, x₂,ₙ → x₃,ₙ = y₀,ₙ → y₁,ₙ: ${model.join ? joinVerdict(model.join) : 'the patches are not joined'}`,
    () =>
      '\\mathbf{x}_{3,n}-\\mathbf{x}_{2,n} = \\mathbf{y}_{1,n}-\\mathbf{y}_{0,n}\\ \\text{for every } n \\iff C^1',
  ),
);
