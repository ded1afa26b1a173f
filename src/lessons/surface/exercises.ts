import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  checkNumbers,
  pointTask,
  random,
} from '../../kit/exercise';
import { sub, words } from '../../kit/format';
import { type Point, bezierPoint, bezierSurfacePoint, bezierTangent, distance } from '../../math';
import { SCRIPTS } from './scripts';
import { type SurfaceState, heights } from './state';

// The lesson's exercises: a point of a flat patch, the height z(u, v) of a
// patch by its 16 weights, and a second patch moved until the two join C¹.

const cell = (m: number, n: number) => `${sub(m)},${sub(n)}`;
const pair = (u: number, v: number) => `(${words(u)}, ${words(v)})`;
const column = (net: readonly (readonly Point[])[], n: number) => net.map((row) => row[n]);

/**
 * Where is P(u, v) on a net that lies flat in the plane z = 0? A grid 3
 * apart with every point moved by −1, 0 or 1 in x and y (rows and columns
 * stay in order), so the answer is not the even grid's (9u, 9v).
 */
const patchPoint: ExerciseSpec<SurfaceState> = {
  id: 'patch-point',
  title: 'Where is a point of the patch?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const net = [0, 1, 2, 3].map((m) =>
      [0, 1, 2, 3].map((n): Point => [3 * m + r.int(-1, 1), 3 * n + r.int(-1, 1), 0]),
    );
    const u = r.pick([0.25, 0.5, 0.75]);
    const v = r.pick([0.25, 0.5, 0.75]);
    const [x, y] = bezierSurfacePoint(net, u, v);
    const answer: Point = [x, y];
    const tolerance = 0.3;
    const base: SurfaceState = { ...defaults, net, u, v, step: 0, mode: 'rows' };
    return {
      // The 16 points alone, the panel's point at the corner (0, 0): P(u, v) not yet drawn.
      state: { ...base, mode: 'patch', u: 0, v: 0 },
      prompt: `This net lies flat in the plane z = 0. Where is the point P${pair(u, v)} of its patch (its x and y, within ${tolerance})?`,
      task: pointTask(
        'patch',
        answer,
        tolerance,
        `Choose v, then u: at v = ${words(v)} each row m gives a point rₘ = Σₙ fₙ(${words(v)}) Pₘ,ₙ, and P${pair(u, v)} is the point at u = ${words(u)} of the curve with control points r₀ … r₃.`,
      ),
      working: base,
    };
  },
};

/** f0 … f3 without the binomial 3 of f1 and f2: the slip of writing t(1 − t)² for 3t(1 − t)². */
const withoutBinomial = (t: number) => [(1 - t) ** 3, t * (1 - t) ** 2, t * t * (1 - t), t ** 3];

/** Σm Σn fm(u) fn(v) z(m,n) with the given factors. */
const weighted = (
  z: readonly (readonly number[])[],
  fu: readonly number[],
  fv: readonly number[],
) => z.reduce((sum, row, m) => sum + row.reduce((s, value, n) => s + fu[m] * fv[n] * value, 0), 0);

/** z(u, v) of a net whose only raised points are its four inner ones. */
const patchHeight: ExerciseSpec<SurfaceState> = {
  id: 'patch-height',
  title: 'Compute a height z(u, v)',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const inner = [1, 2].map(() => [1, 2].map(() => r.int(1, 3)));
    const z = [0, 1, 2, 3].map((m) =>
      [0, 1, 2, 3].map((n) => (m % 3 === 0 || n % 3 === 0 ? 0 : inner[m - 1][n - 1])),
    );
    const net = heights(z);
    const u = r.pick([0.25, 0.4, 0.5, 0.6, 0.75]);
    const v = r.pick([0.25, 0.4, 0.5, 0.6, 0.75].filter((value) => value !== u));
    const at = (a: number, b: number) => bezierSurfacePoint(net, a, b)[2];
    const answer = at(u, v);
    const tolerance = 0.001;
    const raised = [1, 2]
      .flatMap((m) => [1, 2].map((n) => `P${cell(m, n)} at z = ${z[m][n]}`))
      .join(', ');
    const base: SurfaceState = { ...defaults, net, u, v, step: 0, mode: 'matrix', coordinate: 'z' };
    const slips = [
      {
        values: [at(v, u)],
        hint: `u and v are swapped: U·M gives fₘ(u), the share of row m (m runs along u), and Mᵀ·Vᵀ gives fₙ(v), the share of column n.`,
      },
      {
        values: [weighted(z, withoutBinomial(u), withoutBinomial(v))],
        hint: `The step U·M: f₁(u) = 3u(1 − u)² and f₂(u) = 3u²(1 − u), each with its binomial 3 (and the same for v).`,
      },
      {
        values: [at(1 - u, 1 - v)],
        hint: `The step U·M: f₀(u) = (1 − u)³ weighs row 0 and f₃(u) = u³ row 3; t and 1 − t are swapped.`,
      },
    ];
    return {
      // Step 0 shows B, the heights; the panel's product is at the corner (0, 0), not at (u, v).
      state: { ...base, u: 0, v: 0 },
      prompt: `This net is flat at z = 0 except for ${raised}. What is the height z${pair(u, v)} of its patch, to 3 decimals (within ${tolerance})?`,
      task: {
        kind: 'number',
        fields: [`z${pair(u, v)}`],
        tolerance,
        answer: [answer],
        check: (values) =>
          checkNumbers(
            values,
            [answer],
            tolerance,
            `Work the matrix form step by step: U·M gives f₀(u) … f₃(u), Mᵀ·Vᵀ gives f₀(v) … f₃(v), and z(u, v) = Σₘ Σₙ fₘ(u) fₙ(v) zₘ,ₙ, where only the four inner heights count.`,
            slips,
          ),
      },
      working: base,
    };
  },
};

