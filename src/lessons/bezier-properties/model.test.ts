import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { type Point, bezierDerivative, bezierPoint, bezierTangent } from '../../math';
import lesson from './lesson';
import type { ModelOf, PropertiesModel } from './model';
import { type ExperimentId, ARCH_CUBIC, type PropertiesState, normalize, schema } from './state';

// Every expected value below is worked out by hand from the lecture's formulas.

const state = (changes: Partial<PropertiesState>): PropertiesState => ({
  ...defaultsOf(schema),
  ...changes,
});

function modelOf<X extends ExperimentId>(x: X, changes: Partial<PropertiesState>): ModelOf<X> {
  const m = lesson.derive(state({ ...changes, experiment: x })) as PropertiesModel;
  if (m.kind !== x) throw new Error(`derive gave the ${m.kind} model for ${x}`);
  return m as ModelOf<X>;
}

const closeTo = (actual: readonly number[], expected: readonly number[], digits = 12) =>
  expected.forEach((v, i) => expect(actual[i]).toBeCloseTo(v, digits));

describe('end points and end tangents', () => {
  const m = modelOf('ends', { points: ARCH_CUBIC, t: 0.5 });
  it('has P′(0) = 3(P1 − P0), P′(1) = 3(P3 − P2) and P′(½) from the hodograph', () => {
    const [start, end, at] = m.tangents;
    expect(start.vector).toEqual([3, 6]);
    expect(end.vector).toEqual([3, -6]);
    // Hodograph (3,6), (6,0), (3,−6) at ½: ¼(3,6) + ½(6,0) + ¼(3,−6) = (4.5, 0), at P(½) = (2, 1.5).
    closeTo(at.vector, [4.5, 0]);
    closeTo(m.point, [2, 1.5]);
    expect(start.speed).toBeCloseTo(3 * Math.sqrt(5), 12);
  });
  it('shows the arrows at half length: their tips are in the view', () => {
    expect(m.tangents[0].tip).toEqual([1.5, 3]);
    expect(m.extent).toContainEqual([1.5, 3]);
    expect(m.stillAtStart).toBe(false);
  });
});

describe('convex hull', () => {
  it('finds five corners for the preset and keeps all 401 samples inside', () => {
    const m = modelOf('hull', {
      points: [
        [0, 0],
        [1, 3],
        [3, 3.5],
        [2.5, 1],
        [5, 2],
        [6, 0],
      ],
    });
    // (2.5, 1) lies inside the pentagon of the other five points.
    expect(m.hull).toHaveLength(5);
    expect(m.hull).not.toContainEqual([2.5, 1]);
    expect(m.inside).toBe(401);
    expect(m.total).toBe(401);
  });
  it('is a segment for collinear points', () => {
    const m = modelOf('hull', {
      points: [
        [0, 0],
        [1, 1],
        [2, 2],
        [3, 3],
      ],
    });
    expect(m.hull).toEqual([
      [0, 0],
      [3, 3],
    ]);
    expect(m.inside).toBe(m.total);
  });
});

describe('no local control', () => {
  it('moves the curve by at most W(11, 5, 5/11) times the shift of P5', () => {
    const before: Point[] = Array.from({ length: 12 }, (_, i) => [i, 0]);
    const after = before.map((q, i) => (i === 5 ? [5, 2] : q));
    const m = modelOf('local', { points: after, before });
    // W(11, 5, 5/11) = C(11, 5)·5⁵·6⁶ / 11¹¹ = 462·3125·46656 / 11¹¹ ≈ 0.2361.
    const peak = (462 * 3125 * 46656) / 11 ** 11;
    expect(m.moved).toEqual([5]);
    expect(m.single?.peak).toBeCloseTo(peak, 14);
    expect(m.single?.shift).toBe(2);
    // Sampled at t = k/1000, the largest displacement is just below 2·peak.
    expect(m.largest.distance).toBeLessThanOrEqual(2 * peak);
    expect(m.largest.distance).toBeGreaterThan(2 * peak * 0.9999);
    expect(m.largest.at).toBeCloseTo(5 / 11, 3);
  });
});

