import { together } from '../../kit/format';
import { script, step } from '../../kit/script';
import { cross, dot } from '../../math';
import { texNumber } from '../../render/formula';
import type { SurfaceModel } from './model';
import { num, point, pointAt } from './notation';
import { crossFormula } from './propertyScripts';
import type { SurfaceState } from './state';

// The nets worth seeing, each a scene of its own idea: it starts where that
// idea starts, and every press draws something new. Each script speaks of its
// own net (the scene of a net edited away from it is the patch's: scenes.ts).

type At = { state: SurfaceState; model: SurfaceModel };

/** A height in a formula: three decimals. */
const three = (value: number) => texNumber(value, 3);
/** Numbers of one formula, to four decimals, written together (kit/format). */
const four = (...values: number[]) => together(values, 4);
/** A height in a caption, as the step's formula writes it. */
const words = (value: number) => four(value)[0].replace('-', '−');

const pointFormula = ({ state, model }: At) => `${pointAt(state)} = ${point(model.point)}`;

export type FlatReveal = 'net' | 'plane' | 'isoCurves' | 'surface' | 'point' | 'normal';

/** A flat net, evenly spaced: the patch is the square itself, as evenly parametrised. */
export const flatScript = script<SurfaceState, SurfaceModel, FlatReveal>(
  step(
    'net',
    'A flat net: all 16 points in the plane z = 0, evenly spaced',
    () => '\\mathbf{P}_{m,n} = (m,\\ n,\\ 0)',
  ),
  step(
    'plane',
    'The weights are never negative and sum to 1: the patch stays in the square the net spans',
    () => 'f_m(u)\\,f_n(v) \\ge 0,\\quad \\sum_m\\sum_n f_m(u)\\,f_n(v) = 1',
  ),
  step(
    'isoCurves',
    'Evenly spaced points give evenly spaced iso-curves: u = 0, ⅛, ¼, … land at x = 0, ⅜, ¾, …',
    () => '\\sum_{m=0}^{3} m\\,f_m(u) = 3u,\\qquad \\sum_{n=0}^{3} n\\,f_n(v) = 3v',
  ),
  step(
    'surface',
    'The patch is the square itself: P(u, v) = (3u, 3v, 0)',
    () => '\\mathbf{P}(u,v) = (3u,\\ 3v,\\ 0)',
  ),
  step(
    'point',
    ({ state }) => `The point P(${num(state.u)}, ${num(state.v)}) sits at (3u, 3v, 0)`,
    pointFormula,
  ),
  step(
    'normal',
    'Its tangents are the same everywhere, so is its normal: straight up',
    crossFormula,
  ),
);

export type SaddleReveal = 'net' | 'corners' | 'isoU' | 'isoV' | 'isoCurves' | 'point';

/** The saddle: straight rows and columns, straight iso-curves, and yet a curved surface. */
export const saddleScript = script<SurfaceState, SurfaceModel, SaddleReveal>(
  step(
    'net',
    'A saddle net: heights (m − 3/2)(n − 3/2)/2, so every row and every column is straight',
    () => 'z_{m,n} = \\tfrac12\\,(m - \\tfrac32)(n - \\tfrac32)',
  ),
  step(
    'corners',
    'Two opposite corners up, two down: P₀,₀ and P₃,₃ at 9/8, P₃,₀ and P₀,₃ at −9/8',
    ({ state: { net } }) =>
      `z_{0,0} = z_{3,3} = ${three(net[0][0][2])},\\quad z_{3,0} = z_{0,3} = ${three(net[3][0][2])}`,
  ),
  step(
    'isoU',
    ({ state }) =>
      `Fix u = ${num(state.u)}: the columns give c₀ … c₃ on one line, so the iso-curve in v is straight`,
    ({ model }) => model.columnPoints.map((p, n) => `\\mathbf{c}_${n}=${point(p)}`).join(',\\ '),
  ),
  step(
    'isoV',
    ({ state }) => `Fix v = ${num(state.v)}: the rows give r₀ … r₃, again on one line`,
    ({ model }) => model.rowPoints.map((p, m) => `\\mathbf{r}_${m}=${point(p)}`).join(',\\ '),
  ),
  step(
    'isoCurves',
    'Every iso-curve is a straight line, and yet the surface bends: a hyperbolic paraboloid',
    () => '\\mathbf{P}(u,v) = \\bigl(3u,\\ 3v,\\ \\tfrac92\\,(u - \\tfrac12)(v - \\tfrac12)\\bigr)',
  ),
  step(
    'point',
    ({ state, model }) =>
      `At P(${num(state.u)}, ${num(state.v)}) the height is ${words(model.point[2])}: up one way, down the other`,
    ({ state, model }) =>
      `z = \\tfrac92\\,(${num(state.u)} - \\tfrac12)(${num(state.v)} - \\tfrac12) = ${four(model.point[2])[0]}`,
  ),
);

