/**
 * The raster lesson's exercises: where a curve strays furthest from the one
 * segment drawn for it, the next pixel a line rasteriser lights, the flatness
 * that adaptive flattening tests, and a curve shaped to flatten into exactly
 * two segments.
 */
import {
  type ExerciseSpec,
  type Mistake,
  type Random,
  type Verdict,
  checkNumbers,
  checkPoint,
  random,
} from '../../kit/exercise';
import { pointWords, sub, words } from '../../kit/format';
import { type Point, bezierPoint, distance, flatteningTree } from '../../math';
import { flatteningOf } from './geometry';
import { lineSteps } from './raster';
import type { RasterState, View } from './state';

/** "P₀ (3, 4), P₁ (14, 20) and P₂ (28, 6)": the control points as the prompt lists them. */
function listed(points: readonly Point[]): string {
  const names = points.map((p, i) => `P${sub(i)} ${pointWords(p)}`);
  return `${names.slice(0, -1).join(', ')} and ${names[names.length - 1]}`;
}

/** A scene of the lesson at step 0 with these control points, at zoom 1 (1 unit = 1 pixel). */
const sceneState = (
  defaults: RasterState,
  view: View,
  points: Point[],
  change: Partial<RasterState> = {},
): RasterState => ({
  ...defaults,
  view,
  points,
  zoom: 1,
  steppedSegment: 0,
  step: 0,
  ...change,
});

/** Within half a pixel a guessed point is right (1.6% of the 32-pixel raster). */
export const GAP_TOLERANCE = 0.5;

/**
 * A quadratic across the raster: a chord P₀P₂ 18 to 28 px long that rises or
 * falls at most 4 px, and P₁ 8 to 12 px above (or below) its middle fifth. So
 * P₁ projects onto the chord's middle half, the curve stays over the chord,
 * and its furthest point from the segment is at t = ½.
 */
function bulgingQuadratic(r: Random): Point[] {
  const up = r.next() < 0.5;
  // Room for P₂ (y0 ± 4) and P₁ (12 px off) on the 24 rows: 0 ≤ y ≤ 23.
  const y0 = up ? r.int(5, 9) : r.int(14, 18);
  const p0: Point = [r.int(2, 6), y0];
  const p2: Point = [r.int(24, 30), y0 + r.int(-2, 2) * 2];
  const along = r.pick([0.4, 0.5, 0.6]);
  const p1: Point = [
    Math.round(p0[0] + along * (p2[0] - p0[0])),
    Math.round(p0[1] + along * (p2[1] - p0[1])) + (up ? 1 : -1) * r.int(8, 12),
  ];
  return [p0, p1, p2];
}

const farthestPoint: ExerciseSpec<RasterState> = {
  id: 'farthest-point',
  title: 'Where does the curve stray furthest from its segment?',
  kind: 'point',
  pose(seed, defaults) {
    const r = random(seed);
    const points = bulgingQuadratic(r);
    // Step 0 shows the control points and their polygon; n stays at the lesson's 6 so
    // the panel's table says nothing of the one-segment polyline asked about.
    const state = sceneState(defaults, 'plot', points, { uniformSegments: 6 });
    const answer = bezierPoint(points, 0.5);
    const [p0, p1, p2] = points;
    const middle: Point = [(p0[0] + p2[0]) / 2, (p0[1] + p2[1]) / 2];
    const slips: [Point, string][] = [
      [
        p1,
        'P₁ is off the curve: a quadratic only goes halfway from the chord’s middle towards P₁.',
      ],
      [middle, 'That point is on the segment itself: the curve at t = ½ is (P₀ + 2P₁ + P₂)/4.'],
    ];
    const hint = (guess: Point) =>
      slips.find(([at]) => distance(guess, at) <= GAP_TOLERANCE)?.[1] ??
      'The curve’s distance from the line P₀P₂ is largest where t(1 − t) is: work out P(t) there.';
    return {
      state,
      prompt: `The quadratic Bézier curve with control points ${listed(points)} is drawn as one segment, from P₀ to P₂. Where is the curve furthest from that segment (within ${GAP_TOLERANCE} px)?`,
      task: {
        kind: 'point',
        figure: 'curve',
        answer,
        tolerance: GAP_TOLERANCE,
        check: (guess) => checkPoint(guess, answer, GAP_TOLERANCE, hint(guess)),
      },
      // One segment: the two computed points P(0), P(1), the segment, the curve, its largest gap.
      working: { ...state, uniformSegments: 1 },
    };
  },
};

