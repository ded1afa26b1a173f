import {
  type ExerciseSpec,
  type Random,
  type Verdict,
  checkNumbers,
  checkPoint,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import {
  type Point,
  bernstein,
  bernsteinBasis,
  bezierDerivative,
  bezierPoint,
  binomial,
  cubicInflections,
  cubicSelfIntersection,
  distance,
  signedAngle,
} from '../../math';
import { SCRIPTS } from './scripts';
import { type ExperimentId, type PropertiesState, copy } from './state';

/** The experiment's figure as it opens at `step` (a step name of its script). */
function opened(
  defaults: PropertiesState,
  experiment: ExperimentId,
  changes: Partial<PropertiesState>,
  step: 'last' | ((s: PropertiesState) => number),
): PropertiesState {
  const s: PropertiesState = { ...defaults, experiment, before: [], repeated: 1, ...changes };
  const script = SCRIPTS[experiment];
  return { ...s, step: step === 'last' ? script.lastStep(s) : step(s) };
}

/**
 * Property 3, no local control: one point of a long polygon moves, and the
 * curve moves by W(N, i, t) times that, at most W(N, i, i/N) times.
 */
const localMove: ExerciseSpec<PropertiesState> = {
  id: 'local-move',
  title: 'How far does the curve move?',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const n = r.int(3, 6);
    const i = r.int(1, n - 1);
    const shift = r.int(1, 3);
    const up = r.pick([true, false]);
    const spacing = n <= 3 ? 2 : 1;
    // The ends on the ground, the inner points above: never on one line.
    const before: Point[] = Array.from({ length: n + 1 }, (_, k) => [
      spacing * k,
      k === 0 || k === n ? 0 : r.int(1, 3),
    ]);
    const after = before.map((q, k) => (k === i ? [q[0], q[1] + (up ? shift : -shift)] : q));
    const peak = i / n;
    const largest = bernstein(n, i, peak);
    const answer = [largest * shift];
    const tolerance = 0.01;
    const c = binomial(n, i);
    const mistakes = [
      {
        values: [shift],
        hint: `Step “After”: the curve moves by W(${n}, ${i}, t) times P${sub(i)}’s move, a share of it; only an end point drags its end of the curve the whole way.`,
      },
      {
        values: [largest],
        hint: `W(${n}, ${i}, ${i}/${n}) = ${words(largest)} is the share at the largest move: multiply it by the move, ${shift}.`,
      },
      {
        values: [bernstein(n, i, 0.5) * shift],
        hint: `W(${n}, ${i}, t) is largest at t = i/N = ${i}/${n}, not at t = ½.`,
      },
      {
        values: [(largest / c) * shift],
        hint: `W(${n}, ${i}, t) = C(${n}, ${i})·tⁱ·(1 − t)ᴺ⁻ⁱ: the binomial coefficient C(${n}, ${i}) = ${c} is missing.`,
      },
      {
        values: [bernstein(n + 1, i, i / (n + 1)) * shift],
        hint: `N is the degree, ${n}, one less than the ${n + 1} control points.`,
      },
    ];
    const hint = `P(t) moves by W(${n}, ${i}, t)·ΔP${sub(i)}; that weight is largest at t = ${i}/${n}, where it is C(${n}, ${i})·(${i}/${n})${sup(i)}·(${n - i}/${n})${sup(n - i)}.`;
    return {
      state: opened(defaults, 'local', { points: copy(before), before }, (s) =>
        SCRIPTS.local.stepOf(s, 'before'),
      ),
      prompt: `If P${sub(i)} of this curve of degree ${n} moves ${up ? 'up' : 'down'} by ${shift}, how far does the curve move at most (to 2 decimals)?`,
      task: {
        kind: 'number',
        fields: ['largest move'],
        tolerance,
        answer,
        check: (values) => checkNumbers(values, answer, tolerance, hint, mistakes),
      },
      working: opened(defaults, 'local', { points: after, before }, 'last'),
    };
  },
};

const SUPERSCRIPTS = '⁰¹²³⁴⁵⁶⁷⁸⁹';
/** 3 → "³": a power in plain text. */
const sup = (k: number) => [...String(k)].map((d) => SUPERSCRIPTS[Number(d)]).join('');

/** Three or four points round a loop (anticlockwise from the bottom), P₀ to be repeated at the end. */
function ring(r: Random, count: 3 | 4): Point[] {
  if (count === 3)
    return [
      [r.int(0, 2), 0],
      [r.int(4, 5), r.int(1, 3)],
      [r.int(0, 1), r.int(3, 4)],
    ];
  return [
    [r.int(1, 3), 0],
    [r.int(4, 6), r.int(1, 2)],
    [r.int(2, 4), r.int(3, 4)],
    [r.int(0, 1), r.int(1, 2)],
  ];
}

