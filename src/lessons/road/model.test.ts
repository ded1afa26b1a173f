import { describe, expect, it } from 'vitest';
import type { Point } from '../../math';
import { checkScript } from '../../kit/scriptChecks';
import { roadHandles } from './handles';
import lesson from './lesson';
import type { RoadModel } from './model';
import { valleyVillages } from './scenes';
import { SIX_VILLAGES, type RoadState, chunkSize, normalize, schema } from './state';
import { defaultsOf } from '../../app/urlState';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: RoadState) => lesson.derive(s) as RoadModel;
const stepCount = (s: RoadState) => lesson.steps!.count(s);
const describeStep = (s: RoadState, k: number) => lesson.steps!.describe(s, k);
/** How far step `s.step` has built the road. */
const stage = (s: RoadState) => derive(s).stage;

/** A state of the lesson: its defaults with some fields changed, then its cross-field rules. */
function state(change: Partial<RoadState>): RoadState {
  // The whole road (the last step) unless a step is asked for.
  const next = { ...defaultsOf(schema), ...change };
  return normalize({ ...next, step: change.step ?? stepCount(next) }).state;
}

/** Three villages whose y goes 0, 1, 0 and whose x goes 0, 1, 2. */
const hill: Point[] = [
  [0, 0],
  [1, 1],
  [2, 0],
];

const close = (actual: readonly number[], expected: readonly number[]) =>
  expected.forEach((value, i) => expect(actual[i]).toBeCloseTo(value, 12));

describe('the natural road through (0, 0), (1, 1), (2, 0)', () => {
  // The system (lecture notes): [2 1 | 3(y1 − y0)], [1 4 1 | 3(y2 − y0)], [1 2 | 3(y2 − y1)].
  // For y = 0, 1, 0: right-hand side 3, 0, −3, solved by D = 3/2, 0, −3/2
  // (2·3/2 + 0 = 3, 3/2 + 0 − 3/2 = 0, 0 − 3 = −3). For x = 0, 1, 2: 3, 6, 3, so D = 1, 1, 1.
  const m = derive(state({ villages: hill, road: 'natural' }));

  it('solves the system for both coordinates', () => {
    const solve = m.solve!;
    expect(solve.matrix.diag).toEqual([2, 4, 2]);
    expect(solve.rhs).toEqual([
      [3, 6, 3],
      [3, 0, -3],
    ]);
    close(solve.trace[1].solution, [1.5, 0, -1.5]);
    close(solve.trace[0].solution, [1, 1, 1]);
    // γ0 = 1/2, γ1 = 1/(4 − 1/2) = 2/7; for y, Γ0 = 3/2, Γ1 = (0 − 3/2)/(7/2) = −3/7.
    close(solve.trace[1].gamma, [1 / 2, 2 / 7]);
    close(solve.trace[1].Gamma, [3 / 2, -3 / 7, -3 / 2]);
  });

  it('builds each piece from the gradients: [Pi, Pi + Di/3, P(i+1) − D(i+1)/3, P(i+1)]', () => {
    const pieces = m.visible!.pieces;
    expect(pieces).toHaveLength(2);
    [
      [0, 0],
      [1 / 3, 1 / 2],
      [2 / 3, 1],
      [1, 1],
    ].forEach((point, k) => close(pieces[0][k], point));
    m.gradients!.forEach((d, i) =>
      close(
        d,
        [
          [1, 1.5],
          [1, 0],
          [1, -1.5],
        ][i],
      ),
    );
  });

  it('gives the power form of a piece: P(p) = a + b p + c p² + d p³', () => {
    // Segment 0 in y: a = 0, b = D0 = 3/2, c = 3(y1 − y0) − 2D0 − D1 = 0, d = 2(y0 − y1) + D0 + D1 = −1/2.
    const coefficients = m.coefficients(0);
    close(
      coefficients.map((c) => c[1]),
      [0, 1.5, 0, -0.5],
    );
    close(
      coefficients.map((c) => c[0]),
      [0, 1, 0, 0],
    );
  });

  it('while the solve is stepped through, shows only the pieces whose gradients are known', () => {
    // 3 rows: step 0 the villages, 1 the system, 2–4 sweep, 5 fixes D2, 6 fixes D1:
    // segment 1 (P1 to P2) can be drawn.
    const fixing = derive(state({ villages: hill, road: 'natural', step: 5 }));
    expect(fixing.solving).toBe(true);
    expect(fixing.progress).toEqual({ swept: 3, fixed: 1, row: 2 });
    expect(fixing.visible!.pieces).toEqual([]);
    const half = derive(state({ villages: hill, road: 'natural', step: 6 }));
    expect(half.visible!.offset).toBe(1);
    [
      [1, 1],
      [4 / 3, 1],
      [5 / 3, 1 / 2],
      [2, 0],
    ].forEach((point, k) => close(half.visible!.pieces[0][k], point));
    expect(half.visible!.marker).toBeNull();
    // The arrows of the gradients found so far end at Pi + Di/3.
    close(half.gradientTips![2], [2 + 1 / 3, -1 / 2]);
  });

  it('counts the conditions and the cost of the solve', () => {
    // Two cubic segments: 8 unknowns, 4 conditions at the inner village, 2 end positions: 2 free.
    expect(m.count).toEqual({ segments: 2, unknowns: 8, inner: 4, ends: 2, free: 2 });
    expect(m.cost?.unknowns).toBe(8);
  });
});