/** Pixels are whole numbers: the answer is exact. */
export const PIXEL_TOLERANCE = 0;

/**
 * A segment between pixel centres that lights 7 to 12 pixels (one press each
 * in the pixel scene), along x (left to right) or along y (bottom to top), and
 * a step k whose next pixel is a real decision: the ideal line crosses more
 * than half way to the next row (or column), so rounding and cutting off
 * differ, and never at a tie. Drawn again if no step decides.
 */
function pixelSegment(r: Random) {
  for (;;) {
    const run = r.int(6, 11);
    const rise = r.int(1, run - 1) * r.pick([1, -1]);
    const steep = r.next() < 0.5;
    // The raster's last pixel along the run and across it.
    const [alongEnd, acrossEnd] = steep ? [23, 31] : [31, 23];
    const start = r.int(1, alongEnd - run);
    const side = r.int(1 + Math.max(0, -rise), acrossEnd - Math.max(0, rise));
    const first: Point = steep ? [side, start] : [start, side];
    const last: Point = steep ? [side + rise, start + run] : [start + run, side + rise];
    const decisions = Array.from({ length: run - 1 }, (_, k) => k).filter(
      (k) => ((k + 1) * Math.abs(rise)) % run > run / 2,
    );
    if (decisions.length) return { first, last, k: r.pick(decisions) };
  }
}

const nextPixel: ExerciseSpec<RasterState> = {
  id: 'next-pixel',
  title: 'Which pixel comes next?',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const { first, last, k } = pixelSegment(r);
    // A curve of degree 1, from pixel centre to pixel centre (pixel (i, j) is the unit square at (i, j)).
    const points: Point[] = [first, last].map(([i, j]) => [i + 0.5, j + 0.5]);
    // The plot scene: the segment without pixels (the pixel scene's table would list them all).
    const state = sceneState(defaults, 'plot', points);
    const { pixels, major } = lineSteps(points[0], points[1], 1);
    const [now, next] = [pixels[k], pixels[k + 1]];
    const answer = [...next];
    const along = major === 'x' ? 0 : 1;
    const across = 1 - along;
    const run = last[along] - first[along];
    const rise = last[across] - first[across];
    // The ideal line at the next step, and the wrong ways to make it a pixel.
    const ideal = first[across] + ((k + 1) * rise) / run;
    const pixelAt = (a: number, b: number) => (along === 0 ? [a, b] : [b, a]);
    const mistakes: Mistake[] = [
      {
        values: pixelAt(next[along], first[across] + Math.trunc(((k + 1) * rise) / run)),
        hint: `The ideal line crosses at ${major === 'x' ? 'y' : 'x'} = ${words(ideal)}: take the nearest ${major === 'x' ? 'row' : 'column'}, not the one it has passed.`,
      },
      {
        values: pixelAt(next[along], now[across]),
        hint: `Work out where the ideal line crosses ${major} = ${next[along]}, then take the nearest pixel across: it moves on here.`,
      },
      {
        values: pixelAt(now[along], now[across] + Math.sign(rise)),
        hint: `Step along the longer axis, ${major}: it changes by ${Math.abs(run)} pixels, the other by only ${Math.abs(rise)}.`,
      },
    ].filter((m) => m.values.some((v, d) => v !== answer[d]));
    return {
      state,
      prompt: `A line rasteriser draws the segment from pixel ${pointWords(first)} to pixel ${pointWords(last)}, one pixel per step. Which pixel does it light after ${pointWords(now)} (exact whole numbers)?`,
      task: {
        kind: 'number',
        fields: ['x', 'y'],
        tolerance: PIXEL_TOLERANCE,
        answer,
        check: (values) =>
          checkNumbers(
            values,
            answer,
            PIXEL_TOLERANCE,
            `Step ${major} by one, find where the ideal line through the end pixels crosses there, and round to the nearest pixel.`,
            mistakes,
          ),
      },
      // The raster, the end pixels, then one pixel per press with its ideal crossing and rounding.
      working: { ...state, view: 'pixels' },
    };
  },
};

