import { describe, expect, it } from 'vitest';
import { drawState } from '../../kit/scriptChecks';
import { defaultsOf } from '../../app/urlState';
import lesson from './lesson';
import type { BezierSplinesModel } from './model';
import { scripts } from './script';
import { type BezierSplinesState, LECTURE_POINTS, MAX_POINTS, schema } from './state';
import { DATASET_FILES, datasetText } from './datasetFile';

type State = BezierSplinesState;
const derive = (s: State) => lesson.derive(s) as BezierSplinesModel;
const opened = (part: 'worked' | 'degree') =>
  lesson.scenes!.find((scene) => scene.id === part)!.apply(defaultsOf(schema));
const main = lesson.figures.find((f) => f.id === 'main')!;

/** Each press as the lecturer reads it: the step's name, caption and formula. */
function walk(base: State) {
  const script = scripts[base.part];
  return Array.from({ length: script.lastStep(base) + 1 }, (_, step) => {
    const state = { ...base, step };
    const model = derive(state);
    return {
      name: model.shown.name,
      caption: lesson.steps!.describe(state, step),
      formula: lesson.steps!.formula!(model, state),
    };
  });
}

describe('the worked example: computeSplineC1 and computeSplineC2 by hand', () => {
  const steps = walk(opened('worked'));

  it('is two scenes appended after the first six, the links of the six unchanged', () => {
    expect(lesson.scenes!.map((s) => s.id).slice(-2)).toEqual(['worked', 'degree']);
  });

  it('steps through C¹, then C², one equation (or joint) a press', () => {
    expect(steps.map((s) => s.name)).toEqual([
      'points',
      'c1Count',
      'c1First',
      'c1Mirror',
      'c1Mirror',
      'c1Output',
      'c2Count',
      'c2Start',
      'c2Joint',
      'c2Joint',
      'c2End',
      'c2Back',
      'c2Output',
    ]);
  });

  it('shows the C¹ numbers worked by hand', () => {
    // n = 3: 2n + 1 = 7 control points; b₀ = ½((0, 0) + (1, 2.5)) = (0.5, 1.25);
    // b₁ = 2(1, 2.5) − (0.5, 1.25) = (1.5, 3.75); b₂ = 2(4, 2.5) − (1.5, 3.75) = (6.5, 1.25).
    expect(steps[1].formula).toBe(
      '2n + 1 = 2\\cdot 3 + 1 = 7:\\quad p_{0},\\ b_{0},\\ p_{1},\\ b_{1},\\ p_{2},\\ b_{2},\\ p_{3}',
    );
    expect(steps[2].formula).toBe(
      'b_0 = \\tfrac{1}{2}(p_0 + p_1) = \\tfrac{1}{2}\\big((0.00,\\ 0.00) + (1.00,\\ 2.50)\\big) = (0.50,\\ 1.25)',
    );
    expect(steps[3]).toMatchObject({
      caption: 'C¹ at p₁: b₁ = 2p₁ − b₀, the mirror image of b₀ through p₁',
      formula:
        '\\begin{aligned}b_{1} &= 2p_{1} - b_{0} = 2(1.00,\\ 2.50) - (0.50,\\ 1.25) = (1.50,\\ 3.75)\\end{aligned}',
    });
    expect(steps[4].formula).toMatch(
      /= 2\(4\.00,\\ 2\.50\) - \(1\.50,\\ 3\.75\) = \(6\.50,\\ 1\.25\)/,
    );
    // Three rows a line: rows 3 … 5, then row 6 alone.
    // Each row by its number and by its name in the figure (b₂, p₃).
    expect(steps[5].formula).toMatch(
      /5\\ \(b_\{2\}\)\\!:\\ \(6\.50,\\ 1\.25\)\\\\&6\\ \(p_\{3\}\)\\!:\\ \(5\.00,\\ 0\.00\)/,
    );
  });

  it('shows the C² walk worked by hand: each control point in terms of B, then B', () => {
    // 3n + 1 = 10 = 4 points + 2 C¹ + 2 C² + 2 natural ends.
    expect(steps[6].formula).toBe(
      '3n + 1 = 10 = \\underbrace{4}_{\\text{points}} + \\underbrace{2}_{\\text{C¹}} + \\underbrace{2}_{\\text{C²}} + \\underbrace{2}_{\\text{natural ends}}',
    );
    expect(steps[7]).toMatchObject({
      caption: 'Keep B unknown: the natural start A − 2B + C = 0 gives C = 2B − A',
      formula: 'C = 2B - A = 2B',
    });
    // E = 2D − C = (2, 5) − 2B; F = B − 2C + 2E = (4, 10) − 7B.
    expect(steps[8]).toMatchObject({
      caption: 'At D: C¹ gives E = 2D − C, C² gives F = B − 2C + 2E',
      formula:
        '\\begin{aligned}E &= 2D - C = (2.00,\\ 5.00) - 2B\\\\F &= B - 2C + 2E = (4.00,\\ 10.00) - 7B\\end{aligned}',
    });
    // H = 2G − F = (4, −5) + 7B; I = E − 2F + 2H = (2, −25) + 26B.
    expect(steps[9].formula).toBe(
      '\\begin{aligned}H &= 2G - F = (4.00,\\ -5.00) + 7B\\\\I &= E - 2F + 2H = (2.00,\\ -25.00) + 26B\\end{aligned}',
    );
    // H − 2I + J = (5, 45) − 45B = 0, B = (1/9, 1).
    expect(steps[10]).toMatchObject({
      caption: 'The natural end H − 2I + J = 0, the one equation left, fixes B',
      formula:
        'H - 2I + J = (5.00,\\ 45.00) - 45B = 0 \\;\\Rightarrow\\; B = \\tfrac{1}{45}(5.00,\\ 45.00) = (0.11,\\ 1.00)',
    });
    // C = (2/9, 2), E = (16/9, 3), F = (29/9, 3), H = (43/9, 2), I = (44/9, 1).
    expect(steps[11].formula).toBe(
      '\\begin{aligned}&C = (0.22,\\ 2.00),\\quad E = (1.78,\\ 3.00),\\quad F = (3.22,\\ 3.00)\\\\&H = (4.78,\\ 2.00),\\quad I = (4.89,\\ 1.00)\\end{aligned}',
    );
    // Ten control points, five to a line; the solver's agreement is said in the caption.
    // The practical's letters, as the figure labels the points: row 4 is E, row 9 is J.
    expect(steps[12].formula).toMatch(
      /4\\ \(\\text\{E\}\)\\!:\\ \(1\.78,\\ 3\.00\)\\\\&5\\ \(\\text\{F\}\)\\!:/,
    );
    expect(steps[12].formula).toMatch(
      /quad 9\\ \(\\text\{J\}\)\\!:\\ \(5\.00,\\ 0\.00\)\\end\{aligned\}$/,
    );
    expect(steps[12].caption).toMatch(
      /as the whole system solved at once \(they agree to 12 digits\)$/,
    );
  });

  it('gives the side panel the ten points two to a line (five ran 592 px in a laptop’s 404)', () => {
    const state = { ...opened('worked'), step: 12 };
    const narrow = scripts.worked.formula(state, derive(state), 12, true)!;
    const lines = narrow.replace(/^\\begin\{aligned\}|\\end\{aligned\}$/g, '').split('\\\\');
    expect(lines).toHaveLength(5);
    expect(lines[2]).toBe(
      '&4\\ (\\text{E})\\!:\\ (1.78,\\ 3.00),\\quad 5\\ (\\text{F})\\!:\\ (3.22,\\ 3.00)',
    );
    // The same ten rows as the projector's five a line.
    const rows = (tex: string) => tex.match(/\d\\ \(\\text\{[A-J]\}\)\\!:\\ \([^)]*\)/g);
    expect(rows(narrow)).toEqual(rows(steps[12].formula!));
    expect(rows(narrow)).toHaveLength(10);
  });

  it('draws the row numbers, then B, then every letter and the C² curve', () => {
    const at = (step: number) => drawState(lesson, { ...opened('worked'), step }).texts;
    expect(at(4)).not.toContain('6');
    // Rows 0 … 6 of computeSplineC1 beside their points.
    expect(at(5)).toEqual(expect.arrayContaining(['0', '1', '2', '3', '4', '5', '6']));
    expect(at(9)).not.toContain('B');
    expect(at(10)).toContain('B');
    expect(at(10)).not.toContain('E');
    expect(at(11)).toEqual(expect.arrayContaining(['B', 'C', 'E', 'F', 'H', 'I']));
    const curves = (step: number) => drawState(lesson, { ...opened('worked'), step }).elements;
    expect(curves(12)).toBeGreaterThan(curves(11));
  });

  it('names the given points p₀ … p₃, then A, D, G, J once the C² part starts', () => {
    const labels = (step: number) => {
      const state = { ...opened('worked'), step };
      return main.handles!(derive(state)).map((h) => h.label);
    };
    expect(labels(5)).toEqual(['p_{0}', 'p_{1}', 'p_{2}', 'p_{3}']);
    expect(labels(6)).toEqual(['A', 'D', 'G', 'J']);
  });

  it('stays within 20 presses for any number of points, and works for two', () => {
    const many = {
      ...opened('worked'),
      points: LECTURE_POINTS.concat(LECTURE_POINTS)
        .slice(0, MAX_POINTS)
        .map(([x, y], i) => [x + 8 * Math.floor(i / 6), y]),
    };
    // 11 pieces: 10 bᵢ in 3 presses, 10 joints in 3 presses: 1 + 1 + 1 + 3 + 1 + 1 + 1 + 3 + 1 + 1 + 1 = 15 states.
    expect(scripts.worked.lastStep(many)).toBe(14);
    const long = walk(many);
    expect(long[3].caption).toBe(
      'C¹ at p₁ … p₃: each bᵢ = 2pᵢ − bᵢ₋₁, the mirror image of the one before',
    );
    expect(long[11].caption).toBe(
      'At c₂₁ … c₃₀: C¹ and C² give the next two control points at each joint',
    );
    const two = {
      ...opened('worked'),
      points: [
        [0, 0],
        [3, 6],
      ],
    };
    // No bᵢ to mirror, no inner joint: c₂ = 2B − c₀, and the natural end
    // c₁ − 2c₂ + c₃ = B − 4B + 2c₀ + c₃ = (3, 6) − 3B = 0 gives B = (1, 2).
    const short = walk(two);
    expect(short.map((s) => s.name)).toEqual([
      'points',
      'c1Count',
      'c1First',
      'c1Output',
      'c2Count',
      'c2Start',
      'c2End',
      'c2Back',
      'c2Output',
    ]);
    expect(short[6].formula).toBe(
      'c_{1} - 2c_{2} + c_{3} = (3.00,\\ 6.00) - 3B = 0 \\;\\Rightarrow\\; B = \\tfrac{1}{3}(3.00,\\ 6.00) = (1.00,\\ 2.00)',
    );
  });
});

