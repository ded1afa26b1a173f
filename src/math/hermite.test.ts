import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { expectClose, plain, point, unitParameter } from './arbitraries.test-helpers';
import { bezierPoint } from './bezier';
import { bezierToPowerBasis } from './powerBasis';
import {
  HERMITE_LECTURE_INVERSE,
  HERMITE_LECTURE_MATRIX,
  bezierToHermite,
  hermiteBasis,
  hermiteBasisDerivatives,
  hermiteCoefficients,
  hermiteLectureCoefficients,
  hermiteMatrix,
  hermitePoint,
  hermiteToBezier,
} from './hermite';
import type { Point } from './vec';

function multiply(a: number[][], b: number[][]): number[][] {
  return a.map((row) =>
    b[0].map((_, j) => row.reduce((sum, value, k) => sum + value * b[k][j], 0)),
  );
}

const hermiteData = fc
  .constantFrom(2, 3)
  .chain((dimension) =>
    fc.tuple(point(dimension), point(dimension), point(dimension), point(dimension)),
  );

describe('hermiteMatrix', () => {
  it('is the inverse of the conditions in the order x0, x1, x0′, x1′ (not the lecture’s order)', () => {
    const constraints = [
      [1, 0, 0, 0],
      [1, 1, 1, 1],
      [0, 1, 0, 0],
      [0, 1, 2, 3],
    ];
    // constraints · a = [x0, x1, x0′, x1′], so a = hermiteMatrix · [x0, x1, x0′, x1′].
    expect(multiply(constraints, hermiteMatrix())).toEqual([
      [1, 0, 0, 0],
      [0, 1, 0, 0],
      [0, 0, 1, 0],
      [0, 0, 0, 1],
    ]);
    expect(hermiteMatrix()).toEqual([
      [1, 0, 0, 0],
      [0, 0, 1, 0],
      [-3, 3, -2, -1],
      [2, -2, 1, 1],
    ]);
  });
});

describe('the lecture’s matrices (lecture notes, equations 6 and 7)', () => {
  // Typed from the notes (000, "Spline Patches"), data in the order (Pi, P′i, Pi+1, P′i+1).
  const equation6 = [
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [1, 1, 1, 1],
    [0, 1, 2, 3],
  ];
  const equation7 = [
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [-3, -2, 3, -1],
    [2, 1, -2, 1],
  ];

  it('reads as the notes print them', () => {
    expect(HERMITE_LECTURE_MATRIX).toEqual(equation6);
    expect(HERMITE_LECTURE_INVERSE).toEqual(equation7);
  });

  it('are inverses of one another', () => {
    const identity = [
      [1, 0, 0, 0],
      [0, 1, 0, 0],
      [0, 0, 1, 0],
      [0, 0, 0, 1],
    ];
    const matrix = HERMITE_LECTURE_MATRIX.map((row) => [...row]);
    const inverse = HERMITE_LECTURE_INVERSE.map((row) => [...row]);
    expect(multiply(matrix, inverse)).toEqual(identity);
    expect(multiply(inverse, matrix)).toEqual(identity);
  });

  it('is hermiteMatrix with its columns in the lecture’s order', () => {
    // hermiteMatrix's columns weigh (x0, x1, x0′, x1′); the lecture's (Pi, P′i, Pi+1, P′i+1).
    const reordered = hermiteMatrix().map((row) => [row[0], row[2], row[1], row[3]]);
    expect(reordered).toEqual(equation7);
  });
});

describe('hermiteLectureCoefficients', () => {
  it('works equation 7 for the first scene’s patch by hand', () => {
    // P0 = (0, 0), P′0 = (3, 4.5), P1 = (4, 0), P′1 = (3, −4.5):
    // a2 = −3·0 − 2·(3, 4.5) + 3·(4, 0) − (3, −4.5) = (3, −4.5), a3 = 2·0 + (3, 4.5) − 2·(4, 0) + (3, −4.5) = (−2, 0).
    expect(hermiteLectureCoefficients([0, 0], [3, 4.5], [4, 0], [3, -4.5])).toEqual([
      [0, 0],
      [3, 4.5],
      [3, -4.5],
      [-2, 0],
    ]);
  });

  it('agrees with hermiteCoefficients, worked out another way', () => {
    fc.assert(
      fc.property(hermiteData, ([p0, d0, p1, d1]) => {
        const lecture = hermiteLectureCoefficients(p0, d0, p1, d1);
        hermiteCoefficients(p0, d0, p1, d1).forEach((a, k) => expectClose(lecture[k], a, 1e-12));
      }),
    );
  });

  it('gives a Bézier curve’s power form from P0, 3(P1 − P0), P3, 3(P3 − P2) (the lecture’s equation 11)', () => {
    fc.assert(
      fc.property(
        fc
          .constantFrom(2, 3)
          .chain((dimension) => fc.array(point(dimension), { minLength: 4, maxLength: 4 })),
        (bezier) => {
          const [p0, d0, p1, d1] = bezierToHermite(bezier);
          const lecture = hermiteLectureCoefficients(p0, d0, p1, d1);
          bezierToPowerBasis(bezier).forEach((a, k) => expectClose(lecture[k], a, 1e-9));
        },
      ),
    );
  });

  it('rejects mismatched dimensions', () => {
    expect(() => hermiteLectureCoefficients([0, 0], [1, 1, 1], [1, 1], [0, 0])).toThrow(
      /has 3 coordinates but 2 are expected/,
    );
  });
});

