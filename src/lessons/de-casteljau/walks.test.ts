import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { drawState } from '../../kit/scriptChecks';
import { bernstein, bezierPoint, deCasteljau } from '../../math';
import { expansionTex, weightTex } from './bernsteinForm';
import lesson from './lesson';
import type { DeCasteljauModel } from './model';
import { controlPoints } from './points';
import { LINES_RUN, computedBy, pseudocode } from './pseudocode';
import { SCENES, sceneOf } from './scenes';
import { type DeCasteljauState, schema } from './state';
import { lineValues } from './walkPanel';
import { scriptOf } from './walks';

// The arch P0 = (0, 0), P1 = (1, 2), P2 = (3, 2), P3 = (4, 0) at t = 0.5, by hand:
//   level 1: P1,0 = ½(0, 0) + ½(1, 2) = (0.5, 1), P1,1 = ½(1, 2) + ½(3, 2) = (2, 2),
//            P1,2 = ½(3, 2) + ½(4, 0) = (3.5, 1);
//   level 2: P2,0 = ½(0.5, 1) + ½(2, 2) = (1.25, 1.5), P2,1 = ½(2, 2) + ½(3.5, 1) = (2.75, 1.5);
//   level 3: P3,0 = ½(1.25, 1.5) + ½(2.75, 1.5) = (2, 1.5).
// The lecture slides' Example 4.18: x(½) = ⅛x0 + ⅜x1 + ⅜x2 + ⅛x3 = ((3 + 9 + 4)/8, (6 + 6)/8) = (2, 1.5).
const BY_HAND = [
  [
    [0.5, 1],
    [2, 2],
    [3.5, 1],
  ],
  [
    [1.25, 1.5],
    [2.75, 1.5],
  ],
  [[2, 1.5]],
];

const opened = (id: string, step = 0): DeCasteljauState => ({
  ...SCENES.find((s) => s.id === id)!.setup(defaultsOf(schema)),
  step,
});
const derive = (s: DeCasteljauState) => lesson.derive(s) as DeCasteljauModel;
const caption = (s: DeCasteljauState) => lesson.steps!.describe(s, s.step);
const formula = (s: DeCasteljauState) => lesson.steps!.formula!(derive(s), s);
/** The names of a walk's presses, in order. */
const names = (s: DeCasteljauState) =>
  Array.from({ length: scriptOf(s).lastStep(s) + 1 }, (_, k) => scriptOf(s).shown(s, k)).map(
    (shown) => (shown.index ? `${shown.name} ${shown.index}` : shown.name),
  );