/** Property 4, a closed curve: P₀ listed again at the end; where is P(t)? */
const closedPoint: ExerciseSpec<PropertiesState> = {
  id: 'closed-point',
  title: 'A point of the closed curve',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = ring(r, r.pick([3, 4] as const));
    const t = r.pick([0.25, 0.5, 0.75]);
    const n = points.length;
    const closed = [...points, points[0]];
    const answer = bezierPoint(closed, t);
    const tolerance = 0.25;
    const weights = bernsteinBasis(n, t);
    const hint = `P₀ is listed twice, so it weighs W(${n}, 0, t) + W(${n}, ${n}, t) = ${words(weights[0] + weights[n])} at t = ${words(t)}; the others weigh ${weights
      .slice(1, n)
      .map((w) => words(w))
      .join(', ')}, and P(t) is their weighted sum.`;
    return {
      state: opened(defaults, 'closed', { points, t }, (s) => SCRIPTS.closed.stepOf(s, 'polygon')),
      prompt: `P₀ is listed again at the end, P${sub(n)} = P₀, to close the curve: where is P(${words(t)})? Tap your guess; within ${words(tolerance)} of the point counts.`,
      task: {
        kind: 'point',
        figure: 'experiment',
        answer,
        tolerance,
        check: (guess) => checkPoint(guess, answer, tolerance, hint),
      },
      working: opened(defaults, 'closed', { points, t }, 'last'),
    };
  },
};

/** How far P′(0) and P′(1) may differ: N times a tenth of a unit of P₁'s position. */
const C1_SLACK = 0.1;

/**
 * Property 4 again: the closed curve is smooth at P₀ only if it arrives as it
 * leaves. Move P₁ until P′(0) = N(P₁ − P₀) equals P′(1) = N(P₀ − Pₙ₋₁): C¹.
 */
const closedSmooth: ExerciseSpec<PropertiesState> = {
  id: 'closed-smooth',
  title: 'Close the curve without a corner',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    // P₀ at the bottom, the last point level with it on the left: P₁ belongs level on the right.
    const p0: Point = [r.int(2, 3), 0];
    const last: Point = [r.int(0, 1), 0];
    const mirror: Point = [2 * p0[0] - last[0], 0];
    const points: Point[] = [
      p0,
      [mirror[0] + r.int(0, 1), r.int(1, 2)],
      [r.int(2, 4), r.int(3, 4)],
      last,
    ];
    const n = points.length;
    const tolerance = n * C1_SLACK;
    const check = (s: PropertiesState): Verdict => {
      if (s.points.length !== n)
        return {
          correct: false,
          message: `Keep the ${n} control points P₀ … P${sub(n - 1)} (there are ${s.points.length} now).`,
        };
      const strayed = s.points.findIndex((q, i) => i !== 1 && distance(q, points[i]) > 1e-9);
      if (strayed >= 0)
        return {
          correct: false,
          message: `Move only P₁: P${sub(strayed)} belongs at ${pointWords(points[strayed])}.`,
        };
      const hodograph = bezierDerivative([...s.points, s.points[0]]);
      const leaving = hodograph[0];
      const arriving = hodograph[hodograph.length - 1];
      const tangents = `P′(0) = ${pointWords(leaving)} and P′(1) = ${pointWords(arriving)}`;
      if (distance(leaving, arriving) <= tolerance)
        return { correct: true, message: `Correct: ${tangents}, so the curve is C¹ at P₀.` };
      const corner = Math.abs((signedAngle(arriving, leaving) * 180) / Math.PI);
      const need = `C¹ at P₀ needs P₁ − P₀ = P₀ − P${sub(n - 1)}`;
      return {
        correct: false,
        message:
          corner < 1
            ? `Not yet: ${tangents} point the same way (smooth to the eye), but their lengths differ; ${need}.`
            : `Not yet: ${tangents} meet at a corner of ${corner.toFixed(1)}°; ${need}.`,
      };
    };
    const state = opened(defaults, 'closed', { points }, 'last');
    const solution = { ...state, points: points.map((q, i) => (i === 1 ? mirror : q)) };
    return {
      state,
      prompt: `Move only P₁ so that the closed curve is C¹ at P₀ = P${sub(n)}: it leaves P₀ with the very velocity it arrives with, P′(0) = P′(1), within ${words(tolerance)}.`,
      task: { kind: 'construct', check, solution },
      working: solution,
    };
  },
};

/** An inflection this close to an end of the curve is too small to see. */
const END_MARGIN = 0.05;
/** A solution still holds this far away in every direction: a finger's slip does not undo it. */
const SLIP = 0.3;

