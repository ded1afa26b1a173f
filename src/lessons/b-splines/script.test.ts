import { describe, expect, it } from 'vitest';
import { normalizeState } from '../../app/lessonState';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { drawState, sceneStates } from '../../kit/scriptChecks';
import { curveFigure } from './curveFigure';
import { knotFigure } from './knotFigure';
import lesson from './lesson';
import type { BSplineModel } from './model';
import { controlPoints } from './points';
import { SCENES } from './scenes';
import { partScript } from './scripts';
import { type BSplineState, normalize, schema } from './state';

const derive = (s: BSplineState) => lesson.derive(s) as BSplineModel;
const defaults = normalize(defaultsOf(schema)).state;
const sceneState = (id: string, changes: Partial<BSplineState> = {}): BSplineState =>
  normalize({ ...SCENES.find((s) => s.id === id)!.setup(defaults), ...changes }).state;
/** What each step of a scene reveals: the step's name (and which repeat). */
const names = (id: string) => {
  const s = sceneState(id);
  return Array.from({ length: lesson.steps!.count(s) + 1 }, (_, step) => {
    const { shown } = derive({ ...s, step });
    return shown.index > 0 ? `${shown.name} ${shown.index}` : shown.name;
  });
};

describe('the scenes and their named steps', () => {
  // The kit's checkScript, but for two rules the lesson's reviewed texts predate: a caption
  // may name a matrix as the lecture does (G_Bez), and a residual is written 3.6e-16.
  it('every scene steps from little to all, in at most 20 steps, drawing finite numbers', () => {
    expect(lesson.scenes![0].apply(defaults)).toEqual(defaults);
    for (const { id, count, at } of sceneStates(lesson)) {
      expect(count, `${id}: steps`).toBeGreaterThan(1);
      expect(count, `${id}: steps`).toBeLessThanOrEqual(20);
      for (const projector of [false, true]) {
        const first = drawState(lesson, at(0), { projector }).elements;
        expect(first, `${id}: step 0 draws less`).toBeLessThan(
          drawState(lesson, at(count), { projector }).elements,
        );
      }
      for (let k = 0; k <= count; k++) {
        const state = at(k) as unknown as BSplineState;
        expect(lesson.steps!.describe(state, k), `${id} step ${k}`).not.toMatch(/\\|[{}^]/);
        expect(drawState(lesson, state).svg, `${id} step ${k}`).not.toMatch(/NaN|Infinity/);
        const formula = lesson.steps!.formula!(derive(state), state) ?? '';
        expect(formula, `${id} step ${k}`).not.toMatch(/NaN|Infinity|undefined|\\val|\+ -/);
      }
    }
  });

  it('each scene has its family’s steps, named after what they reveal', () => {
    const uniform = ['points', 'polygon', 'segment', 'segments', 'joints'];
    expect(names('uniform')).toEqual(uniform);
    expect(names('closed')).toEqual(uniform);
    expect(names('local')).toEqual(['points', 'curves', 'moved', 'basis']);
    expect(names('convert')).toEqual(['points', 'curve', 'bezier', 'beziers', 'back']);
    expect(names('properties')).toEqual(['points', 'curve', 'hulls', 'line', 'affine']);
    // One row of Cox–de Boor per press, rows 0 … p.
    const knots = ['points', 'knots', 'row 1', 'row 2', 'row 3', 'row 4', 'curve'];
    for (const id of ['knots', 'clamped', 'repeated']) expect(names(id)).toEqual(knots);
    expect(names('nurbs')).toEqual(['points', 'plain', 'weights', 'sum']);
    expect(names('circle')).toEqual(['points', 'weights', 'arcs', 'samples', 'plain']);
    expect(names('projective')).toEqual(['points', 'curve', 'map', 'oldWeights']);
  });

  it('a knot scene of degree p has p + 1 rows: the last step is p + 3', () => {
    for (const degree of [1, 2, 3, 4, 5])
      expect(lesson.steps!.count(sceneState('knots', { degree }))).toBe(degree + 3);
    expect(partScript('repeated').stepOf(sceneState('repeated'), 'curve')).toBe(6);
  });

  it('captions and formulas come from the step declared with them', () => {
    const s = sceneState('uniform');
    expect(lesson.steps!.describe(s, 2)).toBe(
      'Segment Q4 blends x1, x2, x3, x4 with the 1/6 matrix',
    );
    const knots = sceneState('knots', { step: 2 });
    expect(lesson.steps!.describe(knots, 2)).toBe(
      'Row 0 of Cox–de Boor: N(i,0) = 1 on [u(i), u(i+1)), else 0',
    );
    expect(lesson.steps!.describe(knots, 4)).toBe('Row 2: each N(i,2) blends N(i,1) and N(i+1,1)');
    // The last row's formula says the row sums to 1.
    const last = { ...knots, step: 5 };
    expect(lesson.steps!.formula!(derive(last), last)).toMatch(/\\sum_i N_\{i,3\} = 1\.000$/);
    expect(lesson.steps!.formula!(derive(knots), knots)).not.toMatch(/sum/);
  });

  it('the state says which scene it is in', () => {
    for (const scene of SCENES) expect(sceneState(scene.id).part).toBe(scene.id);
    expect(lesson.scenes!.map((scene) => scene.id)).toEqual(SCENES.map((scene) => scene.id));
  });
});

