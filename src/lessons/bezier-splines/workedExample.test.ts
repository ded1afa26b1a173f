import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type Point, bezierPoint, cubicSplineC2, solveCubicSplineC2System } from '../../math';
import { itemsShown, pressItems, presses } from './presses';
import { FOUR_POINTS } from './state';
import { continuation, degreeCount, handC1, handC2 } from './workedExample';

// The worked example's points: p₀ = A = (0, 0), p₁ = D = (1, 2.5), p₂ = G = (4, 2.5), p₃ = J = (5, 0).

const close = (got: readonly Point[], want: readonly Point[], digits = 12) => {
  expect(got).toHaveLength(want.length);
  got.forEach((q, j) => q.forEach((v, d) => expect(v, `row ${j}`).toBeCloseTo(want[j][d], digits)));
};

describe('computeSplineC1 by hand', () => {
  it('takes b₀ the midpoint, then mirrors each bᵢ₋₁ through pᵢ', () => {
    // b₀ = ½((0, 0) + (1, 2.5)) = (0.5, 1.25)
    // b₁ = 2(1, 2.5) − (0.5, 1.25) = (1.5, 3.75)
    // b₂ = 2(4, 2.5) − (1.5, 3.75) = (6.5, 1.25)
    const { b, output } = handC1(FOUR_POINTS);
    expect(b).toEqual([
      [0.5, 1.25],
      [1.5, 3.75],
      [6.5, 1.25],
    ]);
    // 2n + 1 = 7 rows: p₀, b₀, p₁, b₁, p₂, b₂, p₃.
    expect(output).toEqual([
      [0, 0],
      [0.5, 1.25],
      [1, 2.5],
      [1.5, 3.75],
      [4, 2.5],
      [6.5, 1.25],
      [5, 0],
    ]);
  });
});

describe('computeSplineC2 by hand', () => {
  const worked = handC2(FOUR_POINTS);

  it('carries every control point in terms of the unknown B, equation by equation', () => {
    // C = 2B − A = 2B
    // E = 2D − C = (2, 5) − 2B
    // F = B − 2C + 2E = B − 4B + (4, 10) − 4B = (4, 10) − 7B
    // H = 2G − F = (8, 5) − (4, 10) + 7B = (4, −5) + 7B
    // I = E − 2F + 2H = (2, 5) − 2B − (8, 20) + 14B + (8, −10) + 14B = (2, −25) + 26B
    const forms = worked.forms.map((f) => [f.a, f.v[0], f.v[1]]);
    expect(forms).toEqual([
      [0, 0, 0],
      [1, 0, 0],
      [2, 0, 0],
      [0, 1, 2.5],
      [-2, 2, 5],
      [-7, 4, 10],
      [0, 4, 2.5],
      [7, 4, -5],
      [26, 2, -25],
      [0, 5, 0],
    ]);
  });

  it('fixes B by the natural end, then puts it back', () => {
    // H − 2I + J = (4, −5) + 7B − (4, −50) − 52B + (5, 0) = (5, 45) − 45B = 0, so B = (1/9, 1).
    expect([worked.end.a, ...worked.end.v]).toEqual([-45, 5, 45]);
    close([worked.B], [[1 / 9, 1]]);
    // C = 2B = (2/9, 2), E = (2 − 2/9, 3) = (16/9, 3), F = (4 − 7/9, 3) = (29/9, 3),
    // H = (4 + 7/9, 2) = (43/9, 2), I = (2 + 26/9, 1) = (44/9, 1).
    close(worked.controls, [
      [0, 0],
      [1 / 9, 1],
      [2 / 9, 2],
      [1, 2.5],
      [16 / 9, 3],
      [29 / 9, 3],
      [4, 2.5],
      [43 / 9, 2],
      [44 / 9, 1],
      [5, 0],
    ]);
    expect(worked.solverDifference).toBeLessThan(1e-12);
  });

  it('works for one piece: B = (2A + D)/3', () => {
    // C = 2B − A; the natural end B − 2C + D = −3B + 2A + D = 0.
    // A = (0, 0), D = (3, 6): B = (1, 2), C = (2, 4).
    close(
      handC2([
        [0, 0],
        [3, 6],
      ]).controls,
      [
        [0, 0],
        [1, 2],
        [2, 4],
        [3, 6],
      ],
    );
  });

  it('agrees with the maths module’s solver and its natural spline for 2 to 12 points', () => {
    const points = fc.array(
      fc.tuple(fc.integer({ min: -50, max: 50 }), fc.integer({ min: -50, max: 50 })),
      { minLength: 2, maxLength: 12 },
    );
    fc.assert(
      fc.property(points, (raw) => {
        const p: Point[] = raw.map(([x, y]) => [x / 10, y / 10]);
        const { controls } = handC2(p);
        close(controls, solveCubicSplineC2System(p).controls, 6);
        const natural = cubicSplineC2(p);
        close(controls, [p[0], ...natural.flatMap((s) => s.slice(1))], 6);
      }),
      { numRuns: 200 },
    );
  });
});

