import { describe, expect, it } from 'vitest';
import { defaultsOf, encodeState } from '../../app/urlState';
import { sceneStates } from '../../kit/scriptChecks';
import { OrbitCamera } from '../../render/orbitCamera';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import lesson from './lesson';
import type { SurfaceModel } from './model';
import { JOIN_NEXT_C0 } from './presets';
import { SCENES } from './scenes';
import { SCRIPTS } from './scripts';
import { type SurfaceState, schema } from './state';
import { weightsShown } from './weightsFigure';

const derive = (s: SurfaceState) => lesson.derive(s) as SurfaceModel;

/** Every figure drawn through the recording context, the patch through its orbit camera. */
function drawn(state: SurfaceState, projector = false) {
  const model = lesson.derive(state);
  let elements = 0;
  const svg: string[] = [];
  for (const figure of lesson.figures) {
    const view = figure.kind === 'space' ? new OrbitCamera(figure.camera) : new Viewport();
    view.resize(900, 560);
    view.fit(figure.bounds(model), 40, true);
    const context = new SvgContext();
    const painter = new Painter(context, view, makeTheme(false, projector));
    figure.draw(painter, model, { hover: null, thumbnail: false });
    figure.drawOver?.(painter, model, { hover: null, thumbnail: false });
    elements += context.elements.length;
    svg.push(context.toSvg(900, 560));
  }
  return { elements, svg: svg.join('\n') };
}
const defaults = defaultsOf(schema) as SurfaceState;
const sceneState = (id: string, changes: Partial<SurfaceState> = {}): SurfaceState => ({
  ...SCENES.find((s) => s.id === id)!.setup(defaults),
  ...changes,
});
/** The name of each step of a scene, in order. */
const names = (id: string) => {
  const s = sceneState(id);
  return Array.from(
    { length: lesson.steps!.count(s) + 1 },
    (_, step) => derive({ ...s, step }).shown.name,
  );
};

describe('the scenes and their named steps', () => {
  // The kit's checkScript, drawn through an orbit camera (its drawState fits a plane's
  // viewport, which a space figure cannot draw through).
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () => {
    expect(lesson.scenes![0].apply(defaults)).toEqual(defaults);
    for (const scene of sceneStates(lesson)) {
      const { id, count } = scene;
      const at = (k: number) => scene.at(k) as unknown as SurfaceState;
      expect(count, `${id}: steps`).toBeGreaterThan(1);
      expect(count, `${id}: steps`).toBeLessThanOrEqual(20);
      for (const projector of [false, true])
        expect(drawn(at(0), projector).elements, `${id}: step 0 draws less`).toBeLessThan(
          drawn(at(count), projector).elements,
        );
      for (let k = 0; k <= count; k++) {
        const state = at(k);
        const caption = lesson.steps!.describe(state, k);
        expect(caption.length, `${id} step ${k}`).toBeGreaterThan(10);
        expect(caption, `${id} step ${k}`).not.toMatch(/[_\\{}^]|[Ee]quation|the notes/);
        expect(drawn(state).svg, `${id} step ${k}`).not.toMatch(/NaN|Infinity/);
        const formula = lesson.steps!.formula!(derive(state), state) ?? '';
        expect(formula, `${id} step ${k}`).not.toMatch(/NaN|Infinity|undefined|\\val|\+ -|e[+-]\d/);
      }
    }
  });

  it('each kind of scene has its own steps, named after what they reveal', () => {
    const patch = ['points', 'net', 'corners', 'edges', 'isoCurves', 'patch'];
    for (const id of ['patch', 'flat', 'saddle', 'bump', 'wave', 'twisted'])
      expect(names(id)).toEqual(patch);
    expect(names('rows')).toEqual(['net', 'rowCurves', 'rowPoints', 'isoV', 'point', 'isoU']);
    expect(names('casteljau')).toEqual([
      'net',
      'columns',
      'columnPoints',
      'uThenV',
      'rows',
      'rowPoints',
      'vThenU',
    ]);
    expect(names('matrix')).toEqual(['coordinates', 'rowFactors', 'columnFactors', 'product']);
    expect(names('weights')).toEqual(['net', 'rowShares', 'columnShares', 'products', 'average']);
    expect(names('normal')).toEqual(['point', 'uTangent', 'vTangent', 'normal', 'tangentPlane']);
    for (const id of ['c0', 'c1']) expect(names(id)).toEqual(['nets', 'edge', 'patches', 'legs']);
    expect(SCRIPTS.casteljau.stepOf(sceneState('casteljau'), 'rows')).toBe(4);
  });

  it('keeps the links: the same short keys, in the same order', () => {
    expect(encodeState(schema, defaults)).toMatch(
      /^x=0,0,0;.*&y=3,0,0;.*&u=0\.3&v=0\.6&k=0&s=patch&look=shaded&c=z$/,
    );
  });

  it('captions and formulas read the model of their state', () => {
    const s = sceneState('patch', { step: 5 });
    expect(lesson.steps!.describe(s, 5)).toBe('The patch, and the point x(0.3, 0.6) on it');
    expect(lesson.steps!.formula!(derive(s), s)).toMatch(/^\\mathbf\{x\}\(0\.3,0\.6\) = \(/);
    // The join's verdict follows the second net, from the model.
    const c1 = sceneState('c1', { step: 3 });
    const c0 = sceneState('c0', { step: 3 });
    expect(lesson.steps!.describe(c1, 3)).toMatch(/collinear and equally long: C¹/);
    expect(lesson.steps!.describe(c0, 3)).toMatch(/not collinear: C⁰ only, a crease$/);
    expect(c0.secondNet).toBe(JOIN_NEXT_C0);
  });

  it('the heat map shows row shares, column shares, then products', () => {
    const shown = [0, 1, 2, 3, 4].map((step) =>
      weightsShown(derive(sceneState('weights', { step }))),
    );
    expect(shown).toEqual(['products', 'rows', 'columns', 'products', 'products']);
    expect(weightsShown(derive(sceneState('rows', { step: 1 })))).toBe('products');
  });

  it('a step costs no new geometry: the patch and the point are kept', () => {
    const first = derive(sceneState('casteljau', { step: 0 }));
    const later = derive({ ...first.state, step: 6 });
    expect(later).not.toBe(first);
    expect(later.patch).toBe(first.patch);
    expect(later.uThenV).toBe(first.uThenV);
    expect(later.matrix).toBe(first.matrix);
    expect(derive({ ...first.state, u: 0.9 }).uThenV).not.toBe(first.uThenV);
  });
});