describe('what a step draws, by name', () => {
  it('step 0 of every scene shows the points alone: no curve, no trail', () => {
    for (const scene of SCENES) {
      const m = derive(sceneState(scene.id));
      expect(m.shown.is('points')).toBe(true);
      expect(curveFigure.trail!(m)).toBeNull();
      expect(curveFigure.trail!(derive({ ...m.state, step: 1 }))).toEqual(m.point);
    }
  });

  it('the knots become handles once the knot vector is shown, never in the uniform cubic', () => {
    const knots = sceneState('knots');
    expect(knotFigure.handles!(derive(knots))).toEqual([]);
    const handles = knotFigure.handles!(derive({ ...knots, step: 1 }));
    expect(handles.map((h) => h.id)).toEqual(knots.knots.map((_, j) => `u${j}`));
    expect(knotFigure.handles!(derive({ ...sceneState('uniform'), step: 4 }))).toEqual([]);
  });

  it('the line’s square handles come with the line’s step', () => {
    const s = sceneState('properties', { step: 2 });
    const ids = (step: number) =>
      lesson.figures[0].handles!(derive({ ...s, step })).map((h) => h.id);
    expect(ids(2)).toEqual(['p0', 'p1', 'p2', 'p3', 'p4', 'p5', 'p6']);
    expect(ids(3).slice(-2)).toEqual(['l0', 'l1']);
    const moved = curveFigure.moveHandle!(s, 'l1', [10, 5], derive(s));
    expect(moved.line).toEqual([s.line[0], [10, 5]]);
  });

  it('every control point keeps its own label, even two on one spot (the circle’s x0 and x8)', () => {
    const handles = controlPoints.handles(sceneState('circle'));
    expect(handles.map((h) => [h.label, h.showLabel])).toEqual(
      handles.map((_, i) => [`x_{${i}}`, true]),
    );
  });

  it('draws the same for a step as the step’s name says: more at each step of the uniform cubic', () => {
    const s = sceneState('uniform');
    const sizes = [0, 1, 3, 4].map((step) => drawState(lesson, { ...s, step }).elements);
    expect(sizes).toEqual([...sizes].sort((a, b) => a - b));
  });
});

describe('a point edit takes its weight and its “before” point along', () => {
  it('adds a weight of 1 where the point goes, and refits the knots', () => {
    const s = sceneState('nurbs');
    const added = controlPoints.add(s, [3.5, 3.2])!;
    expect(added.points).toHaveLength(8);
    const at = added.points.findIndex((p) => p[0] === 3.5 && p[1] === 3.2);
    expect(at).toBe(3);
    expect(added.weights).toEqual([1, 1, 4, 1, 1, 1, 0.25, 1]);
    expect(added.before[at]).toEqual([3.5, 3.2]);
    expect(added.knots).toHaveLength(8 + 3 + 1);
    const removed = controlPoints.remove(s, 2)!;
    expect(removed.weights).toEqual([1, 1, 1, 1, 0.25, 1]);
  });

  it('keeps p + 1 points for degree p, and at least four', () => {
    const four = sceneState('knots', {
      points: [
        [0, 0],
        [1, 1],
        [2, 0],
        [3, 1],
      ],
    });
    expect(controlPoints.remove(four, 0)).toBeNull();
    const five = { ...four, points: [...four.points, [4, 0]], degree: 4 };
    expect(controlPoints.remove(normalize(five).state, 0)).toBeNull();
  });
});

describe('derive once, and less per step', () => {
  it('a step or a new t keeps the curve; new points make a new one', () => {
    for (const id of ['uniform', 'knots', 'circle']) {
      const s = sceneState(id);
      const m = derive(s);
      expect(derive({ ...s, step: 2 }).segments).toBe(m.segments);
      expect(derive({ ...s, t: 0.9 }).segments).toBe(m.segments);
      const points = s.points.map((p) => [p[0], p[1] + 1]);
      expect(derive({ ...s, points }).segments).not.toBe(m.segments);
    }
  });
});

describe('the link', () => {
  it('keeps its one-letter keys in their order: x p q t k d u w l', () => {
    const query = encodeState(schema, sceneState('knots'));
    expect(query.split('&').map((part) => part.split('=')[0])).toEqual([
      'x',
      'p',
      'q',
      't',
      'k',
      'd',
      'u',
      'w',
      'l',
    ]);
  });

  it('an old link opens the same state', () => {
    const link = 'x=repeated&k=6&d=3&u=0,0,0,0,1,1,1,2,2,2,2&t=0.3&w=1,1,1,1,1,1,1';
    const state = normalizeState(lesson, decodeState(schema, link).state).state;
    expect(state).toMatchObject({
      part: 'repeated',
      step: 6,
      degree: 3,
      knots: [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2],
      t: 0.3,
    });
    expect(decodeState(schema, link).issues).toEqual([]);
  });
});