/** The flatness is asked to two decimals. */
export const FLATNESS_TOLERANCE = 0.01;

/**
 * A cubic from its differences: P₁ − P₀ = v, Δ²P₀ = a, Δ²P₁ = b, so P₂ = 2v + a
 * and P₃ = 3v + 2a + b from P₀, moved to the middle of the raster. Neither is
 * zero, |a| and |b| differ by at least 1 and the larger is 3 or more, so the
 * flatness is 2.25 px or more (and at most 0.75·√50 ≈ 5.3 px).
 */
function cubicFromDifferences(r: Random): { points: Point[]; a: Point; b: Point } {
  for (;;) {
    const v: Point = [r.int(3, 5), r.int(-2, 2)];
    const a: Point = [r.int(-5, 5), r.int(-5, 5)];
    const b: Point = [r.int(-5, 5), r.int(-5, 5)];
    const [la, lb] = [Math.hypot(a[0], a[1]), Math.hypot(b[0], b[1])];
    if (Math.abs(la - lb) < 1 || Math.max(la, lb) < 3 || Math.min(la, lb) < 1) continue;
    const from0: Point[] = [
      [0, 0],
      v,
      [2 * v[0] + a[0], 2 * v[1] + a[1]],
      [3 * v[0] + 2 * a[0] + b[0], 3 * v[1] + 2 * a[1] + b[1]],
    ];
    const shift = [16, 12].map((centre, d) => {
      const values = from0.map((p) => p[d]);
      return centre - Math.round((Math.min(...values) + Math.max(...values)) / 2);
    });
    return { points: from0.map((p) => [p[0] + shift[0], p[1] + shift[1]]), a, b };
  }
}

/**
 * τ of the flatness exercise's working: below every flatness it poses (2.25 px
 * and up), above a quarter of each (5.3/4): the whole curve is split once, and
 * the first press of the subdivision visits it, its flatness in the formula.
 */
const FLATNESS_WORKING_TAU = 2;

const flatness: ExerciseSpec<RasterState> = {
  id: 'flatness',
  title: 'How far can the curve be from its chord?',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const { points, a, b } = cubicFromDifferences(r);
    const [la, lb] = [Math.hypot(a[0], a[1]), Math.hypot(b[0], b[1])];
    const state = sceneState(defaults, 'subdivide', points, { tolerance: FLATNESS_WORKING_TAU });
    const answer = [flatteningOf(state).tree[0].flatness * state.zoom];
    const mistakes: Mistake[] = [
      {
        values: [Math.max(la, lb)],
        hint: 'That is max‖Δ²P‖ alone: multiply by n(n − 1)/8 = 3·2/8 for a cubic.',
      },
      {
        values: [(12 / 8) * Math.max(la, lb)],
        hint: 'n is the degree, 3 for four control points: n(n − 1)/8 = 6/8.',
      },
      {
        values: [(6 / 8) * Math.min(la, lb)],
        hint: 'Take the larger of the two second differences, ‖P₂ − 2P₁ + P₀‖ and ‖P₃ − 2P₂ + P₁‖.',
      },
      {
        values: [(6 / 8) * (la + lb)],
        hint: 'The bound takes the largest second difference, not their sum.',
      },
    ];
    return {
      state,
      prompt: `Adaptive flattening tests the cubic with control points ${listed(points)} against τ. What is its flatness n(n − 1)/8 · max‖Pᵢ₊₂ − 2Pᵢ₊₁ + Pᵢ‖ in pixels, to 2 decimals?`,
      task: {
        kind: 'number',
        fields: ['flatness (px)'],
        tolerance: FLATNESS_TOLERANCE,
        answer,
        check: (values) =>
          checkNumbers(
            values,
            answer,
            FLATNESS_TOLERANCE,
            'Work out both second differences P₂ − 2P₁ + P₀ and P₃ − 2P₂ + P₁, take the longer, and multiply by 3·2/8.',
            mistakes,
          ),
      },
      // The test, then the first piece visited, the whole curve, with its flatness against τ.
      working: state,
    };
  },
};