describe('the other roads', () => {
  it('Roman road: straight pieces, with the marker halfway along at p̄ = ½', () => {
    const m = derive(
      state({
        villages: [
          [0, 0],
          [4, 2],
          [4, 6],
        ],
        road: 'roman',
        pBar: 1.5,
      }),
    );
    expect(m.visible!.pieces).toEqual([
      [
        [0, 0],
        [4, 2],
      ],
      [
        [4, 2],
        [4, 6],
      ],
    ]);
    expect(m.visible!.marker).toEqual({ piece: 1, p: 0.5, point: [4, 4] });
    expect(m.along).toEqual({ piece: 1, p: 0.5 });
    expect(m.coefficients(0)).toEqual([
      [0, 0],
      [4, 2],
    ]);
    // Ticks at p̄ = 0, ¼, …, 2: five on the first piece, four more on the second.
    expect(m.visible!.ticks!.length / 5).toBe(9);
  });

  it('quadratic pieces: B₀ = P₀ + D₀/2, then each Bi is B(i−1) reflected in Pi', () => {
    const m = derive(
      state({ villages: SIX_VILLAGES, road: 'quadratic', quadraticGradient: [30, 0] }),
    );
    expect(m.quadraticControl).toEqual([15, 0]);
    // B1 = 2·(20, 16) − (15, 0) = (25, 32); B2 = 2·(42, 10) − (25, 32) = (59, −12).
    expect(m.quadraticPolygon!.controls.slice(0, 2)).toEqual([
      [25, 32],
      [59, -12],
    ]);
    expect(m.quadraticPolygon!.polygon.slice(0, 4)).toEqual([
      [0, 0],
      [15, 0],
      [20, 16],
      [25, 32],
    ]);
    expect(m.solve).toBeNull();
  });

  it('Hermite: the gradient at Pi is half the chord between its neighbours, zero at the ends', () => {
    const m = derive(state({ villages: SIX_VILLAGES, road: 'hermite' }));
    // D1 = ((42, 10) − (0, 0))/2 = (21, 5).
    expect(m.gradients!.slice(0, 2)).toEqual([
      [0, 0],
      [21, 5],
    ]);
  });

  it('ring road: one more segment, and the first right-hand side 3(x1 − xm)', () => {
    const m = derive(state({ villages: SIX_VILLAGES, road: 'ring' }));
    expect(m.visible!.pieces).toHaveLength(6);
    expect(m.ringRhs).toBe(3 * (20 - 92));
    expect(m.visible!.pieces[5][3]).toEqual([0, 0]);
  });

  it('a ring through two villages is not drawn, and the map says why first', () => {
    const m = derive(
      state({
        villages: [
          [0, 0],
          [60, 25],
        ],
        road: 'ring',
      }),
    );
    expect(m.visible!.missing).toMatch(/at least three villages/);
    expect(m.count).toBeNull();
    expect(m.mapNotes[0]).toBe(
      'A ring road needs at least three villages: with two it would only go there and back.',
    );
    expect(m.mapNotes[1]).toBe(
      'Two villages: one segment, a straight road for every method without a chosen gradient.',
    );
  });

  it('clamped: the end handles are the tips of D₀/3 and Dm/3', () => {
    const m = derive(
      state({ villages: hill, road: 'clamped', startGradient: [3, 6], endGradient: [-3, 3] }),
    );
    expect(m.usesEndGradients).toBe(true);
    expect(m.endHandles).toEqual([
      [1, 2],
      [1, 1],
    ]);
    expect(m.solve!.rhs[0]).toEqual([3, 6, -3]);
  });
});

