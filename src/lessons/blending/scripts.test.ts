import { parameterRow } from '../../kit/notes';
import { setNotation } from '../../render/notation';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { drawState } from '../../kit/scriptChecks';
import { filled } from '../../kit/format';
import lesson from './lesson';
import type { BlendingModel } from './model';
import { NOTES_KEY } from './notesKey';
import { bsplineScript, hermiteScript, lagrangeScript } from './compareScripts';
import { symmetryScript } from './symmetryScript';
import { type BlendingState, schema } from './state';
import { centroidFormula, matrixFormTex, pointFormula, rowFormula } from './tex';

const cubic: BlendingState = defaultsOf(schema);
const derive = (s: BlendingState) => lesson.derive(s) as BlendingModel;
const opened = (id: string) => {
  const scene = lesson.scenes!.find((s) => s.id === id)!;
  return { ...(scene.apply(cubic) as BlendingState), step: 0 };
};
const names = (script: typeof hermiteScript, s: BlendingState) =>
  Array.from({ length: script.lastStep(s) + 1 }, (_, k) => script.shown(s, k).name);
const walk = (s: BlendingState) =>
  Array.from({ length: lesson.steps!.count(s) + 1 }, (_, step) => {
    const at = { ...s, step };
    return [lesson.steps!.describe(at, step), lesson.steps!.formula!(derive(at), at)];
  });

describe('the Compare scenes start where their own idea starts (issue #20)', () => {
  it('replay no Bernstein weight: the Bézier picture is step 0, then the other basis', () => {
    expect(names(hermiteScript, opened('hermite'))).toEqual([
      'bezier',
      'data',
      'tangents',
      'basis',
      'basis',
      'basis',
      'basis',
      'atMu',
    ]);
    expect(names(bsplineScript, opened('bspline'))).toEqual([
      'bezier',
      'basis',
      'basis',
      'basis',
      'basis',
      'ends',
      'spline',
      'atMu',
    ]);
    expect(names(lagrangeScript, opened('lagrange'))).toEqual([
      'bezier',
      ...Array(7).fill('basis'),
      'spline',
      'hull',
      'atMu',
    ]);
    // The recorded links' last steps (7, 7, 10) are still each scene's last step.
    expect(['hermite', 'bspline', 'lagrange'].map((id) => lesson.steps!.count(opened(id)))).toEqual(
      [7, 7, 10],
    );
  });

  it('every step of every scene, and of the symmetry, draws something the step before did not', () => {
    const states = [
      ...lesson.scenes!.map((scene) => ({ id: scene.id, s: opened(scene.id) })),
      { id: 'mirror', s: { ...cubic, mu: 0.3, comparison: 'mirror' as const } },
    ];
    for (const { id, s } of states) {
      let before = drawState(lesson, s).svg;
      for (let k = 1; k <= lesson.steps!.count(s); k++) {
        const now = drawState(lesson, { ...s, step: k }).svg;
        expect(now, `${id} step ${k}`).not.toBe(before);
        before = now;
      }
    }
  });

  it('Hermite: the end gradients of the lecture cubic, 3(P₁ − P₀) = (3, 6) and 3(P₃ − P₂) = (3, −6)', () => {
    const [, , tangents] = walk(opened('hermite'));
    expect(tangents[1]).toBe(
      'D_0 = 3(P_1 - P_0) = (3.00,\\ 6.00),\\quad D_3 = 3(P_3 - P_2) = (3.00,\\ -6.00)',
    );
  });

  it('B-spline: the curve starts at (P₀ + 4P₁ + P₂)/6 = (7/6, 10/6), not at P₀', () => {
    const steps = walk(opened('bspline'));
    expect(steps[1][0]).toBe(
      'B₀: never negative, and at most 0.167, so it never takes a point whole',
    );
    expect(steps[2][0]).toBe(
      'B₁: never negative, and at most 0.667, so it never takes a point whole',
    );
    expect(steps[5][1]).toMatch(/^\\tfrac\{1\}\{6\}\(P_0 \+ 4P_1 \+ P_2\) = \(1\.167,\\ 1\.667\)/);
  });
});