describe('repeated and closing points', () => {
  it('sums the weights of the copies: P1 three times in a cubic is degree 5', () => {
    const m = modelOf('repeat', {
      points: [
        [0, 0],
        [1, 3],
        [4, 3],
        [5, 0],
      ],
      repeated: 1,
      // Step 3: the curve (step 1), then two extra copies.
      step: 3,
      t: 0.5,
    });
    expect(m.controls).toHaveLength(6);
    // W(5, 1..3, ½) = (5 + 10 + 10)/32; once: W(3, 1, ½) = 3/8.
    expect(m.weight).toBeCloseTo(25 / 32, 14);
    expect(m.weightOnce).toBeCloseTo(3 / 8, 14);
  });
  it('measures the corner where a closed curve meets itself', () => {
    const square = modelOf('closed', {
      points: [
        [0, 0],
        [1, 0],
        [1, 1],
        [0, 1],
      ],
    });
    // Leaving along 4(P1 − P0) = (4, 0), arriving along 4(P0 − P3) = (0, −4): a right angle.
    expect(square.n).toBe(4);
    expect(square.corner).toBeCloseTo(90, 12);
    expect(square.smooth).toBe(false);
    const smooth = modelOf('closed', {
      points: [
        [0, 0],
        [1, 0],
        [1, 1],
        [-1, 0],
      ],
    });
    expect(smooth.corner).toBe(0);
    expect(smooth.smooth).toBe(true);
  });
});

describe('degree elevation', () => {
  const m = modelOf('elevate', { points: ARCH_CUBIC, step: 2 }); // one elevation;
  it('gives Qi = i/4·P(i−1) + (1 − i/4)·Pi on the same curve', () => {
    expect(m.controls).toEqual([
      [0, 0],
      [0.75, 1.5],
      [2, 2],
      [3.25, 1.5],
      [4, 0],
    ]);
    expect(m.deviation).toBeLessThan(1e-12);
    expect(m.lastStep).toEqual({ from: 3, q1: [0.75, 1.5] });
  });
  it('measures the gap of each polygon: |P1 − P(1/3)| for the cubic', () => {
    // P(1/3) = (34/27, 36/27).
    expect(m.gaps[0]).toBeCloseTo(Math.hypot(1 - 34 / 27, 2 - 36 / 27), 12);
    expect(m.gaps[1]).toBeLessThan(m.gaps[0]);
  });
});

describe('subdivision', () => {
  it('splits at ½ into the de Casteljau polygons, twice', () => {
    const m = modelOf('split', { points: ARCH_CUBIC, t: 0.5, step: 3 }); // two splits;
    expect(m.levels.map((level) => level.length)).toEqual([1, 2, 4]);
    expect(m.first?.[0]).toEqual([
      [0, 0],
      [0.5, 1],
      [1.25, 1.5],
      [2, 1.5],
    ]);
    expect(m.gaps[1]).toBeLessThan(m.gaps[0] / 3);
    expect(m.atEnd).toBe(false);
  });
  it('says when t = 0 splits off a single point', () => {
    expect(modelOf('split', { t: 0, step: 2 }).atEnd).toBe(true);
  });
});

describe('affine and perspective maps', () => {
  it('shears about (2, 1) and shifts 6 right: images agree', () => {
    const m = modelOf('affine', { points: ARCH_CUBIC, map: 'shear' });
    if (!m.images.ok) throw new Error(m.images.why);
    // (x, y) ↦ (x + 0.8(y − 1) + 6, y): P0 = (0, 0) ↦ (5.2, 0), P1 = (1, 2) ↦ (7.8, 2).
    closeTo(m.images.mappedControls[0], [5.2, 0]);
    closeTo(m.images.mappedControls[1], [7.8, 2]);
    expect(m.images.weights).toEqual([1, 1, 1, 1]);
    expect(m.images.distance).toBeLessThan(1e-12);
    expect(m.images.rationalDistance).toBeNull();
  });
  it('divides by w = 1 + 0.22(x − 2) + 0.12(y − 1) in perspective, and weights repair it', () => {
    const m = modelOf('affine', { points: ARCH_CUBIC, map: 'perspective' });
    if (!m.images.ok) throw new Error(m.images.why);
    closeTo(m.images.weights, [0.44, 0.9, 1.34, 1.32]);
    closeTo(m.images.weightRange, [0.44, 1.34]);
    expect(m.images.distance).toBeGreaterThan(0.1);
    expect(m.images.rationalDistance).toBeLessThan(1e-9);
  });
  it('draws no image when a point is beyond the vanishing line', () => {
    // w(−5, 0) = 1 + 0.22·(−7) + 0.12·(−1) = −0.66.
    const m = modelOf('affine', {
      points: [[-5, 0], ...ARCH_CUBIC.slice(1)],
      map: 'perspective',
    });
    expect(m.images.ok).toBe(false);
    expect(m.extra).toEqual([]);
  });
});

