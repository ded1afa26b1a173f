import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { checkScript } from '../../kit/scriptChecks';
import lesson from './lesson';
import type { CurvatureModel } from './model';
import { gradientHandles, planePoints, topViewPoints } from './points';
import { SCENES, sceneOf } from './scenes';
import { PART_SCRIPTS } from './scripts';
import { type CurvatureState, schema } from './state';

const defaults = defaultsOf(schema) as CurvatureState;
/** The figure of the curve as the shell hosts it: handles from the point lists. */
const curveFigure = lesson.figures[0];
/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: CurvatureState) => lesson.derive(s) as CurvatureModel;
const scene = (id: string) => SCENES.find((s) => s.id === id)!.setup(defaults);
const formula = (s: CurvatureState) => lesson.steps!.formula!(derive(s), s);
/** The names of a part's steps, in the order the clicker walks them. */
const names = (s: CurvatureState) =>
  Array.from(
    { length: lesson.steps!.count(s) + 1 },
    (_, k) => derive({ ...s, step: k }).shown.name,
  );

describe('the scripts of the curvature lesson', () => {
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () =>
    checkScript(lesson));

  it('names each step after what it reveals, one script per part', () => {
    expect(names(scene('plane'))).toEqual([
      'curve',
      'velocity',
      'tangent',
      'normal',
      'curvature',
      'comb',
      'inflections',
    ]);
    expect(names(scene('helix'))).toEqual([
      'curve',
      'tangent',
      'normal',
      'binormal',
      'osculating',
      'frames',
      'flips',
    ]);
    expect(names(scene('arc'))).toEqual([
      'curve',
      'ticks',
      'arcLength',
      'table',
      'equalLength',
      'both',
    ]);
  });

  it('finds every scene’s script from its state: the part’s', () => {
    for (const s of SCENES) {
      const state = s.setup(defaults);
      expect(s.script, s.id).toBe(PART_SCRIPTS[state.part]);
      expect(SCENES.find((x) => x.id === sceneOf(state))!.script, s.id).toBe(s.script);
    }
  });

  it('keeps the captions of the lecture, word for word', () => {
    const caption = (s: CurvatureState, k: number) => lesson.steps!.describe(s, k);
    expect(caption(scene('plane'), 4)).toBe(
      'The curvature κ and the osculating circle of radius 1/|κ|',
    );
    expect(caption(scene('twisted'), 6)).toBe(
      'Where κ → 0 the frame flips: N and B swing round fast (at κ = 0 they would jump)',
    );
    expect(caption(scene('arc'), 2)).toBe(
      'The arc length s(t) = ∫ |P′(ξ)| dξ from 0 to t, against t',
    );
    // Beyond the last step, the last caption.
    expect(caption(scene('arc'), 9)).toBe('Both sets of ticks: equal t against equal s');
  });

  it('gives each step its formula with the numbers worked by hand', () => {
    // The lecture cubic at t = 1/2: P = (2, 1.5), P′ = (4.5, 0), P″ = (0, −12),
    // κ = 4.5·(−12)/4.5³ = −0.5926, R = 27/16 = 1.6875.
    const half = (step: number) => formula({ ...defaults, t: 0.5, step });
    expect(half(0)).toBe('P(0.5) = (2.00,\\ 1.50)');
    expect(half(1)).toBe("P'(0.5) = (4.50,\\ 0.00),\\quad |P'| = 4.500");
    expect(half(2)).toBe("T = \\frac{P'}{|P'|} = (1.000,\\ 0.000)");
    // κ < 0: the curve turns right, so N is T turned clockwise, (0, −1).
    expect(half(3)).toBe('\\text{turning right: } N = (T_y,\\ -T_x) = (0.000,\\ -1.000)');
    expect(half(4)).toBe(
      "\\kappa = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{-54.000}{91.125} = -0.593,\\quad R = \\frac{1}{|\\kappa|} = 1.688",
    );
    // The helix a = 1, b = 1/4: κ = 16/17, τ = 4/17, from the general formulas and the closed forms.
    const helix = (step: number) => formula({ ...scene('helix'), step });
    expect(helix(2)).toMatch(/= 0\.941,\\quad \\frac\{a\}\{a\^2\+b\^2\} = 0\.941,/);
    expect(helix(3)).toMatch(/= 0\.235,\\quad \\frac\{b\}\{a\^2\+b\^2\} = 0\.235$/);
    // The cusp: T and N are undefined there, and the formula says so.
    expect(formula({ ...scene('cusp'), step: 2 })).toMatch(/\\text\{is undefined\}$/);
    // Equal steps of length: the same formula at the last two steps.
    const arc = scene('arc');
    expect(formula({ ...arc, step: 4 })).toBe(formula({ ...arc, step: 5 }));
    expect(formula({ ...arc, step: 1 })).toBe('t_i = \\frac{i}{8},\\quad i = 0, \\dots, 8');
  });

  it('computes the curve once: a step or t keeps it, new points make it again', () => {
    const s = scene('natural');
    const at0 = derive({ ...s, step: 0 });
    const at6 = derive({ ...s, step: 6 });
    expect(at6.plane).toBe(at0.plane);
    expect(at6.space).toBe(at0.space);
    const moved = derive({ ...s, t: 0.7 });
    expect(moved.plane!.comb).toBe(at0.plane!.comb);
    expect(moved.plane!.at).not.toBe(at0.plane!.at);
    const helix = scene('helix');
    expect(derive({ ...helix, step: 5 }).space).toBe(derive({ ...helix, step: 1 }).space);
    expect(derive({ ...helix, t: 0.6 }).space.kappa).toBe(derive(helix).space.kappa);
    const arc = scene('arc');
    expect(derive({ ...arc, t: 0.2 }).arc!.table).toBe(derive(arc).arc!.table);
    const points = s.points.map((p) => [...p]);
    expect(derive({ ...s, points }).plane!.comb).not.toBe(at0.plane!.comb);
  });
});