describe('how many choices a degree leaves', () => {
  it('counts control points, points and joint equations (n = 3 pieces)', () => {
    // d = 1: 4 − 4 − 0 = 0; d = 2: 7 − 4 − 2 = 1 (b₀); d = 3: 10 − 4 − 4 = 2 (natural ends); d = 5: 16 − 4 − 8 = 4.
    expect([1, 2, 3, 5].map((d) => degreeCount(d, 3))).toEqual([
      { unknowns: 4, interpolation: 4, smoothness: 0, free: 0 },
      { unknowns: 7, interpolation: 4, smoothness: 2, free: 1 },
      { unknowns: 10, interpolation: 4, smoothness: 4, free: 2 },
      { unknowns: 16, interpolation: 4, smoothness: 8, free: 4 },
    ]);
  });
  it('leaves d − 1 whatever the number of pieces', () => {
    for (let n = 1; n <= 11; n++)
      for (let d = 1; d <= 6; d++) expect(degreeCount(d, n).free).toBe(d - 1);
  });
});

describe('a cubic continued past its end', () => {
  it('is P(1 + t): the first C² piece reaches (6, 2) at t = 1, not G', () => {
    // A = (0, 0), B = (1/9, 1), C = (2/9, 2), D = (1, 2.5). In powers of t:
    // a₁ = 3(B − A) = (1/3, 3), a₂ = 3(A − 2B + C) = 0, a₃ = D − 3C + 3B − A = (2/3, −1/2).
    // P(2) = 2a₁ + 8a₃ = (2/3 + 16/3, 6 − 4) = (6, 2).
    // Its control points on [1, 2]: D, 2D − C, 4D − 4C + B, 8D − 12C + 6B − A.
    const first = handC2(FOUR_POINTS).controls.slice(0, 4);
    const next = continuation(first);
    close(next, [
      [1, 2.5],
      [2 - 2 / 9, 3],
      [4 - 8 / 9 + 1 / 9, 3],
      [6, 2],
    ]);
    // The same polynomial at t = 1.5: (1.5/3 + 3.375·2/3, 1.5·3 − 3.375/2) = (2.75, 2.8125).
    close([bezierPoint(next, 0.5)], [[2.75, 2.8125]]);
    // Its first two inner control points are E and F: C¹ and C² at D already ask what continuing asks.
    close(next.slice(1, 3), handC2(FOUR_POINTS).controls.slice(4, 6));
  });
});

describe('presses for a run of repeated steps', () => {
  it('takes one press per item up to three, then several per press', () => {
    // 2 items: [1], [2]; 10 items in 3 presses: 1–3, 4–6, 7–10.
    expect([0, 1, 2, 3, 10].map(presses)).toEqual([0, 1, 2, 3, 3]);
    expect([1, 2].map((k) => pressItems(2, k))).toEqual([[1], [2]]);
    expect([1, 2, 3].map((k) => pressItems(10, k))).toEqual([
      [1, 2, 3],
      [4, 5, 6],
      [7, 8, 9, 10],
    ]);
    expect([0, 1, 2, 3].map((k) => itemsShown(10, k))).toEqual([0, 3, 6, 10]);
  });
});