describe('degree d, continuity up to Cᵈ⁻¹', () => {
  const steps = walk(opened('degree'));

  it('counts what each degree leaves to choose, then shows why not Cᵈ', () => {
    expect(steps.map((s) => s.name)).toEqual([
      'points',
      'degree1',
      'degree2',
      'degree3',
      'general',
      'notCd',
    ]);
    // n = 3: d = 1: 4 − 4 − 0 = 0; d = 2: 7 − 4 − 2 = 1; d = 3: 10 − 4 − 4 = 2.
    expect(steps[1].caption).toBe(
      'Degree 1, order 2: 4 control points, all of them the points — C⁰, nothing left to choose',
    );
    expect(steps[2].formula).toBe(
      'd = 2:\\quad \\underbrace{7}_{dn+1} - \\underbrace{4}_{n+1} - \\underbrace{2}_{(d-1)(n-1)} = 1',
    );
    expect(steps[3].caption).toBe(
      'Degree 3, order 4: 10 control points; the points, C¹ and C² leave 2, the natural ends',
    );
    // The first C² piece continued: P₀(2) = (6, 2) (workedExample.test.ts), not G = (4, 2.5).
    expect(steps[5].formula).toBe(
      'P_1(t) = P_0(1 + t):\\quad P_1(1) = P_0(2) = (6.00,\\ 2.00) \\neq p_2 = (4.00,\\ 2.50)',
    );
  });

  it('draws each degree, all three named, then the continued piece', () => {
    const at = (step: number) => drawState(lesson, { ...opened('degree'), step }).texts;
    expect(at(3)).not.toContain('d = 1');
    expect(at(4)).toEqual(expect.arrayContaining(['d = 1', 'd = 2', 'd = 3']));
    expect(at(4).join(' ')).not.toMatch(/1 \+ t/);
    expect(at(5).join(' ')).toMatch(/P.*0.*\(1 \+ t\)/);
    // Its end is named: P₀(2), the point the formula says is not p₂.
    expect(at(5).join(' ')).toMatch(/P.*0.*\(2\)/);
  });
});

describe('the datasets as files', () => {
  it('writes x y a line, named after the practical’s datasets', () => {
    const s = defaultsOf(schema);
    expect(DATASET_FILES).toEqual({
      infinity: 'infinity.txt',
      spiral: 'spiral.txt',
      semicircle: 'semi.txt',
    });
    // The figure eight's first points: (3 cos 0, 1.5 sin 0) = (3, 0), (3 cos π/4, 1.5 sin π/2) = (2.12, 1.5).
    const text = datasetText(s.infinity);
    expect(text.split('\n').slice(0, 3)).toEqual(['3 0', '2.12 1.5', '0 0']);
    expect(text.endsWith('3 0\n')).toBe(true);
    expect(text.split('\n')).toHaveLength(s.infinity.length + 1);
    // The half circle ends at (3 cos 0, 3 sin 0) = (3, 0); the spiral starts at r = 0.4.
    expect(datasetText(s.semicircle).split('\n')[0]).toBe('-3 0');
    expect(datasetText(s.spiral).split('\n')[0]).toBe('0.4 0');
  });
});