describe('the symmetry μ → 1 − μ, stepped with the numbers of μ (the lecture slides: symmetric under u → 1 − u)', () => {
  const mirror = { ...cubic, mu: 0.3, comparison: 'mirror' as const };

  it('walks the functions, the mirrored cursor, each pair, and the reversed curve', () => {
    expect(names(symmetryScript, mirror)).toEqual([
      'functions',
      'mirror',
      'pair',
      'pair',
      'reversed',
    ]);
    const steps = walk(mirror);
    expect(steps[1]).toEqual([
      'Mirror μ in ½: a second cursor at 1 − μ = 0.7',
      '1 - \\mu = 1 - 0.3 = 0.7',
    ]);
    // W(3, 0, 0.3) = 0.7³ = 0.343 = W(3, 3, 0.7); W(3, 1, 0.3) = 3 · 0.3 · 0.7² = 0.441 = W(3, 2, 0.7).
    expect(steps[2]).toEqual([
      "W(3, 0, μ) = W(3, 3, 1 − μ) = 0.343: swapping μ and 1 − μ swaps P₀'s weight and P₃'s",
      'W(3,0,0.3) = 1\\cdot 0.3^{0}\\,0.7^{3} = 1\\cdot 0.7^{3}\\,0.3^{0} = W(3,3,0.7) = 0.3430',
    ]);
    expect(steps[3][1]).toBe(
      'W(3,1,0.3) = 3\\cdot 0.3^{1}\\,0.7^{2} = 3\\cdot 0.7^{2}\\,0.3^{1} = W(3,2,0.7) = 0.4410',
    );
    // P(0.7) = 0.027 P0 + 0.189 P1 + 0.441 P2 + 0.343 P3 = (0.189 + 1.323 + 1.372, 0.378 + 0.882) = (2.884, 1.26).
    expect(steps[4][1]).toBe('P(0.7) = \\sum_{i=0}^{3} W(3,i,0.3)\\,P_{3-i} = (2.884,\\ 1.260)');
  });

  it('N = 2: the middle function is its own mirror image', () => {
    const quadratic = {
      ...mirror,
      p: [
        [0, 0],
        [2, 3],
        [4, 0],
      ],
    };
    // W(2, 1, 0.3) = 2 · 0.3 · 0.7 = 0.42.
    expect(walk(quadratic)[3][0]).toBe(
      'W(2, 1, μ) = W(2, 1, 1 − μ) = 0.42: the middle function is its own mirror image',
    );
  });
});

describe('one letter for the parameter: μ, as the lecture notes write it (issue #20)', () => {
  it('the matrix form and its row at μ are written in μ, not u', () => {
    const m = derive(cubic);
    const matrix = matrixFormTex(m.matrix);
    expect(matrix).toMatch(/^\\begin\{aligned\}P\(\\mu\) &= U\\,M\\,\\mathbf\{P\}/);
    expect(matrix).toMatch(
      /\\begin\{pmatrix\}1 & \\mu & \\mu\^\{2\} & \\mu\^\{3\}\\end\{pmatrix\}/,
    );
    expect(matrix).not.toMatch(/\bu\b|x_\{/);
    // Past degree 6, M by its rule: M(j, i) = (−1)^(j−i) C(n, j) C(j, i), checked on the maths' matrix.
    const eight = derive({ ...cubic, p: Array.from({ length: 9 }, (_, i) => [i, (i * i) % 5]) });
    expect(matrixFormTex(eight.matrix)).toContain('M_{ji} &= (-1)^{j-i}\\binom{8}{j}\\binom{j}{i}');
    const choose = (n: number, k: number): number =>
      k === 0 || k === n ? 1 : choose(n - 1, k - 1) + choose(n - 1, k);
    eight.matrix.forEach((row, j) =>
      row.forEach((entry, i) =>
        expect(entry).toBe(j >= i ? (-1) ** (j - i) * choose(8, j) * choose(j, i) : 0),
      ),
    );
    expect(filled(rowFormula(0.5, m.weights))).toMatch(/^\\text\{at \} \\mu = 0\.5:/);
  });

  it('the panel’s formulas are one line its box may break after a + or a comma (a laptop’s panel is 404 px)', () => {
    // The cubic (0, 0), (1, 2), (3, 2), (4, 0) at μ = ½: weights 1/8, 3/8, 3/8, 1/8, point (2, 1.5).
    const m = derive(cubic);
    expect(filled(rowFormula(0.5, m.weights))).toBe(
      '\\text{at } \\mu = 0.5:\\quad U M = (0.1250,\\allowbreak\\ 0.3750,\\allowbreak\\ 0.3750,\\allowbreak\\ 0.1250)',
    );
    expect(filled(pointFormula(0.5, m.weights, cubic.p, m.point, true))).toBe(
      'P(0.5) = 0.1250\\,(0.00,\\ 0.00) + 0.3750\\,(1.00,\\ 2.00) + 0.3750\\,(3.00,\\ 2.00) + 0.1250\\,(4.00,\\ 0.00) = (2.0000,\\ 1.5000)',
    );
    expect(filled(centroidFormula(3, m.centre))).toBe(
      'P(0.5) = \\tfrac{1}{8}P_{0} + \\tfrac{3}{8}P_{1} + \\tfrac{3}{8}P_{2} + \\tfrac{1}{8}P_{3} = (2.0000,\\ 1.5000)',
    );
  });

  it('the key says how the slides (u) and the practical (t) write μ: the kit’s row, in the reader’s letter', () => {
    // The lesson's own rows no longer name the parameter: the kit's row does, for every lesson.
    expect(NOTES_KEY.some(([here]) => here === 'μ')).toBe(false);
    setNotation('mu', 't');
    expect(parameterRow()).toEqual([
      't, the curve’s parameter',
      'μ in the lecture notes, u in the slides, t in the practical and the continuation notes; the letter is chosen at the top of the page',
    ]);
    setNotation(null, 't');
    expect(parameterRow()).toBeNull();
  });
});
