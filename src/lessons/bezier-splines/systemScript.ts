import { sub, texResidue } from '../../kit/format';
import { script, step } from '../../kit/script';
import { controlPointName, type Point, type SplineEquation } from '../../math';
import { texNumber, texPoint } from '../../render/formula';
import type { BezierSplinesModel } from './model';
import type { BezierSplinesState } from './state';

/** What the steps of the C² system reveal, by name. */
export type SystemReveal =
  | 'points'
  | 'unknowns'
  | 'interpolation'
  | 'c1Equations'
  | 'c2Equations'
  | 'naturalEnds'
  | 'matrix'
  | 'solution'
  | 'sameAsNatural';

type State = BezierSplinesState;
type Model = BezierSplinesModel;

const pt = (p: Point) => texPoint(p, 2);
const num = (v: number, digits = 2) => texNumber(v, digits);

/** The name of the spline's control point j (A … J for four points, else c_j) in captions. */
const name = (j: number, n: number) => {
  const text = controlPointName(j, 3 * n + 1);
  return text.startsWith('c_') ? `c${sub(j)}` : text;
};

/** The shape of the system: n pieces, 3n + 1 control points, the joints' names; four points are the practical's A … J. */
const shape = (s: State) => {
  const n = s.points.length - 1;
  const size = 3 * n + 1;
  const joints = Array.from({ length: n + 1 }, (_, i) => name(3 * i, n)).join(', ');
  return { n, size, joints, four: size === 10 };
};

/** Control point j in TeX: its letter, or c_j. */
const texName = (m: Model, j: number) => (m.names[j].length === 1 ? m.names[j] : `c_{${j}}`);
const aligned = (rows: string[]) => `\\begin{aligned}${rows.join('\\\\')}\\end{aligned}`;
/** The inner joints c₃, c₆, …, c₃ₙ₋₃, where C¹ and C² are asked. */
const innerJoints = (s: State) =>
  Array.from({ length: s.points.length - 2 }, (_, i) => 3 * (i + 1));

/** One row of the system as its equation: `C - 2D + E &= 0`, `D &= (1.00,\\ 2.50)`. */
const equationTex = (m: Model, e: SplineEquation) => {
  const terms = e.coefficients.flatMap((v, j) => (v === 0 ? [] : [{ v, name: texName(m, j) }]));
  const left = terms
    .map(({ v, name: x }, k) => {
      const times = Math.abs(v) === 1 ? '' : num(Math.abs(v), 0);
      const sign = v < 0 ? '-' : '+';
      return `${k === 0 ? (v < 0 ? '-' : '') : ` ${sign} `}${times}${x}`;
    })
    .join('');
  return `${left} &= ${e.kind === 'point' ? pt(e.right) : '0'}`;
};

/**
 * The whole system, joint by joint (its matrix, 3n + 1 rows, is the panel's
 * table): a row for each point, its C¹ equation and its C² one, P″ = 0 at the
 * two ends. Ten matrix rows crowded the figure in presenter view; four rows
 * of three columns leave it its room (#19).
 */
const jointsTex = (m: Model) => {
  const { equations } = m.system;
  const n = (equations.length - 1) / 3;
  const at = (kinds: SplineEquation['kind'][], i: number) => {
    const e = equations.find((q) => kinds.includes(q.kind) && q.at === i);
    // An empty pair of columns where the joint has no such equation.
    return e ? equationTex(m, e) : '&';
  };
  const rows = Array.from(
    { length: n + 1 },
    (_, i) => `${at(['point'], i)} & ${at(['C1'], i)} & ${at(['C2', 'natural'], i)}`,
  );
  return aligned(rows);
};

