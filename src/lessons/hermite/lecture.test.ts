/**
 * The lesson read against the course notes: the matrices on screen are the
 * lecture's (typed here from the notes), their product with the data is the
 * patch computed another way, and every handle of every scene is on the figure.
 */
import { describe, expect, it } from 'vitest';
import { sceneStates } from '../../kit/scriptChecks';
import { bezierToPowerBasis, hermiteBasis, hermiteMatrix, type Point } from '../../math';
import { HERMITE_LECTURE_INVERSE, HERMITE_LECTURE_MATRIX } from '../../math/hermite';
import lesson from './lesson';
import type { HermiteModel } from './model';
import type { Reveal } from './script';
import type { HermiteState } from './state';

/** The lecture notes (000), "Spline Patches": equation 6 as a matrix and equation 7, data (Pi, P′i, Pi+1, P′i+1). */
const EQUATION_6 = [
  [1, 0, 0, 0],
  [0, 1, 0, 0],
  [1, 1, 1, 1],
  [0, 1, 2, 3],
];
const EQUATION_7 = [
  [1, 0, 0, 0],
  [0, 1, 0, 0],
  [-3, -2, 3, -1],
  [2, 1, -2, 1],
];
/** The continuation notes (002), "Cubic Hermite Interpolation": (a, b, c, d) from (x0, x1, x0′, x1′). */
const CONTINUATION_INVERSE = [
  [2, -2, 1, 1],
  [-3, 3, -2, -1],
  [0, 0, 1, 0],
  [1, 0, 0, 0],
];

const times = (matrix: readonly (readonly number[])[], data: readonly Point[]): Point[] =>
  matrix.map((row) => data[0].map((_, d) => row.reduce((sum, m, k) => sum + m * data[k][d], 0)));

const expectClose = (actual: readonly Point[], expected: readonly Point[]) =>
  expected.forEach((row, i) => row.forEach((v, d) => expect(actual[i][d]).toBeCloseTo(v, 10)));

/** Every scene as it opens, with its state at step k. */
const scenes = () =>
  sceneStates(lesson).map(({ id, count, at }) => ({
    id,
    count,
    at: (k: number) => at(k) as unknown as HermiteState,
  }));

/** Every scene at every step of its script. */
const everyStep = () =>
  scenes().flatMap(({ id, count, at }) =>
    Array.from({ length: count + 1 }, (_, k) => ({ id, k, state: at(k) })),
  );

/** TeX of a matrix as the lesson writes it. */
const texMatrix = (rows: readonly (readonly number[])[]) =>
  `\\begin{pmatrix}${rows.map((row) => row.join(' & ')).join('\\\\')}\\end{pmatrix}`;

describe('the matrices of the lecture notes', () => {
  it('are the lesson’s, number for number', () => {
    expect(HERMITE_LECTURE_MATRIX).toEqual(EQUATION_6);
    expect(HERMITE_LECTURE_INVERSE).toEqual(EQUATION_7);
    expect(hermiteMatrix().reverse()).toEqual(CONTINUATION_INVERSE);
  });

  it('are what the steps show: equation 6 at the matrix step, equation 7 at every patch', () => {
    const formulas = everyStep()
      .filter(({ state }) => !state.bezier)
      .map(({ state }) => {
        const model = lesson.derive(state) as HermiteModel;
        return { shown: model.shown, tex: lesson.steps!.formula!(model, state)! };
      });
    const matrix = formulas.filter(({ shown }) => shown.is('matrix'));
    const patches = formulas.filter(({ shown }) => shown.is('patch'));
    expect(matrix.length).toBe(4);
    expect(patches.length).toBe(1 + 1 + 4 + 4);
    for (const { tex } of matrix) expect(tex).toContain(texMatrix(EQUATION_6));
    for (const { tex } of patches) expect(tex).toContain(texMatrix(EQUATION_7));
    // Nowhere the app's old matrix, whose columns weigh (Pi, Pi+1, Di, Di+1).
    for (const { tex } of formulas) expect(tex).not.toContain(texMatrix(hermiteMatrix()));
  });
});