describe('the points of the curvature lesson', () => {
  it('labels every point with its own name, on one spot as another too, and adds or removes none', () => {
    const s: CurvatureState = {
      ...defaults,
      points: [
        [0, 0],
        [1, 1],
        [1, 1],
        [2, 0],
      ],
    };
    const handles = curveFigure.handles!(derive(s));
    expect(handles.map((h) => [h.id, h.label, h.showLabel])).toEqual([
      ['p0', 'P_{0}', true],
      ['p1', 'P_{1}', true],
      ['p2', 'P_{2}', true],
      ['p3', 'P_{3}', true],
    ]);
    expect(lesson.figures.map((f) => [f.addPoint, f.removeHandle])).toEqual([
      [undefined, undefined],
      [undefined, undefined],
      [undefined, undefined],
    ]);
    expect(planePoints.add(s, [5, 5])).toBeNull();
    expect(planePoints.remove(s, 0)).toBeNull();
  });

  it('moves a Hermite gradient by its tip P + D/3, and leaves the other gradients as they were', () => {
    const s: CurvatureState = {
      ...defaults,
      source: 'hermite',
      points: [
        [0, 0],
        [1, 2],
        [3, 0.1],
      ],
      gradients: [
        [1, 0.1],
        [0.3, 0.7],
        [2, 2],
      ],
    };
    const handles = gradientHandles.handles(s);
    expect(handles.map((h) => [h.id, h.label, h.small])).toEqual([
      ['d0', 'P_{0} + D_{0}/3', true],
      ['d1', 'P_{1} + D_{1}/3', true],
      ['d2', 'P_{2} + D_{2}/3', true],
    ]);
    const moved = curveFigure.moveHandle!(s, 'd1', [2, 3], derive(s));
    // D1 = 3·((2, 3) − (1, 2)) = (3, 3).
    expect(moved.gradients).toEqual([s.gradients[0], [3, 3], s.gradients[2]]);
    expect(moved.gradients[0]).toBe(s.gradients[0]);
  });

  it('moves a space cubic’s point in the top view in x and y, keeping its height', () => {
    const s = scene('twisted');
    expect(topViewPoints.handles(s).map((h) => [h.id, h.shape, h.position])).toEqual(
      s.spacePoints.map((q, i) => [`q${i}`, 'square', [q[0], q[1]]]),
    );
    const moved = curveFigure.moveHandle!(s, 'q1', [1, 1], derive(s));
    expect(moved.spacePoints[1]).toEqual([1, 1, 0.5]);
    expect(moved.spacePoints.filter((_, i) => i !== 1)).toEqual(
      s.spacePoints.filter((_, i) => i !== 1),
    );
    // No Q handles where there is no space cubic.
    expect(topViewPoints.handles(scene('helix'))).toEqual([]);
    const space = lesson.figures.find((f) => f.id === 'space')!;
    const lifted = space.moveHandle!(s, 'q2', [2, -2, 1], derive(s));
    expect(lifted.spacePoints[2]).toEqual([2, -2, 1]);
  });
});
