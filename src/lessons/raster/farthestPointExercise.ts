/**
 * The exercise on plotting a curve: where a quadratic drawn as one
 * segment strays furthest from it.
 */
import { type ExerciseSpec, type Random, pointTask, random } from '../../kit/exercise';
import { type Point, bezierPoint, distance } from '../../math';
import { listed, sceneState } from './exerciseSetup';
import type { RasterState } from './state';

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

export const farthestPoint: ExerciseSpec<RasterState> = {
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
      task: pointTask('curve', answer, GAP_TOLERANCE, hint),
      // One segment: the two computed points P(0), P(1), the segment, the curve, its largest gap.
      working: { ...state, uniformSegments: 1 },
    };
  },
};