describe('the pseudocode, run on the arch at t = 0.5 (a point worked by hand)', () => {
  it('takes one press per line run: the input, line 1, each point of line 4, the return, the plot', () => {
    expect(names(opened('pseudocode'))).toEqual([
      'input',
      'copy',
      'compute 1',
      'compute 2',
      'compute 3',
      'compute 4',
      'compute 5',
      'compute 6',
      'return',
      'plot',
    ]);
    // Line 4 runs for r = 1, i = 0 … 2; r = 2, i = 0 … 1; r = 3, i = 0.
    expect([1, 2, 3, 4, 5, 6].map((k) => computedBy(3, k))).toEqual([
      [[1, 0]],
      [[1, 1]],
      [[1, 2]],
      [[2, 0]],
      [[2, 1]],
      [[3, 0]],
    ]);
  });

  it('shows every intermediate number, each the one worked by hand and the maths’ own', () => {
    const levels = deCasteljau(opened('pseudocode').p, 0.5);
    const steps: [number, number, number][] = [
      [2, 1, 0],
      [3, 1, 1],
      [4, 1, 2],
      [5, 2, 0],
      [6, 2, 1],
      [7, 3, 0],
    ];
    for (const [step, r, i] of steps) {
      const m = derive(opened('pseudocode', step));
      expect(m.current).toEqual([[r, i]]);
      expect(m.levels[r][i]).toEqual(BY_HAND[r - 1][i]);
      expect(levels[r][i]).toEqual(BY_HAND[r - 1][i]);
    }
    expect(formula(opened('pseudocode', 2))).toBe(
      '\\text{4: } r = 1,\\ i = 0:\\quad P_{1,0} = 0.5\\cdot(0,\\ 0) + 0.5\\cdot(1,\\ 2) = (0.5,\\ 1)',
    );
    // At t = 0.3 the two weights differ: P1,0 = 0.7·(0, 0) + 0.3·(1, 2) = (0.3, 0.6).
    expect(formula({ ...opened('pseudocode', 2), t: 0.3 })).toBe(
      '\\text{4: } r = 1,\\ i = 0:\\quad P_{1,0} = 0.7\\cdot(0,\\ 0) + 0.3\\cdot(1,\\ 2) = (0.3,\\ 0.6)',
    );
    expect(formula(opened('pseudocode', 6))).toBe(
      '\\text{4: } r = 2,\\ i = 1:\\quad P_{2,1} = 0.5\\cdot(2,\\ 2) + 0.5\\cdot(3.5,\\ 1) = (2.75,\\ 1.5)',
    );
    expect(caption(opened('pseudocode', 6))).toBe(
      'r = 2, i = 1: line 4 cuts the edge P₁,₁ P₁,₂ at t = 0.5, giving P₂,₁',
    );
    expect(formula(opened('pseudocode', 8))).toBe(
      '\\text{5: return } P_{3,0} = P(0.5) = (2,\\ 1.5)',
    );
    // drawCurve at j/10: P(0.1) = 0.729·P0 + 0.243·P1 + 0.027·P2 + 0.001·P3
    //   = (0.243 + 0.081 + 0.004, 0.486 + 0.054) = (0.328, 0.54).
    expect(formula(opened('pseudocode', 9))).toContain('P(0.1) = (0.328,\\ 0.54)');
    const plotted = derive(opened('pseudocode', 9)).plotted;
    expect(plotted).toHaveLength(11);
    plotted.forEach((q, j) => expect(q).toEqual(bezierPoint(opened('pseudocode').p, j / 10)));
  });

  it('marks the lines each step runs, with the loop variables and the point made', () => {
    expect(LINES_RUN.compute).toEqual([2, 3, 4]);
    expect(lineValues(derive(opened('pseudocode', 0)))[0]).toBe('n = 3, t = 0.5');
    const values = lineValues(derive(opened('pseudocode', 5)));
    expect(values.slice(1, 6)).toEqual(['P₀,₀ … P₀,₃', 'r = 2', 'i = 0', 'P₂,₀ = (1.25, 1.5)', '']);
    expect(lineValues(derive(opened('pseudocode', 9)))[5]).toBe('P₃,₀ = (2, 1.5)');
  });

  it('draws the point each step computes with its numbers, and counts what is computed so far', () => {
    // The label is drawn in parts: P, the subscript 1,0, then the numbers.
    expect(drawState(lesson, opened('pseudocode', 2)).texts.join('')).toContain('P1,0 = (0.5, 1)');
    const m = derive(opened('pseudocode', 5));
    // Line 1 copied level 0; three points of level 1 and the first of level 2 are made.
    expect(m.computed).toEqual([4, 3, 1, 0]);
    expect(derive(opened('pseudocode', 1)).computed).toEqual([4, 0, 0, 0]);
    expect(derive(opened('pseudocode', 0)).computed).toEqual([0, 0, 0, 0]);
  });

  it('steps a whole level per press above degree 4, so a scene stays within 20 presses', () => {
    const quintic = { ...opened('pseudocode'), p: opened('quintic').p };
    expect(computedBy(5, 2)).toEqual([
      [2, 0],
      [2, 1],
      [2, 2],
      [2, 3],
    ]);
    // input, copy, one press for each of 5 levels, return, plot.
    expect(pseudocode.lastStep(quintic)).toBe(8);
    expect(caption({ ...quintic, step: 3 })).toBe(
      'r = 2: lines 3 and 4 run i = 0 … 3, cutting every edge of level 1 at t = 0.5',
    );
    // Degree 4 still takes one press per point: 4 + 3 + 2 + 1 = 10 points, 14 presses.
    const quartic = { ...quintic, p: quintic.p.slice(0, 5) };
    expect(pseudocode.lastStep(quartic)).toBe(13);
  });
});