/** Part 3: the (3n+1) × (3n+1) system for a C² cubic spline, one kind of equation per press. */
export const system = script<State, Model, SystemReveal>(
  step('points', ({ state }) => `The points ${shape(state).joints} to interpolate`),
  step('unknowns', ({ state }) => {
    const { n, size, four } = shape(state);
    return four
      ? 'Three cubic pieces [A B C D], [D E F G], [G H I J]: 10 control points, 6 of them unknown'
      : `${n} cubic pieces: ${size} control points c${sub(0)} … c${sub(3 * n)}, unknowns all`;
  }),
  step(
    'interpolation',
    ({ state }) => {
      const { n, joints } = shape(state);
      return `Interpolation: ${joints} are the given points (${n + 1} equations; shared ends give C⁰)`;
    },
    ({ state, model }) =>
      aligned(state.points.map((q, i) => `${texName(model, 3 * i)} &= ${pt(q)}`)),
  ),
  step(
    'c1Equations',
    ({ state }) =>
      shape(state).four
        ? 'C¹ at D and G: C − 2D + E = 0 and F − 2G + H = 0 (2 equations)'
        : `C¹ at each inner joint: c₃ᵢ₋₁ − 2c₃ᵢ + c₃ᵢ₊₁ = 0 (${shape(state).n - 1} equations)`,
    ({ state, model }) => {
      const c = (j: number) => texName(model, j);
      return aligned(innerJoints(state).map((k) => `${c(k - 1)} - 2${c(k)} + ${c(k + 1)} &= 0`));
    },
  ),
  step(
    'c2Equations',
    ({ state }) =>
      shape(state).four
        ? 'C² at D and G: B − 2C + 2E − F = 0 and E − 2F + 2H − I = 0: the practical’s 8 equations'
        : `C² at each inner joint: c₃ᵢ₋₂ − 2c₃ᵢ₋₁ + 2c₃ᵢ₊₁ − c₃ᵢ₊₂ = 0 (${shape(state).n - 1} equations)`,
    ({ state, model }) => {
      const c = (j: number) => texName(model, j);
      return aligned(
        innerJoints(state).map(
          (k) => `${c(k - 2)} - 2${c(k - 1)} + 2${c(k + 1)} - ${c(k + 2)} &= 0`,
        ),
      );
    },
  ),
  step(
    'naturalEnds',
    ({ state }) => {
      const { size, four } = shape(state);
      return four
        ? 'Natural ends, P″ = 0: A − 2B + C = 0 and H − 2I + J = 0 — 10 equations, 10 unknowns'
        : `Natural ends, P″ = 0 at both: ${size} equations for ${size} unknowns`;
    },
    ({ state, model }) => {
      const c = (j: number) => texName(model, j);
      const n = state.points.length - 1;
      return aligned([
        `${c(0)} - 2${c(1)} + ${c(2)} &= 0`,
        `${c(3 * n - 2)} - 2${c(3 * n - 1)} + ${c(3 * n)} &= 0`,
      ]);
    },
  ),
  step(
    'matrix',
    ({ state }) => {
      const { size } = shape(state);
      return `The whole ${size} × ${size} system, joint by joint: the point, C¹, C² (P″ = 0 at the ends); x and y share the matrix`;
    },
    ({ model }) => jointsTex(model),
  ),
  step(
    'solution',
    'Solved: the control points, drawn, and the residual of every equation',
    ({ model }) => {
      // Three inner points to a line, so the numbers stay large in presenter view.
      const inner = model.system.controls.flatMap((q, j) =>
        j % 3 === 0 ? [] : [`${texName(model, j)} = ${pt(q)}`],
      );
      const lines = Array.from({ length: Math.ceil(inner.length / 3) }, (_, r) =>
        inner.slice(3 * r, 3 * r + 3).join(',\\quad '),
      );
      return aligned(
        [...lines, `\\max|A c - r| = ${texResidue(model.system.residual)}`].map((l) => `&${l}`),
      );
    },
  ),
  step(
    'sameAsNatural',
    'The same control points as the natural cubic spline of the road lesson',
    ({ model }) => `\\max_j |c_j - c_j^{\\text{natural}}| = ${texResidue(model.difference)}`,
  ),
);