describe('inflection and self-intersection', () => {
  it('finds the inflection of a cubic symmetric about (2, 1) at t = ½', () => {
    const m = modelOf('cubic', {
      points: [
        [0, 0],
        [1.5, 3],
        [2.5, -1],
        [4, 2],
      ],
    });
    expect(m.inflections).toHaveLength(1);
    expect(m.inflections[0].t).toBeCloseTo(0.5, 12);
    closeTo(m.inflections[0].point, [2, 1]);
    expect(m.loop).toBeNull();
    // It starts turning right: the legs (1.5, 3) then (1, −4) have cross product −9; it ends turning left.
    expect(m.runs[0].sign).toBe(-1);
    expect(m.runs[m.runs.length - 1].sign).toBe(1);
  });
  it('finds the loop where x(t) = 2: t = ½ ± √33/22, at (2, 18/11)', () => {
    // x(t) − 2 = 22t³ − 33t² + 15t − 2 = (2t − 1)(11t² − 11t + 2); y = 9t(1 − t) = 18/11 there.
    const m = modelOf('cubic', {
      points: [
        [0, 0],
        [5, 3],
        [-1, 3],
        [4, 0],
      ],
    });
    expect(m.loop?.t[0]).toBeCloseTo(0.5 - Math.sqrt(33) / 22, 9);
    expect(m.loop?.t[1]).toBeCloseTo(0.5 + Math.sqrt(33) / 22, 9);
    closeTo(m.loop!.point, [2, 18 / 11], 9);
    expect(m.inflections).toEqual([]);
  });
  it('gives κ(½) = −16/27 for the arch cubic, and nothing for a straight one', () => {
    // P′(½) = (4.5, 0), P″(½) = (0, −12): κ = 4.5·(−12) / 4.5³.
    expect(modelOf('cubic', { points: ARCH_CUBIC, t: 0.5 }).curvature).toBeCloseTo(-16 / 27, 12);
    const line = modelOf('cubic', {
      points: [
        [0, 0],
        [1, 1],
        [2, 2],
        [3, 3],
      ],
    });
    expect(line.straight).toBe(true);
  });
});

describe('the Hermite form of a cubic', () => {
  const m = modelOf('hermite', { points: ARCH_CUBIC, t: 0.4 });
  it('has the power form of equation 11 and the end data x0, x0′, x1, x1′', () => {
    expect(m.power).toEqual([
      [0, 0],
      [3, 6],
      [3, -6],
      [-2, 0],
    ]);
    expect([m.x0, m.d0, m.x1, m.d1]).toEqual([
      [0, 0],
      [3, 6],
      [4, 0],
      [3, -6],
    ]);
  });
  it('draws the end tangents at half length, as the end-tangents scene does: (0,0) + ½(3,6), (4,0) + ½(3,−6)', () => {
    expect(m.tips).toEqual([
      [1.5, 3],
      [5.5, -3],
    ]);
  });
  it('gives the same point: P(0.4) = a0 + 0.4a1 + 0.16a2 + 0.064a3 = (1.552, 1.44)', () => {
    closeTo(m.hermiteAtT, [1.552, 1.44]);
    closeTo(m.point, [1.552, 1.44]);
    expect(m.deviation).toBeLessThan(1e-12);
  });
});