describe('the construction expanded back into the Bernstein form', () => {
  it('expands one level per press, then shows the construction lands on the same point', () => {
    expect(names(opened('bernstein'))).toEqual(['points', 'blend 1', 'blend 2', 'blend 3', 'same']);
  });

  it('writes the weights as the lecture notes’ table does', () => {
    expect(weightTex(3, 0)).toBe('(1-t)^{3}');
    expect(weightTex(3, 1)).toBe('3t(1-t)^{2}');
    expect(weightTex(3, 2)).toBe('3t^{2}(1-t)');
    expect(weightTex(3, 3)).toBe('t^{3}');
    expect(expansionTex(2, 1)).toBe('(1-t)^{2}\\,P_{1} + 2t(1-t)\\,P_{2} + t^{2}\\,P_{3}');
    expect(expansionTex(6)).toBe('\\sum_{j=0}^{6} W(6,j,t)\\,P_{0+j}');
  });

  it('gives each level’s weights and first point worked by hand, equal to the construction’s', () => {
    const m = derive(opened('bernstein', 2));
    // W(2, j, ½) = ¼, ½, ¼: P2,0 = ¼(0, 0) + ½(1, 2) + ¼(3, 2) = (1.25, 1.5).
    expect(m.weights[2]).toEqual([0.25, 0.5, 0.25]);
    expect(m.blends[2][0]).toEqual([1.25, 1.5]);
    // The braces are the recursion (1 − t)P1,0 + tP1,1 with level 1 written out.
    expect(formula(opened('bernstein', 2))).toContain(
      '\\begin{aligned}P_{2,0} &= (1-t)\\{(1-t)\\,P_{0} + t\\,P_{1}\\} + t\\{(1-t)\\,P_{1} + t\\,P_{2}\\}\\\\ &= (1-t)^{2}',
    );
    expect(formula(opened('bernstein', 2))).toContain(
      '&= 0.25\\cdot(0,\\ 0) + 0.5\\cdot(1,\\ 2) + 0.25\\cdot(3,\\ 2) = (1.25,\\ 1.5)',
    );
    // W(3, i, ½) = ⅛, ⅜, ⅜, ⅛: the slides' Example 4.18.
    expect(m.weights[3]).toEqual([0.125, 0.375, 0.375, 0.125]);
    expect(m.weights[3]).toEqual([0, 1, 2, 3].map((i) => bernstein(3, i, 0.5)));
    // The last level in three lines (five crowded the figure in presenter view, #19): the
    // recursion with level 2 written out in braces, the expansion and Σ, the numbers:
    // ⅛(0, 0) + ⅜(1, 2) + ⅜(3, 2) + ⅛(4, 0) = ((3 + 9 + 4)/8, (6 + 6)/8) = (2, 1.5).
    expect(caption(opened('bernstein', 3))).toBe('Level 3 expanded: P₃,₀ = Σ W(3, i, t) Pᵢ');
    expect(formula(opened('bernstein', 3))).toBe(
      '\\begin{aligned}' +
        'P_{3,0} &= (1-t)\\{(1-t)^{2}\\,P_{0} + 2t(1-t)\\,P_{1} + t^{2}\\,P_{2}\\} + t\\{(1-t)^{2}\\,P_{1} + 2t(1-t)\\,P_{2} + t^{2}\\,P_{3}\\}\\\\ ' +
        '&= (1-t)^{3}\\,P_{0} + 3t(1-t)^{2}\\,P_{1} + 3t^{2}(1-t)\\,P_{2} + t^{3}\\,P_{3} = \\textstyle\\sum_{i=0}^{3} W(3,i,t)\\,P_i\\\\ ' +
        '&= 0.125\\cdot(0,\\ 0) + 0.375\\cdot(1,\\ 2) + 0.375\\cdot(3,\\ 2) + 0.125\\cdot(4,\\ 0) = (2,\\ 1.5)' +
        '\\end{aligned}',
    );
    expect(formula(opened('bernstein', 4))).toBe(
      'P_{3,0} = (2,\\ 1.5)\\ \\text{(construction)},\\quad \\sum_{i=0}^{3} W(3,i,t)\\,P_i = (2,\\ 1.5),\\quad \\text{apart by } 0',
    );
    expect(m.blends.map((level, r) => (r === 0 ? null : level))).toEqual([null, ...BY_HAND]);
  });

  it('blends every level from the control points to the construction’s own points', () =>
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: -9, max: 9 }), fc.integer({ min: -9, max: 9 })), {
          minLength: 2,
          maxLength: 9,
        }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (p, t) => {
          const m = derive({ ...opened('bernstein'), p, t });
          const levels = deCasteljau(p, t);
          m.blends.forEach((level, r) =>
            level.forEach((q, i) => q.forEach((v, d) => expect(v).toBeCloseTo(levels[r][i][d], 9))),
          );
          expect(m.blendGap).toBeLessThan(1e-9);
        },
      ),
    ));
});

describe('the walks in the link and in the scenes', () => {
  it('keeps the link key split: 0 and 1 as before, code and bernstein for the new walks', () => {
    const mode = (raw: string) => decodeState(schema, `split=${raw}`).state.mode;
    expect(['0', '1', 'false', 'true', 'code', 'bernstein'].map(mode)).toEqual([
      'construction',
      'halves',
      'construction',
      'halves',
      'pseudocode',
      'bernstein',
    ]);
    expect(decodeState(schema, 'split=maybe').issues).toHaveLength(1);
    expect(encodeState(schema, opened('pseudocode'))).toMatch(/&split=code$/);
    expect(encodeState(schema, { ...opened('cubic'), mode: 'halves' })).toMatch(/&split=1$/);
  });

  it('finds each walk its scene, and opens the new scenes on the arch at t = 0.5', () => {
    expect(sceneOf(opened('pseudocode'))).toBe('pseudocode');
    expect(sceneOf(opened('bernstein'))).toBe('bernstein');
    expect(sceneOf(opened('loop'))).toBe('cubic');
    expect(sceneOf({ ...opened('cubic'), mode: 'halves' })).toBe('cubic');
    for (const id of ['pseudocode', 'bernstein']) {
      expect(opened(id).p).toEqual(opened('cubic').p);
      expect(opened(id).t).toBe(0.5);
    }
  });

  it('keeps a walk shown to its end at its end when a point is added', () => {
    const end = opened('pseudocode', 9);
    const added = controlPoints.add(end, [5, 1])!;
    // Five points: 4 + 3 + 2 + 1 = 10 points of line 4, 14 presses: the last is 13.
    expect(added.step).toBe(13);
    expect(controlPoints.add(opened('pseudocode', 4), [5, 1])!.step).toBe(4);
  });
});