describe('the control points', () => {
  /** The patch figure as the shell gets it, its handles from the point lists. */
  const shellFigure = lesson.figures[0];
  const handles = (s: SurfaceState) => shellFigure.handles!(derive(s));

  it('labels every point of the net while it is the subject, then only its corners', () => {
    const labelled = (s: SurfaceState) =>
      handles(s)
        .filter((h) => h.showLabel)
        .map((h) => h.label);
    expect(handles(defaults).map((h) => h.label)).toEqual(
      [0, 1, 2, 3].flatMap((m) => [0, 1, 2, 3].map((n) => `x_{${m},${n}}`)),
    );
    expect(labelled(sceneState('patch', { step: 1 }))).toHaveLength(16);
    const corners = ['x_{0,0}', 'x_{0,3}', 'x_{3,0}', 'x_{3,3}'];
    expect(labelled(sceneState('patch', { step: 2 }))).toEqual(corners);
    expect(labelled(sceneState('rows'))).toEqual(corners);
    expect(labelled(sceneState('c1'))).toEqual([]);
  });

  it('gives the second net’s rows y₁ … y₃ handles only in the scene of two patches', () => {
    expect(handles(sceneState('normal'))).toHaveLength(16);
    const pair = handles(sceneState('c1'));
    expect(pair).toHaveLength(28);
    expect(pair.slice(16, 20).map((h) => h.label)).toEqual([
      'y_{1,0}',
      'y_{1,1}',
      'y_{1,2}',
      'y_{1,3}',
    ]);
    expect(pair.every((h) => h.small)).toBe(true);
  });

  it('moves the point of the handle, and nothing else', () => {
    const s = sceneState('c1');
    const [x11] = handles(s).filter((h) => h.label === 'x_{1,1}');
    const moved = shellFigure.moveHandle!(s, x11.id, [1, 1, 5], derive(s));
    expect(moved.net[1][1]).toEqual([1, 1, 5]);
    expect(moved.net.flat().filter((p, i) => p !== s.net.flat()[i])).toHaveLength(1);
    expect(moved.secondNet).toBe(s.secondNet);
    const [y21] = handles(s).filter((h) => h.label === 'y_{2,1}');
    const next = shellFigure.moveHandle!(s, y21.id, [5, 1, 2], derive(s));
    expect(next.secondNet[2][1]).toEqual([5, 1, 2]);
    expect(next.secondNet[0]).toBe(s.secondNet[0]);
    expect(next.net).toBe(s.net);
    // A net of 16 fixed points: nothing to add, nothing to delete.
    expect(shellFigure.addPoint).toBeUndefined();
    expect(shellFigure.removeHandle).toBeUndefined();
  });
});
