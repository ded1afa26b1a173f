import { describe, expect, it } from 'vitest';
import type { Script } from '../../kit/script';
import { drawState, sceneStates } from '../../kit/scriptChecks';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import lesson from './lesson';
import type { BezierSplinesModel } from './model';
import { type Reveal, scripts } from './script';
import { type BezierSplinesState, type Part, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: BezierSplinesState) => lesson.derive(s) as BezierSplinesModel;
const opened = (part: Part) =>
  lesson.scenes!.find((scene) => scene.id === part)!.apply(defaultsOf(schema));

/** Each press of a part as the lecturer reads it: the step's name, caption and formula. */
function walk(part: Part) {
  const script: Script<BezierSplinesState, BezierSplinesModel, Reveal> = scripts[part];
  const base = opened(part);
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

describe('the scripts of the six parts', () => {
  // The kit's checkScript with the registry's caption rule (tests/lessons.test.ts): these
  // captions count equations ("4 equations") and write |pᵢ₊₁ − pᵢ|^½.
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () => {
    for (const scene of sceneStates(lesson)) {
      const { id, count } = scene;
      const at = (k: number) => scene.at(k) as unknown as BezierSplinesState;
      expect(count, id).toBeGreaterThan(1);
      expect(count, id).toBeLessThanOrEqual(20);
      for (const projector of [false, true])
        expect(drawState(lesson, at(0), { projector }).elements, id).toBeLessThan(
          drawState(lesson, at(count), { projector }).elements,
        );
      for (let k = 0; k <= count; k++) {
        const caption = lesson.steps!.describe(at(k), k);
        expect(caption.length, `${id} ${k}`).toBeGreaterThan(10);
        expect(caption, `${id} ${k}`).not.toMatch(/\\[a-z]|_\{|\^\{|[Ee]quation \d|the notes/);
        expect(drawState(lesson, at(k)).svg, `${id} ${k}`).not.toMatch(/NaN|Infinity/);
        const formula = lesson.steps!.formula!(lesson.derive(at(k)), at(k)) ?? '';
        expect(formula, `${id} ${k}`).not.toMatch(/NaN|Infinity|undefined|\\val|\+ -|e[+-]\d/);
      }
    }
  });

  it('why pieces: the points, one curve, one point moved, pieces, the point moved again', () => {
    expect(walk('why')).toEqual([
      { name: 'points', caption: 'The points p₀ … p₅ to join by one smooth curve', formula: null },
      {
        name: 'single',
        caption:
          'One Bézier curve with them as control points: degree 5, and it misses the inner points',
        formula: 'P(t) = \\sum_{i=0}^{5} B^{5}_i(t)\\,p_i',
      },
      {
        name: 'moved',
        caption: 'Move p₃ up by 1: every part of that one curve moves — no local control',
        formula:
          '\\Delta P(t) = B^{5}_{3}(t)\\cdot(0,\\,1) \\neq 0 \\text{ for every } t \\in (0,1)',
      },
      {
        name: 'pieces',
        caption: 'Pieces instead: one cubic between each two neighbours, joined smoothly (C²)',
        formula: 'P_i(t) = \\sum_{j=0}^{3} B^3_j(t)\\,c_{3i+j},\\quad i = 0,\\dots,n-1',
      },
      {
        name: 'local',
        caption: 'Move p₃ again: pieces far from it barely move; the question is how pieces join',
        formula: '\\max_j |\\Delta c_j| \\text{ on the first piece} = 0.077',
      },
    ]);
  });

  it('the quadratic spline: b₀, one mirror image bᵢ per further piece, then the swing', () => {
    const steps = walk('quadratic');
    expect(steps.map((s) => s.name)).toEqual([
      'points',
      'firstPiece',
      'mirror',
      'mirror',
      'mirror',
      'mirror',
      'swing',
    ]);
    expect(steps[0].caption).toBe(
      'The points p₀ … p₅: n = 5 quadratic pieces [pᵢ, bᵢ, pᵢ₊₁] to find',
    );
    expect(steps[1]).toMatchObject({
      caption: 'Choose b₀ (the midpoint of p₀p₁ to start; drag it): the first piece',
      formula: 'b_0 = (0.50,\\ 1.00)',
    });
    // b₃ = 2p₃ − b₂ = 2·(4, 0.5) − (4.5, 2) = (3.5, −1).
    expect(steps[4]).toMatchObject({
      caption: 'C¹ at p₃: b₃ = 2p₃ − b₂, the mirror image of b₂',
      formula: 'b_{3} = 2p_{3} - b_{2} = 2\\cdot(4.00,\\ 0.50) - (4.50,\\ 2.00) = (3.50,\\ -1.00)',
    });
    expect(steps[6].caption).toBe(
      'Move b₀ by ±0.5: every bᵢ moves by ∓0.5 in turn — the spline swings and never settles',
    );
    // One point more, one mirror step more.
    const more = { ...opened('quadratic'), points: [...opened('quadratic').points, [8, 1]] };
    expect(scripts.quadratic.lastStep(more)).toBe(7);
  });

  it('the C² system: one kind of equation per press, in the practical’s letters', () => {
    const steps = walk('system');
    expect(steps.map((s) => s.name)).toEqual([
      'points',
      'unknowns',
      'interpolation',
      'c1Equations',
      'c2Equations',
      'naturalEnds',
      'matrix',
      'solution',
      'sameAsNatural',
    ]);
    expect(steps[0].caption).toBe('The points A, D, G, J to interpolate');
    expect(steps[3]).toEqual({
      name: 'c1Equations',
      caption: 'C¹ at D and G: C − 2D + E = 0 and F − 2G + H = 0 (2 equations)',
      formula: '\\begin{aligned}C - 2D + E &= 0\\\\F - 2G + H &= 0\\end{aligned}',
    });
    expect(steps[5].formula).toBe(
      '\\begin{aligned}A - 2B + C &= 0\\\\H - 2I + J &= 0\\end{aligned}',
    );
    expect(steps[6].caption).toBe(
      'The whole 10 × 10 system, joint by joint: the point, C¹, C² (P″ = 0 at the ends); x and y share the matrix',
    );
    // The practical's ten equations in four rows, one per joint (ten matrix rows crowded the
    // figure in presenter view, #19): A, D, G, J are the points (0, 0), (1, 2.5), (4, 2.5),
    // (5, 0); C¹ at D and G; C² at D and G, and P″ = 0 at A and J.
    expect(steps[6].formula).toBe(
      '\\begin{aligned}' +
        'A &= (0.00,\\ 0.00) & & & A - 2B + C &= 0\\\\' +
        'D &= (1.00,\\ 2.50) & C - 2D + E &= 0 & B - 2C + 2E - F &= 0\\\\' +
        'G &= (4.00,\\ 2.50) & F - 2G + H &= 0 & E - 2F + 2H - I &= 0\\\\' +
        'J &= (5.00,\\ 0.00) & & & H - 2I + J &= 0' +
        '\\end{aligned}',
    );
    // Three points (0, 0), (1, 2.5), (4, 2.5): 7 control points c₀ … c₆, one inner joint c₃.
    const three = {
      ...opened('system'),
      points: [
        [0, 0],
        [1, 2.5],
        [4, 2.5],
      ],
      step: 6,
    };
    expect(lesson.steps!.formula!(derive(three), three)).toBe(
      '\\begin{aligned}' +
        'c_{0} &= (0.00,\\ 0.00) & & & c_{0} - 2c_{1} + c_{2} &= 0\\\\' +
        'c_{3} &= (1.00,\\ 2.50) & c_{2} - 2c_{3} + c_{4} &= 0 & c_{1} - 2c_{2} + 2c_{4} - c_{5} &= 0\\\\' +
        'c_{6} &= (4.00,\\ 2.50) & & & c_{4} - 2c_{5} + c_{6} &= 0' +
        '\\end{aligned}',
    );
    // B = A + D₀/3 of the natural spline through (0, 0), (1, 2.5), (4, 2.5), (5, 0).
    expect(steps[7].formula).toMatch(/^\\begin\{aligned\}&B = \(0\.11,\\ 1\.00\),\\quad C = /);
    expect(steps[8].formula).toMatch(/^\\max_j \|c_j - c_j\^\{\\text\{natural\}\}\| = /);
  });

  it('the grid: one column per press, and no formula (the grid needs the height)', () => {
    expect(walk('grid')).toEqual([
      {
        name: 'points',
        caption: 'The practical’s three datasets: infinity, spiral and a half circle',
        formula: null,
      },
      {
        name: 'c0',
        caption: 'C⁰: straight pieces through the points, a corner at every point',
        formula: null,
      },
      {
        name: 'c1',
        caption: 'C¹: quadratic pieces, b₀ the midpoint of p₀p₁ — smooth, but swinging',
        formula: null,
      },
      {
        name: 'c2',
        caption: 'C²: cubic pieces from the linear system — smooth and calm',
        formula: null,
      },
    ]);
  });

  it('the inspector: joints, pieces, verdicts, tangents, curvature, the comb', () => {
    const steps = walk('inspector');
    expect(steps.map((s) => s.name)).toEqual([
      'joints',
      'pieces',
      'verdicts',
      'tangents',
      'curvature',
      'comb',
    ]);
    // C^2 in maths, not in \text{} (where ^ is an error KaTeX draws in red).
    expect(steps[2].formula).toBe('\\text{joint 1: }C^2,\\quad \\text{joint 2: }G^1');
    expect(steps[3]).toMatchObject({
      caption: 'At each joint, the two tangent vectors: their angle decides G¹, their lengths C¹',
      formula:
        "P_0'(1) = (3.00,\\ -1.50),\\ P_1'(0) = (3.00,\\ -1.50),\\ \\angle = 0.0^\\circ,\\ |P_1'|/|P_0'| = 1.000",
    });
    expect(steps[4].formula).toBe(
      "P_0''(1) = (0.00,\\ -6.00),\\ P_1''(0) = (0.00,\\ -6.00),\\ \\kappa = -0.477 \\mid -0.477",
    );
    expect(steps[5]).toMatchObject({
      caption: 'The curvature comb: where its teeth jump, the curvature jumps (not G²)',
      formula: null,
    });
  });

  it('Catmull-Rom: hand-set tangents, then uniform, one-sided, centripetal, chordal, all', () => {
    const steps = walk('catmull');
    expect(steps.map((s) => s.name)).toEqual([
      'points',
      'hermite',
      'uniform',
      'oneSided',
      'centripetal',
      'chordal',
      'all',
    ]);
    expect(steps[0].caption).toBe('The points p₀ … p₃');
    expect(steps[2].formula).toBe('T_1 = \\tfrac{1}{2}(p_2 - p_0) = (1.50,\\ 0.60)');
    // The hairpin's gaps: |p₁ − p₀| = √10, |p₂ − p₁| = 0.2, |p₃ − p₂| = √10.69.
    expect(steps[4].formula).toBe('\\Delta_i = |p_{i+1} - p_i|^{1/2} = 1.78,\\ 0.45,\\ 1.81');
    expect(steps[5].formula).toBe('\\Delta_i = |p_{i+1} - p_i|^{1} = 3.16,\\ 0.20,\\ 3.27');
    expect(steps[6].formula).toBe(
      '\\text{uniform: 1 crossing},\\quad \\text{centripetal: 0 crossings},\\quad \\text{chordal: 0 crossings}',
    );
  });

  it('shows each scene’s own figures: the grid alone in its scene, the main figure elsewhere', () => {
    const shown = (part: Part) => lesson.figuresShown!({ ...opened(part) });
    expect(shown('grid')).toHaveLength(9);
    expect(shown('grid')).toContain('spi-c1');
    for (const part of ['why', 'quadratic', 'system', 'inspector', 'catmull'] as const)
      expect(shown(part)).toEqual(['main']);
  });

  it('solves no spline again for a step: the geometry is kept while the points are the same', () => {
    const s = opened('system');
    expect(derive({ ...s, step: 3 }).system).toBe(derive({ ...s, step: 4 }).system);
    expect(derive({ ...s, step: 3 }).shown.is('c1Equations')).toBe(true);
  });

  it('keeps every link key, in the same order, so every link opens the same picture', () => {
    const link = encodeState(schema, opened('inspector'));
    expect(link.split('&').map((field) => field.split('=')[0])).toEqual([
      'part',
      'step',
      'p',
      'b',
      'q',
      'inf',
      'spi',
      'semi',
      'tg',
    ]);
    const decoded = decodeState(
      schema,
      'part=catmull&step=1&p=0,0;3,1;3,1.2;0,2.5&tg=1,1;2,2;3,3;4,4',
    );
    expect(decoded.issues).toEqual([]);
    expect(decoded.state.points[2]).toEqual([3, 1.2]);
    expect(decoded.state.tangents[3]).toEqual([4, 4]);
  });
});