/** The tolerance τ of the construction, in pixels. */
export const SPLIT_TOLERANCE = 0.5;

/**
 * Directions from the chord's middle to P₁, 3 to 3.2 px long and steep (the
 * chord is nearly level): P₁ off the line P₀P₂, over its middle.
 */
const DIRECTIONS: Point[] = [
  [0, 3],
  [0, -3],
  [1, 3],
  [-1, 3],
  [1, -3],
  [-1, -3],
];

/** The segments adaptive flattening makes at τ, and the flatness of the whole curve and of its halves. */
function flattened(points: readonly Point[]) {
  const tree = flatteningTree(points, SPLIT_TOLERANCE);
  return {
    segments: tree.filter((node) => !node.split).length,
    whole: tree[0].flatness,
    half: tree.length > 1 ? tree[1].flatness : null,
  };
}

const twoSegments: ExerciseSpec<RasterState> = {
  id: 'two-segments',
  title: 'Exactly two segments',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    // P₀ + P₂ even, so the chord's middle M is a whole pixel.
    const middle: Point = [r.int(10, 22), r.int(10, 14)];
    const half: Point = [r.int(6, 9), r.int(-3, 3)];
    const p0: Point = [middle[0] - half[0], middle[1] - half[1]];
    const p2: Point = [middle[0] + half[0], middle[1] + half[1]];
    const d = r.pick(DIRECTIONS);
    const far = r.int(2, 3);
    const at = (k: number): Point => [middle[0] + k * d[0], middle[1] + k * d[1]];
    const shaped = (p1: Point) =>
      sceneState(defaults, 'subdivide', [p0, p1, p2], { tolerance: SPLIT_TOLERANCE });
    const solution = shaped(at(1));
    const check = (s: RasterState): Verdict => {
      const [q0, q1, q2] = s.points;
      if (s.points.length !== 3 || distance(q0, p0) > 0 || distance(q2, p2) > 0)
        return {
          correct: false,
          message:
            'Move only P₁: P₀ and P₂ stay where they are, and the curve keeps its three points.',
        };
      const { segments, whole, half: halves } = flattened(s.points);
      const flat = `the whole curve’s flatness is ${words(whole)} px`;
      if (segments === 2)
        return {
          correct: true,
          message: `Correct: ${flat} > τ = ${SPLIT_TOLERANCE}, so it is split once, and each half’s ${words(halves ?? 0)} px ≤ τ.`,
        };
      return segments < 2
        ? {
            correct: false,
            message: `Not yet: ${flat} ≤ τ = ${SPLIT_TOLERANCE}, so it is one segment. Move P₁ further from the middle of P₀P₂ (now ${words(distance(q1, middle))} px away).`,
          }
        : {
            correct: false,
            message: `Not yet: ${segments} segments, as ${flat} and each half’s ${words(halves ?? 0)} px > τ = ${SPLIT_TOLERANCE}, so the halves are split again: bring P₁ closer to the middle of P₀P₂ (now ${words(distance(q1, middle))} px away).`,
          };
    };
    return {
      state: shaped(at(far)),
      prompt: `Keep P₀ ${pointWords(p0)} and P₂ ${pointWords(p2)}, and drag P₁ so that adaptive flattening to τ = ${SPLIT_TOLERANCE} px draws the quadratic with exactly two segments. The whole curve must be split at t = ½, and both halves must then be flat enough.`,
      task: { kind: 'construct', check, solution },
      // The test on the whole curve, the split, both halves flat: two segments.
      working: solution,
    };
  },
};

/** The lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<RasterState>[] = [
  farthestPoint,
  nextPixel,
  flatness,
  twoSegments,
];