export type BumpReveal = 'net' | 'edges' | 'surface' | 'point' | 'shares' | 'tangentPlane';

/** f₁ + f₂ at u and at v: the share of the two inner rows and of the two inner columns. */
const innerShares = (model: SurfaceModel) => ({
  a: model.rowShares[1] + model.rowShares[2],
  b: model.columnShares[1] + model.columnShares[2],
});

/** The bump: four points lifted, the patch rising less than they do. */
export const bumpScript = script<SurfaceState, SurfaceModel, BumpReveal>(
  step(
    'net',
    'A bump: the twelve border points at height 0, the four inner points lifted to 2',
    () => 'z_{1,1} = z_{1,2} = z_{2,1} = z_{2,2} = 2,\\qquad \\text{every other } z_{m,n} = 0',
  ),
  step(
    'edges',
    'The border rows and columns lie on the ground, and so do the four edges of the patch',
    () => '\\mathbf{P}(u,0) = \\sum_{m=0}^{3} f_m(u)\\,\\mathbf{P}_{m,0},\\quad z = 0',
  ),
  step('surface', 'Inside, the patch rises towards the lifted points, but does not reach them'),
  step(
    'point',
    ({ state, model }) =>
      `At P(${num(state.u)}, ${num(state.v)}) it is ${words(model.point[2])} high, not 2`,
    ({ model }) => {
      const { a, b } = innerShares(model);
      const [sa, sb, z] = four(a, b, model.point[2]);
      return `z = 2\\,\\bigl(f_1(u) + f_2(u)\\bigr)\\bigl(f_1(v) + f_2(v)\\bigr) = 2 \\cdot ${sa} \\cdot ${sb} = ${z}`;
    },
  ),
  step(
    'shares',
    'Why: the four inner points share only part of the weight; the rest sits on the ground',
    ({ model }) => {
      const { a, b } = innerShares(model);
      const [sa, sb, product] = four(a, b, a * b);
      return `\\sum_{m,n\\in\\{1,2\\}} f_m(u)\\,f_n(v) = ${sa} \\cdot ${sb} = ${product} < 1`;
    },
  ),
  step(
    'tangentPlane',
    'The tangent plane and the normal there: level at the top, u = v = ½',
    crossFormula,
  ),
);

export type WaveReveal = 'net' | 'columnCurves' | 'rowCurves' | 'surface' | 'isoV' | 'point';

/** ½f₀(v) + f₁(v) + f₂(v) + ½f₃(v): how high the wave stands at v. */
const waveHeight = (model: SurfaceModel) => {
  const f = model.columnShares;
  return 0.5 * f[0] + f[1] + f[2] + 0.5 * f[3];
};