describe('the Hermite basis, read down the columns of equation 7', () => {
  it('weights Pi, Pi+1, Di, Di+1 by the columns for Pi, Pi+1, P′i, P′i+1', () => {
    // H0 weighs Pi (column 1), H1 Pi+1 (column 3), H2 Di (column 2), H3 Di+1 (column 4).
    const columns = [0, 2, 1, 3].map((c) => EQUATION_7.map((row) => row[c]));
    for (const mu of [0, 0.3, 0.5, 0.8, 1]) {
      const powers = [1, mu, mu ** 2, mu ** 3];
      const read = columns.map((column) => column.reduce((sum, v, k) => sum + v * powers[k], 0));
      hermiteBasis(mu).forEach((h, k) => expect(read[k]).toBeCloseTo(h, 12));
    }
    const formulaAt = (name: Reveal) => {
      const state = everyStep().find(({ state }) => {
        const { shown } = lesson.derive(state) as HermiteModel;
        return !state.bezier && shown.is(name);
      })!.state;
      return lesson.steps!.formula!(lesson.derive(state), state)!;
    };
    const written = (k: number) => `H_${k} = (${columns[k].join(',\\ ')})\\cdot`;
    expect(formulaAt('pointWeights')).toContain(written(0));
    expect(formulaAt('pointWeights')).toContain(written(1));
    expect(formulaAt('gradientWeights')).toContain(written(2));
    expect(formulaAt('gradientWeights')).toContain(written(3));
  });
});

describe('equation 7 times the data', () => {
  it('is each patch of every scene, as the Bézier curve multiplied out (equation 11)', () => {
    for (const { id, k, state } of everyStep()) {
      const { patch } = lesson.derive(state) as HermiteModel;
      const product = times(EQUATION_7, patch.data);
      // Computed another way: the patch's Bézier control points in the power basis.
      expectClose(product, bezierToPowerBasis(patch.bezier));
      expectClose(product, patch.coefficients);
      expectClose(product, patch.power);
      // And back: equation 6 times a0 … a3 is the data again.
      expectClose(times(EQUATION_6, product), patch.data);
      expect(patch.data, `${id} step ${k}`).toEqual([patch.p0, patch.d0, patch.p1, patch.d1]);
    }
  });

  it('with the Bézier curve’s data (B0, 3(B1 − B0), B3, 3(B3 − B2)) is the same patch', () => {
    for (const { state } of everyStep()) {
      const { patch } = lesson.derive(state) as HermiteModel;
      const [b0, b1, b2, b3] = patch.bezier;
      const data = [b0, b1.map((v, d) => 3 * (v - b0[d])), b3, b3.map((v, d) => 3 * (v - b2[d]))];
      expectClose(times(EQUATION_7, data), bezierToPowerBasis(patch.bezier));
    }
  });

  it('and the continuation notes’ form give the same numbers, in the reverse order', () => {
    const { patch } = lesson.derive(everyStep()[0].state) as HermiteModel;
    const [p0, d0, p1, d1] = patch.data;
    const abcd = times(CONTINUATION_INVERSE, [p0, p1, d0, d1]);
    expectClose(abcd, [...patch.coefficients].reverse());
  });
});

describe('the figure of every scene', () => {
  it('shows every handle at every step, the gradients’ tips too, within its bounds', () => {
    for (const { id, k, state } of everyStep()) {
      const model = lesson.derive(state) as HermiteModel;
      for (const figure of lesson.figures) {
        const box = figure.bounds(model);
        for (const handle of figure.handles?.(model) ?? []) {
          const [x, y] = handle.position;
          const where = `${id} step ${k}, ${figure.id}: ${handle.id} at (${x}, ${y})`;
          expect(x, where).toBeGreaterThanOrEqual(box.minX);
          expect(x, where).toBeLessThanOrEqual(box.maxX);
          expect(y, where).toBeGreaterThanOrEqual(box.minY);
          expect(y, where).toBeLessThanOrEqual(box.maxY);
        }
      }
    }
  });

  it('fits the same box at every step of a scene, so revealing a tip never leaves it off', () => {
    for (const { id, count, at } of scenes()) {
      const first = lesson.figures[0].bounds(lesson.derive(at(0)));
      const tips = (lesson.derive(at(0)) as HermiteModel).tips;
      for (const [x, y] of tips) {
        expect(x, id).toBeGreaterThanOrEqual(first.minX);
        expect(x, id).toBeLessThanOrEqual(first.maxX);
        expect(y, id).toBeGreaterThanOrEqual(first.minY);
        expect(y, id).toBeLessThanOrEqual(first.maxY);
      }
      expect(lesson.figures[0].bounds(lesson.derive(at(count))), id).toEqual(first);
    }
  });
});