/** How far each column's leg across the edge is from C¹, and the edge from C⁰. */
function joinGaps(state: SurfaceState): { n: number; edge: number; leg: number }[] {
  return [0, 1, 2, 3].map((n) => {
    const [left, right] = [column(state.net, n), column(state.secondNet, n)];
    return {
      n,
      edge: distance(bezierPoint(left, 1), bezierPoint(right, 0)),
      // A cubic's P′ at an end is 3 times its leg: Q₁ − Q₀ against P₃ − P₂.
      leg: distance(bezierTangent(left, 1), bezierTangent(right, 0)) / 3,
    };
  });
}

function joinVerdict(state: SurfaceState, tolerance: number): Verdict {
  const gaps = joinGaps(state);
  const torn = gaps.find((g) => g.edge > tolerance);
  if (torn)
    return {
      correct: false,
      message: `Not yet: the edge is torn at column n = ${torn.n}, where P${cell(3, torn.n)} and Q${cell(0, torn.n)} are ${words(torn.edge)} apart. Put P${cell(3, torn.n)} back on the shared edge.`,
    };
  const off = gaps.filter((g) => g.leg > tolerance);
  if (off.length === 0)
    return {
      correct: true,
      message: `Correct: every leg Q₁,ₙ − Q₀,ₙ equals P₃,ₙ − P₂,ₙ (within ${words(Math.max(...gaps.map((g) => g.leg)))}): the patches join C¹.`,
    };
  const worst = off.reduce((a, b) => (b.leg > a.leg ? b : a));
  return {
    correct: false,
    message: `Not yet: ${off.length === 1 ? 'one column is' : `${off.length} columns are`} off. At n = ${worst.n} the leg Q${cell(1, worst.n)} − Q${cell(0, worst.n)} differs from P${cell(3, worst.n)} − P${cell(2, worst.n)} by ${words(worst.leg)}: Q${cell(1, worst.n)} belongs at 2P${cell(3, worst.n)} − P${cell(2, worst.n)}.`,
  };
}

/** A height for the nets: 0 … 2 in halves. */
const height = (r: Random) => r.pick([0, 0.5, 1, 1.5, 2]);

/** Two patches that share an edge: move Q's row 1 until they join C¹. */
const smoothJoin: ExerciseSpec<SurfaceState> = {
  id: 'smooth-join',
  title: 'Join two patches C¹',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    // P over [0, 3]²: flat along its sides n = 0, 3 and its first row, random heights inside.
    const z = [0, 1, 2, 3].map((m) =>
      [0, 1, 2, 3].map((n) => (m === 0 || n % 3 === 0 ? 0 : height(r))),
    );
    const net = heights(z);
    // Q over [3, 6] × [0, 3]: row 0 is P's row 3, row 1 its C¹ continuation 2P₃,ₙ − P₂,ₙ.
    const smooth: Point[][] = [
      net[3].map((p) => [...p]),
      net[3].map((p, n) => p.map((value, d) => 2 * value - net[2][n][d])),
      [0, 1, 2, 3].map((n) => [5, n, n % 3 === 0 ? 0 : r.pick([-0.5, 0, 0.5])]),
      [0, 1, 2, 3].map((n) => [6, n, 0]),
    ];
    // One or two points of row 1 moved in x and y (never both by 0); their heights stay right.
    const moved = r.int(0, 1) === 0 ? [r.int(0, 3)] : [r.int(0, 1), r.int(2, 3)];
    const secondNet = smooth.map((row, m) =>
      row.map((p, n): Point => {
        if (m !== 1 || !moved.includes(n)) return [...p];
        const dx = r.pick([-0.5, 0, 0.5]);
        const dy = dx === 0 ? r.pick([-0.5, 0.5]) : r.pick([-0.5, 0, 0.5]);
        return [p[0] + dx, p[1] + dy, p[2]];
      }),
    );
    const tolerance = 0.1;
    const base: SurfaceState = { ...defaults, net, secondNet, mode: 'join', step: 0 };
    const solution = { ...base, secondNet: smooth };
    return {
      // Both patches and the verdict on their legs: the crease shows.
      state: { ...base, step: SCRIPTS.join.lastStep(base) },
      prompt: `Across the shared edge, each leg P₂,ₙ → P₃,ₙ = Q₀,ₙ → Q₁,ₙ must go on straight with equal length for a C¹ join. Move points of Q's row 1 (Q₁,₀ … Q₁,₃) until the patches join C¹ (each within ${tolerance}).`,
      task: { kind: 'construct', check: (state) => joinVerdict(state, tolerance), solution },
      working: solution,
    };
  },
};

/** The lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<SurfaceState>[] = [
  patchPoint,
  patchHeight,
  smoothJoin,
];