/** The wave: an S along u (with an inflection), an arch along v. */
export const waveScript = script<SurfaceState, SurfaceModel, WaveReveal>(
  step(
    'net',
    'A wave: along u each column goes up, then down; along v the heights are halved at the ends',
    () =>
      'z_{m,n} = h_m\\,s_n,\\quad h = (0,\\ 1.5,\\ -1.5,\\ 0),\\quad s = (\\tfrac12,\\ 1,\\ 1,\\ \\tfrac12)',
  ),
  step(
    'columnCurves',
    'Each column is the control polygon of a cubic in u: an S, up then down',
    () => '\\sum_{m=0}^{3} f_m(u)\\,\\mathbf{P}_{m,n},\\quad n = 0, \\dots, 3',
  ),
  step(
    'rowCurves',
    'Each row is the control polygon of a cubic in v: an arch, lower at its ends',
    () => '\\sum_{n=0}^{3} f_n(v)\\,\\mathbf{P}_{m,n},\\quad m = 0, \\dots, 3',
  ),
  step('surface', 'The patch: a wave along u, lower towards the edges v = 0 and v = 1'),
  step(
    'isoV',
    ({ state }) =>
      `The iso-curve v = ${num(state.v)} is an S: it turns the other way at u = ½, where it crosses z = 0`,
    ({ model }) =>
      `z = 1.5\\,\\bigl(f_1(u) - f_2(u)\\bigr)\\,g(v) = 4.5\\,u(1-u)(1-2u)\\,g(v),\\quad g(v) = \\tfrac12 f_0 + f_1 + f_2 + \\tfrac12 f_3 = ${texNumber(waveHeight(model), 4)}`,
  ),
  step(
    'point',
    ({ state }) => `The point P(${num(state.u)}, ${num(state.v)}) on the wave`,
    ({ state, model }) =>
      `${pointAt(state)} = ${point(model.point)},\\quad 4.5 \\cdot ${num(state.u)}(1-${num(state.u)})(1-2\\cdot${num(state.u)}) \\cdot ${texNumber(waveHeight(model), 4)} = ${texNumber(model.point[2], 4)}`,
  ),
);

export type TwistedReveal = 'cornerQuad' | 'net' | 'edges' | 'surface' | 'point' | 'normal';

/** (P₃,₀ − P₀,₀) × (P₀,₃ − P₀,₀) · (P₃,₃ − P₀,₀): zero exactly when the four corners are in one plane. */
export function cornerVolume(net: SurfaceState['net']): number {
  const o = net[0][0];
  const minus = (p: readonly number[]) => p.map((value, d) => value - o[d]);
  return dot(cross(minus(net[3][0]), minus(net[0][3])), minus(net[3][3]));
}

/** A net no plane holds: the patch still meets its four corners, and twists between them. */
export const twistedScript = script<SurfaceState, SurfaceModel, TwistedReveal>(
  step(
    'cornerQuad',
    'Not even the four corners are in one plane: joined, they make a twisted quadrilateral',
    ({ state }) =>
      `(\\mathbf{P}_{3,0}-\\mathbf{P}_{0,0})\\times(\\mathbf{P}_{0,3}-\\mathbf{P}_{0,0})\\cdot(\\mathbf{P}_{3,3}-\\mathbf{P}_{0,0}) = ${texNumber(cornerVolume(state.net), 3)} \\ne 0`,
  ),
  step('net', 'The net: its rows and columns bend, rise and fall; no plane holds it'),
  step(
    'edges',
    'The edges of the patch are the Bézier curves of the border rows and columns: curves in space',
    () => '\\mathbf{P}(u,0)=\\sum_{m=0}^{3} f_m(u)\\,\\mathbf{P}_{m,0}',
  ),
  step('surface', 'The patch passes through all four corners and twists between them'),
  step('point', ({ state }) => `The point P(${num(state.u)}, ${num(state.v)}) on it`, pointFormula),
  step(
    'normal',
    'The normal ∂P/∂u × ∂P/∂v turns from place to place: move u and v to see it',
    crossFormula,
  ),
);