describe('the derivative curve (hodograph)', () => {
  const m = modelOf('hodograph', { points: ARCH_CUBIC, t: 0.3 });
  it('has the legs times n as control points, by hand and as the maths gives them', () => {
    expect(m.differences).toEqual([
      [1, 2],
      [2, 0],
      [1, -2],
    ]);
    // 3(P1 − P0) = (3, 6), 3(P2 − P1) = (6, 0), 3(P3 − P2) = (3, −6): a quadratic.
    expect(m.hodograph).toEqual([
      [3, 6],
      [6, 0],
      [3, -6],
    ]);
    expect(m.hodograph).toEqual(bezierDerivative(ARCH_CUBIC));
    // Its ends are property 1's end tangents.
    const ends = modelOf('ends', { points: ARCH_CUBIC, t: 0.3 }).tangents;
    expect([m.hodograph[0], m.hodograph[2]]).toEqual([ends[0].vector, ends[1].vector]);
  });
  it('draws the vectors from O, right of the polygon: (4 + 0.3·4, 1) = (5.2, 1)', () => {
    // The polygon spans x 0 … 4, y 0 … 2 (size 4); the vectors and 0 span x 0 … 6, y −6 … 6.
    closeTo(m.origin, [5.2, 1]);
    closeTo(m.placed[1], [11.2, 1]);
    closeTo(m.placedDifferences[2], [6.2, -1]);
    expect(m.extent).toContainEqual(m.placed[0]);
  });
  it('gives P′(0.3) = 0.49·(3, 6) + 0.42·(6, 0) + 0.09·(3, −6) = (4.26, 2.4), along the tangent', () => {
    closeTo(m.weights, [0.49, 0.42, 0.09]);
    closeTo(m.derivative, [4.26, 2.4]);
    closeTo(bezierTangent(ARCH_CUBIC, 0.3), [4.26, 2.4]);
    // The construction's level 2: (0.69, 1.02) and (2.11, 1.82); 3 × their difference.
    closeTo(m.edge[0], [0.69, 1.02]);
    closeTo(m.edge[1], [2.11, 1.82]);
    closeTo(m.fromEdge, [4.26, 2.4]);
    closeTo(m.point, [1.116, 1.26]);
    expect(m.disagreement).toBeLessThan(1e-12);
    // The arrow at P(t) ends at (1.116 + 4.26, 1.26 + 2.4) = (5.376, 3.66), inside the view.
    closeTo(m.extent[m.extent.length - 1], [5.376, 3.66]);
  });
  it('is the velocity of the curve for any polygon: a central difference of P agrees', () =>
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: -9, max: 9 }), fc.integer({ min: -9, max: 9 })), {
          minLength: 2,
          maxLength: 8,
        }),
        fc.double({ min: 0.01, max: 0.99, noNaN: true }),
        (points, t) => {
          const h = modelOf('hodograph', { points, t });
          const step = 1e-5;
          const [a, b] = [bezierPoint(points, t - step), bezierPoint(points, t + step)];
          h.derivative.forEach((v, d) => expect(v).toBeCloseTo((b[d] - a[d]) / (2 * step), 4));
          expect(h.hodograph).toHaveLength(points.length - 1);
          expect(h.disagreement).toBeLessThan(1e-9);
        },
      ),
    ));
  it('is one constant vector for a straight segment (degree 1)', () => {
    const line = modelOf('hodograph', {
      points: [
        [0, 0],
        [2, 1],
      ],
      t: 0.7,
    });
    expect(line.hodograph).toEqual([[2, 1]]);
    closeTo(line.derivative, [2, 1]);
    closeTo(line.fromEdge, [2, 1]);
  });
});

describe('a cubic experiment given other than four points', () => {
  it('shows the arch cubic, and says so by what it is', () => {
    const five = state({ experiment: 'hermite', points: [...ARCH_CUBIC, [5, 1]] });
    const { state: shown, issues } = normalize(five);
    expect(shown.points).toEqual(ARCH_CUBIC);
    expect(issues).toEqual([
      'this experiment is about cubics, which have 4 control points, not 5; the arch cubic (0, 0), (1, 2), (3, 2), (4, 0) is shown',
    ]);
  });
});