/** The inflections of the cubic far enough from its ends to be seen. */
const visibleInflections = (p: readonly Point[]) =>
  cubicInflections(p).filter((t) => t >= END_MARGIN && t <= 1 - END_MARGIN);

/** Where P_k can go, on the grid inside the polygon's box, for the cubic to inflect with a margin. */
function inflectingSpots(p: readonly Point[], k: number): Point[] {
  const xs = p.map((q) => q[0]);
  const ys = p.map((q) => q[1]);
  const around = [
    [0, 0],
    ...Array.from({ length: 8 }, (_, j) => [
      Math.cos((j * Math.PI) / 4),
      Math.sin((j * Math.PI) / 4),
    ]),
  ];
  const spots: Point[] = [];
  for (let x = Math.min(...xs); x <= Math.max(...xs); x++)
    for (let y = Math.min(...ys); y <= Math.max(...ys); y++) {
      // Not on or beside another control point: the polygon keeps four distinct corners.
      if (p.some((q, i) => i !== k && distance(q, [x, y]) < 1)) continue;
      const holds = around.every(
        ([dx, dy]) =>
          visibleInflections(p.map((q, i) => (i === k ? [x + SLIP * dx, y + SLIP * dy] : q)))
            .length > 0,
      );
      if (holds) spots.push([x, y]);
    }
  return spots;
}

/** An arch every seed can fall back on: P₂ has room to make it inflect. */
const FALLBACK_ARCH: Point[] = [
  [0, 0],
  [1, 3],
  [4, 3],
  [5, 0],
];

/**
 * A cubic that turns one way only (an arch: no inflection, no loop), the
 * inner point to move, and the grid spots where moving it makes the cubic
 * inflect.
 */
function oneWayArch(r: Random): { p: Point[]; k: number; spots: Point[] } {
  for (let tries = 0; tries < 20; tries++) {
    const p: Point[] = [
      [0, r.int(0, 1)],
      [r.int(0, 2), r.int(3, 4)],
      [r.int(3, 5), r.int(2, 4)],
      [r.int(5, 6), r.int(0, 1)],
    ];
    if (cubicInflections(p).length > 0 || cubicSelfIntersection(p) !== null) continue;
    const k = r.pick([1, 2]);
    const spots = inflectingSpots(p, k);
    if (spots.length > 0) return { p, k, spots };
  }
  return { p: FALLBACK_ARCH, k: 2, spots: inflectingSpots(FALLBACK_ARCH, 2) };
}

/** Property 8: move one inner point until the cubic turns both ways. */
const inflection: ExerciseSpec<PropertiesState> = {
  id: 'inflection',
  title: 'Make the cubic turn both ways',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const { p, k, spots } = oneWayArch(r);
    const spot = r.pick(spots);
    const name = `P${sub(k)}`;
    const check = (s: PropertiesState): Verdict => {
      const strayed = s.points.findIndex((q, i) => i !== k && distance(q, p[i]) > 1e-9);
      if (strayed >= 0)
        return {
          correct: false,
          message: `Move only ${name}: P${sub(strayed)} belongs at ${pointWords(p[strayed])}.`,
        };
      const seen = visibleInflections(s.points);
      if (seen.length > 0)
        return {
          correct: true,
          message: `Correct: the cubic turns both ways, with an inflection at t = ${seen.map((t) => t.toFixed(2)).join(' and ')}.`,
        };
      const loop = cubicSelfIntersection(s.points);
      if (loop)
        return {
          correct: false,
          message: `Not yet: that is a loop (the curve crosses itself at t = ${loop[0].toFixed(2)} and ${loop[1].toFixed(2)}), and along a loop a cubic turns one way only. Pull ${name} back out of it.`,
        };
      const all = cubicInflections(s.points);
      if (all.length > 0)
        return {
          correct: false,
          message: `Not yet: the only inflection is at t = ${all[0].toFixed(2)}, too near the end to see; move ${name} further the same way.`,
        };
      return {
        correct: false,
        message: `Not yet: no inflection, the cubic still turns one way only. Move ${name} so the polygon bends one way at P₁ and the other way at P₂.`,
      };
    };
    const state = opened(defaults, 'cubic', { points: p }, 'last');
    const solved = { ...state, points: p.map((q, i) => (i === k ? spot : q)) };
    return {
      state,
      prompt: `Move only ${name} until the cubic turns both ways, with an inflection where its curvature changes sign.`,
      task: { kind: 'construct', check, solution: solved },
      working: solved,
    };
  },
};

/** The Bézier properties lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<PropertiesState>[] = [
  localMove,
  closedPoint,
  closedSmooth,
  inflection,
];