describe('the overlay', () => {
  it('builds each chosen curve once, in order, and says which it cannot draw', () => {
    const m = derive(state({ villages: hill, view: 'compare', compare: [10, 0, 6] }));
    expect(m.visible).toBeNull();
    expect(m.overlay.map((curve) => curve.index)).toEqual([0, 6, 10]);
    expect(m.overlay.map((curve) => curve.road.kind)).toEqual(['pieces', 'polyline', 'missing']);
    // The Roman road's first piece elevated to a cubic: control points a third of the way along.
    [
      [0, 0],
      [1 / 3, 1 / 3],
      [2 / 3, 2 / 3],
      [1, 1],
    ].forEach((point, k) => close(m.overlay[0].cubics![0][k], point));
  });
});

describe('notes about the villages', () => {
  it('names villages on one spot', () => {
    const m = derive(
      state({
        villages: [
          [0, 0],
          [1, 1],
          [1, 1],
          [3, 0],
        ],
      }),
    );
    expect(m.notes[0]).toMatch(/on top of each other \(P1 = P2\)/);
  });
});

describe('the script (road)', () => {
  it('every scene steps from the villages alone to the whole road, in at most 20 steps', () => {
    checkScript(lesson);
  });

  it('the six villages: the system, six rows swept, six gradients fixed', () => {
    const lecture = state({ step: 0 });
    expect(stepCount(lecture)).toBe(13);
    expect(stage({ ...lecture, step: 1 }).solveStep).toBe(0);
    expect(stage({ ...lecture, step: 4 }).solveStep).toBe(3);
    expect(stage({ ...lecture, step: 13 }).solveStep).toBe(12);
    expect(describeStep(lecture, 3)).toBe('Forward sweep: row 1 becomes [1 γ | Γ]');
    expect(describeStep(lecture, 8)).toBe(
      'Back substitution: D₅ fixed, the road grows back from Pₘ',
    );
  });

  it('500 villages sweep and substitute in chunks of 56 rows: 19 steps, not 1000', () => {
    const valley = state({ villages: valleyVillages(500), step: 0 });
    expect(chunkSize(500)).toBe(56);
    expect(stepCount(valley)).toBe(1 + 9 + 9);
    expect(stage({ ...valley, step: 2 }).solveStep).toBe(56);
    expect(stage({ ...valley, step: 10 }).solveStep).toBe(500);
    expect(stage({ ...valley, step: 19 }).solveStep).toBe(1000);
    expect(describeStep(valley, 2)).toBe('Forward sweep: rows 0–55 become [1 γ | Γ]');
  });

  it('every method has steps: the others build their pieces from P₀ after their construction', () => {
    const roman = state({ road: 'roman', step: 0 });
    expect(stepCount(roman)).toBe(5);
    expect(derive({ ...roman, step: 2 }).visible!.pieces).toHaveLength(2);
    expect(derive({ ...roman, step: 2 }).visible!.marker).toBeNull();
    expect(derive({ ...roman, step: 5 }).visible!.marker).not.toBeNull();
    const quadratic = state({ road: 'quadratic', step: 0 });
    expect(stepCount(quadratic)).toBe(6);
    expect(describeStep(quadratic, 1)).toMatch(/^One chosen gradient D₀ at P₀/);
    expect(derive({ ...quadratic, step: 1 }).visible!.pieces).toHaveLength(0);
    const ring = state({ road: 'ring', step: 0 });
    expect(stepCount(ring)).toBe(1 + 6);
    const overlay = state({ view: 'compare', compare: [0, 3, 6], step: 2 });
    expect(stepCount(overlay)).toBe(3);
    expect(derive(overlay).overlay.map((c) => c.index)).toEqual([0, 3]);
    expect(describeStep(overlay, 3)).toBe('Answer 3 of 3: Lagrange polynomial');
  });

  it('labels the 600th village’s gradient D_{599}, all digits subscripted', () => {
    const v = valleyVillages(600);
    const m = derive(state({ villages: v, road: 'clamped' }));
    expect(roadHandles(m).find((h) => h.id === 'b')!.label).toBe('D_{599}');
  });
});
