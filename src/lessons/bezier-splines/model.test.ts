import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import lesson from './lesson';
import type { BezierSplinesModel } from './model';
import { type BezierSplinesState, PARTS, schema } from './state';

/** The lesson as the shell hosts it: its scenes, steps and figures, the model derived once per state. */
const derive = (s: BezierSplinesState) => lesson.derive(s) as BezierSplinesModel;
const scenes = lesson.scenes!;
const steps = lesson.steps!;
const stepCount = steps.count;
const figure = (id: string) => lesson.figures.find((f) => f.id === id)!;
const mainFigure = figure('main');

const defaults = defaultsOf(schema);
const at = (part: (typeof PARTS)[number]) => scenes.find((s) => s.id === part)!.apply(defaults);

describe('the C¹ quadratic spline', () => {
  it('follows b0 = (0.5, 1) through the lecture points by bᵢ = 2pᵢ − bᵢ₋₁', () => {
    // b1 = 2(1, 2) − (0.5, 1); b2 = 2(3, 2.5) − b1; b3 = 2(4, 0.5) − b2; b4 = 2(6, 1) − b3.
    expect(derive(at('quadratic')).quadraticControls).toEqual([
      [0.5, 1],
      [1.5, 3],
      [4.5, 2],
      [3.5, -1],
      [8.5, 3],
    ]);
  });
  it('swings by ∓δ at every bᵢ when b0 moves by δ: the change never fades', () => {
    const m = derive(at('quadratic'));
    m.swing[0].forEach((piece, i) => {
      // The quadratic's b is raised to degree 3: c1 = p + 2/3(b − p), so c1 moves by 2/3 of b's move.
      const moved = piece[1][1] - m.quadratic[i][1][1];
      expect(Math.abs(moved)).toBeCloseTo((2 / 3) * 0.5, 12);
      expect(Math.sign(moved)).toBe(i % 2 === 0 ? 1 : -1);
    });
  });
});

describe('the C² system', () => {
  it('names the practical’s control points A … J for four points, and solves to the natural spline', () => {
    const m = derive(at('system'));
    expect(m.names.join('')).toBe('ABCDEFGHIJ');
    expect(m.system.residual).toBeLessThan(1e-12);
    expect(m.difference).toBeLessThan(1e-12);
  });
});

describe('the hand-built spline', () => {
  it('is C² at joint 1 and G¹ with length ratio ½ at joint 2', () => {
    // Joint 2: c6 − c5 = (1, 1), c7 − c6 = (0.5, 0.5): same direction, half the length.
    const [first, second] = derive(at('inspector')).joints;
    expect(first.continuity).toBe('C2');
    expect(second.continuity).toBe('G1');
    expect(second.lengthRatio).toBeCloseTo(0.5, 12);
  });
  it('moves a joint with its two neighbours', () => {
    const s = at('inspector');
    const next = mainFigure.moveHandle!(s, 'q3', [3, 3], derive(s));
    expect(next.handBuilt.slice(2, 5)).toEqual([
      [2, 3.5],
      [3, 3],
      [4, 2.5],
    ]);
    expect(next.handBuilt[1]).toEqual(s.handBuilt[1]);
  });
});

describe('the grid', () => {
  it('moves a point of a row in all three of its cells, and no other row', () => {
    const s = at('grid');
    const cell = figure('spi-c1');
    const next = cell.moveHandle!(s, 'p2', [9, 9], derive(s));
    const m = derive(next);
    expect(m.grid.spiral.c0[1][3]).toEqual([9, 9]);
    expect(m.grid.spiral.c2[2][0]).toEqual([9, 9]);
    expect(m.grid.spiral.c1[1][3]).toEqual([9, 9]);
    expect(next.infinity).toBe(s.infinity);
  });
});