describe('hermiteBasis', () => {
  it('has the values of the lecture’s table', () => {
    expect(plain(hermiteBasis(0))).toEqual([1, 0, 0, 0]);
    expect(plain(hermiteBasis(1))).toEqual([0, 1, 0, 0]);
    expect(hermiteBasis(0.5)).toEqual([0.5, 0.5, 0.125, -0.125]);
    const t = 0.25;
    const expected = [
      2 * t ** 3 - 3 * t ** 2 + 1,
      -2 * t ** 3 + 3 * t ** 2,
      t ** 3 - 2 * t ** 2 + t,
      t ** 3 - t ** 2,
    ];
    hermiteBasis(t).forEach((value, i) => expect(value).toBeCloseTo(expected[i], 15));
    expect(hermiteBasis(0.25)).toEqual([0.84375, 0.15625, 0.140625, -0.046875]);
    expect(hermiteBasis(0.75)).toEqual([0.15625, 0.84375, 0.046875, -0.140625]);
  });

  it('matches the power-form polynomials everywhere', () => {
    fc.assert(
      fc.property(unitParameter, (t) => {
        const expected = [
          2 * t ** 3 - 3 * t ** 2 + 1,
          -2 * t ** 3 + 3 * t ** 2,
          t ** 3 - 2 * t ** 2 + t,
          t ** 3 - t ** 2,
        ];
        hermiteBasis(t).forEach((value, i) => expect(value).toBeCloseTo(expected[i], 14));
      }),
    );
  });

  it('has derivatives matching finite differences', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.01, max: 0.99, noNaN: true }),
        fc.constantFrom(1, 2),
        (t, order) => {
          const h = 1e-5;
          const f = order === 1 ? hermiteBasis : (x: number) => hermiteBasisDerivatives(x, 1);
          const [ahead, behind] = [f(t + h), f(t - h)];
          hermiteBasisDerivatives(t, order).forEach((value, i) =>
            expect(value).toBeCloseTo((ahead[i] - behind[i]) / (2 * h), 5),
          );
        },
      ),
    );
    expect(plain(hermiteBasisDerivatives(0))).toEqual([0, 0, 1, 0]);
    expect(plain(hermiteBasisDerivatives(1))).toEqual([0, 0, 0, 1]);
    expect(hermiteBasisDerivatives(0.5, 3)).toEqual([12, -12, 6, 6]);
    expect(hermiteBasisDerivatives(0.5, 4)).toEqual([0, 0, 0, 0]);
  });

  it('rejects t outside [0, 1] and a bad order', () => {
    expect(() => hermiteBasis(-0.5)).toThrow(/t = -0.5 is outside/);
    expect(() => hermiteBasisDerivatives(0.5, 0)).toThrow(/order/);
  });
});

describe('hermiteCoefficients', () => {
  it('gives a0 = x0, a1 = x0′, a2 = −3x0 + 3x1 − 2x0′ − x1′, a3 = 2x0 − 2x1 + x0′ + x1′', () => {
    expect(hermiteCoefficients([1], [2], [5], [3])).toEqual([
      [1],
      [2],
      [3 * 5 - 3 * 1 - 4 - 3],
      [2 - 10 + 2 + 3],
    ]);
  });

  it('gives a cubic with the right end points and end gradients', () => {
    fc.assert(
      fc.property(hermiteData, ([p0, d0, p1, d1]) => {
        const [a0, a1, a2, a3] = hermiteCoefficients(p0, d0, p1, d1);
        const at1 = a0.map((_, d) => a0[d] + a1[d] + a2[d] + a3[d]);
        const slope1 = a0.map((_, d) => a1[d] + 2 * a2[d] + 3 * a3[d]);
        expectClose(a0, p0);
        expectClose(a1, d0);
        expectClose(at1, p1, 1e-9);
        expectClose(slope1, d1, 1e-9);
      }),
    );
  });
});

describe('hermitePoint and the Bézier form', () => {
  it('Hermite → Bézier gives P0, P0 + D0/3, P1 − D1/3, P1', () => {
    expect(hermiteToBezier([0, 0], [3, 6], [4, 0], [3, -6])).toEqual([
      [0, 0],
      [1, 2],
      [3, 2],
      [4, 0],
    ]);
    expect(
      bezierToHermite([
        [0, 0],
        [1, 2],
        [3, 2],
        [4, 0],
      ]),
    ).toEqual([
      [0, 0],
      [3, 6],
      [4, 0],
      [3, -6],
    ]);
  });

  it('draws the same curve either way', () => {
    fc.assert(
      fc.property(hermiteData, unitParameter, ([p0, d0, p1, d1], t) => {
        const bezier = hermiteToBezier(p0, d0, p1, d1);
        expectClose(hermitePoint(p0, d0, p1, d1, t), bezierPoint(bezier, t), 1e-8);
        bezierToHermite(bezier).forEach((value, i) =>
          expectClose(value, [p0, d0, p1, d1][i], 1e-9),
        );
      }),
    );
  });

  it('keeps precision for end points near 1e6', () => {
    const p = hermitePoint([1e6, 1e6], [0, 0], [1e6 + 1, 1e6 + 1], [0, 0], 0.5);
    expect(p).toEqual([1e6 + 0.5, 1e6 + 0.5]);
  });

  it('rejects mismatched dimensions', () => {
    const bad: Point = [1, 2, 3];
    expect(() => hermiteCoefficients([0, 0], bad, [1, 1], [0, 0])).toThrow(
      /d0 has 3 coordinates but 2 are expected/,
    );
    expect(() =>
      bezierToHermite([
        [0, 0],
        [1, 1],
        [2, 2],
      ]),
    ).toThrow(/exactly 4 control points/);
  });
});