describe('the script', () => {
  it('opens with the defaults and every scene at step 0', () => {
    expect(scenes[0].apply(defaults)).toEqual(defaults);
    expect(scenes.map((s) => s.id)).toEqual(PARTS);
    for (const scene of scenes) expect(scene.apply(defaults).step).toBe(0);
  });
  it('has a caption for every step of every scene, and formulas with finite numbers', () => {
    for (const scene of scenes) {
      const s = scene.apply(defaults);
      for (let k = 0; k <= stepCount(s); k++) {
        const state = { ...s, step: k };
        expect(steps.describe(state, k), `${scene.id} ${k}`).toMatch(/^\S.{10,}$/);
        expect(steps.formula!(derive(state), state) ?? '').not.toMatch(/NaN|undefined|Infinity/);
      }
    }
  });
});

describe('a sharp corner (control points on the joint)', () => {
  // The link: the inspector's "Sharp corner at joint 1", whose velocities are both zero.
  const q = [
    [0, 0],
    [1, 2],
    [3, 2],
    [3, 2],
    [3, 2],
    [5, 0],
    [6, 1],
    [6.5, 1.5],
    [8, 3],
    [9, 2],
  ];
  const corner = (step: number) => ({ ...at('inspector'), handBuilt: q, step });
  const drawnTexts = (step: number) => {
    const state = corner(step);
    const model = derive(state);
    const view = new Viewport(900, 600);
    view.resize(900, 600);
    view.fit(mainFigure.bounds(model), 18, true);
    const svg = new SvgContext();
    mainFigure.draw(new Painter(svg, view, makeTheme(false, false)), model, {
      hover: null,
      thumbnail: false,
    });
    return { texts: svg.texts.join(' | '), formula: steps.formula!(model, state) ?? '' };
  };

  it('says the angle, the ratio and κ are undefined there, and shows no NaN', () => {
    const velocities = drawnTexts(3);
    // Joint 1 is the corner; joint 2 (a G¹ joint) keeps its angle and ratio.
    expect(velocities.texts).toContain('joint 1: C⁰ · P′ = 0: no angle, no ratio |');
    expect(velocities.texts).not.toMatch(/NaN/);
    expect(velocities.formula).toMatch(/\\text\{undefined\}/);
    expect(velocities.formula).not.toMatch(/NaN|circ/);
    const curvature = drawnTexts(4);
    expect(curvature.texts).toContain('κ undefined (P′ = 0)');
    expect(curvature.texts).not.toMatch(/NaN/);
    expect(curvature.formula).toMatch(/\\kappa = \\text\{undefined\} \\mid \\text\{undefined\}/);
  });
});

describe('the uniform Catmull-Rom loop at the hairpin', () => {
  it('is found between the curve’s two passes through its crossing', () => {
    // HAIRPIN (0, 0), (3, 1), (3, 1.2), (0, 2.5): T₁ = (p₂ − p₀)/2 = (1.5, 0.6) and
    // T₂ = (p₃ − p₁)/2 = (−1.5, 0.75), so the piece p₁ → p₂ has control points
    // (3, 1), (3.5, 1.2), (3.5, 0.95), (3, 1.2): x(t) = 3 + 1.5t(1 − t), its tip
    // x(½) = 3.375. It crosses itself at t and 1 − t with y(t) = y(1 − t):
    // t = 0.30133 (bisection by hand), at (3.31579, 1.08421); on [t, 1 − t]
    // y runs from 1.07917 to 1.08537.
    const m = derive(at('catmull'));
    const [uniform, centripetal, chordal] = m.alphas;
    expect(uniform.crossings).toHaveLength(1);
    expect(uniform.crossings[0][0]).toBeCloseTo(3.31579, 4);
    expect(uniform.crossings[0][1]).toBeCloseTo(1.08421, 4);
    const loop = uniform.loop!;
    expect(loop.maxX).toBeCloseTo(3.375, 9);
    expect(loop.minY).toBeLessThanOrEqual(1.07918);
    expect(loop.maxY).toBeGreaterThanOrEqual(1.08536);
    // With the legs within 0.02 of the points’ diagonal (0.02 × 3.905) of the crossing, no more.
    expect(loop.minX).toBeLessThan(3.31579);
    expect(loop.minX).toBeGreaterThan(3.31579 - 0.0782);
    expect(loop.maxY - loop.minY).toBeLessThan(0.1);
    // The centripetal and chordal curves never cross: nothing to magnify.
    expect([centripetal.loop, chordal.loop]).toEqual([null, null]);
  });
});
