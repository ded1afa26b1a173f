import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { cross } from '../../math';
import { sceneStates } from '../../kit/scriptChecks';
import { OrbitCamera } from '../../render/orbitCamera';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import lesson from './lesson';
import type { SurfaceModel } from './model';
import { JOIN_NEXT_C0 } from './presets';
import { SCENES, sceneOf } from './scenes';
import { NOTES_SYMBOLS, ROWS_SLIP } from './notes';
import { cornerVolume } from './presetScripts';
import { SCRIPTS } from './scripts';
import { LEANING_HILL_NET, type SurfaceState, schema } from './state';
import { weightsShown } from './weightsFigure';
import { drawHandles } from '../../render/handles';
import type { LabelBox } from '../../render/labels';
import { namedPoints } from './points';
import type { Point } from '../../app/lesson';

/**
 * The patch figure as the shell draws it (figure, handles, then the marks
 * above them), fitted as the shell fits it: the labels it placed, where the
 * net's points are on screen, and a small handle's radius.
 */
function placed(state: SurfaceState, width: number, height: number, projector = false) {
  const figure = lesson.figures[0];
  const model = lesson.derive(state);
  const view = new OrbitCamera(figure.camera);
  view.resize(width, height);
  view.fit(figure.bounds(model), 0.12 * Math.min(width, height));
  const theme = makeTheme(false, projector);
  const painter = new Painter(new SvgContext(), view, theme);
  const info = { hover: null, thumbnail: false };
  figure.draw(painter, model, info);
  drawHandles(painter, figure.handles!(model));
  figure.drawOver?.(painter, model, info);
  return {
    labels: painter.labels as readonly LabelBox[],
    points: state.net.flat().map((p) => view.toScreen(p)),
    radius: theme.sizes.handle * 0.5,
  };
}
const placedLabels = (state: SurfaceState, width: number, height: number) =>
  placed(state, width, height).labels;

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

  it('each scene has its own steps, named after what they reveal', () => {
    expect(names('patch')).toEqual(['points', 'net', 'corners', 'edges', 'isoCurves', 'patch']);
    expect(names('flat')).toEqual(['net', 'plane', 'isoCurves', 'surface', 'point', 'normal']);
    expect(names('saddle')).toEqual(['net', 'corners', 'isoU', 'isoV', 'isoCurves', 'point']);
    expect(names('bump')).toEqual(['net', 'edges', 'surface', 'point', 'shares', 'tangentPlane']);
    expect(names('wave')).toEqual(['net', 'columnCurves', 'rowCurves', 'surface', 'isoV', 'point']);
    expect(names('twisted')).toEqual(['cornerQuad', 'net', 'edges', 'surface', 'point', 'normal']);
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
    expect(lesson.steps!.describe(s, 5)).toBe('The patch, and the point P(0.3, 0.6) on it');
    expect(lesson.steps!.formula!(derive(s), s)).toMatch(/^\\mathbf\{P\}\(0\.3,0\.6\) = \(/);
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

  it('names every point of the net while it is the subject, then only its corners (placed by the figure)', () => {
    const named = (s: SurfaceState) =>
      handles(s)
        .filter((_, i) => i < 16 && namedPoints(s)(i))
        .map((h) => h.label);
    const names = (s: SurfaceState) =>
      placedLabels(s, 900, 560)
        .map((b) => b.text)
        .filter((t) => /^P_\{\d,\d\}$/.test(t))
        .sort();
    const all = [0, 1, 2, 3].flatMap((m) => [0, 1, 2, 3].map((n) => `P_{${m},${n}}`));
    expect(handles(defaults).map((h) => h.label)).toEqual(all);
    // The handles name no point themselves: the figure places every name.
    expect(handles(defaults).some((h) => h.showLabel)).toBe(false);
    for (const step of [0, 1]) {
      const s = sceneState('patch', { step });
      expect(named(s)).toEqual(all);
      expect(names(s)).toEqual(all);
    }
    const corners = ['P_{0,0}', 'P_{0,3}', 'P_{3,0}', 'P_{3,3}'];
    expect(named(sceneState('patch', { step: 2 }))).toEqual(corners);
    expect(names(sceneState('patch', { step: 2 }))).toEqual(corners);
    expect(named(sceneState('rows'))).toEqual(corners);
    for (const id of ['flat', 'saddle', 'bump', 'wave', 'twisted'])
      expect(named(sceneState(id)), id).toEqual(corners);
    expect(named(sceneState('c1'))).toEqual([]);
  });

  it('step 0: no name covers another or a point of the net, on a laptop and on the projector', () => {
    for (const id of SCENES.map((scene) => scene.id)) {
      const s = sceneState(id);
      for (const [width, height, projector] of [
        [540, 700, false],
        [900, 560, false],
        [1104, 677, true],
        [840, 520, true],
      ] as const) {
        const where = `${id} at ${width} × ${height}${projector ? ', projector' : ''}`;
        const { labels, points, radius } = placed(s, width, height, projector);
        for (let i = 0; i < labels.length; i++)
          for (let j = i + 1; j < labels.length; j++) {
            const a = labels[i];
            const b = labels[j];
            const w = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
            const h = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
            expect(w > 1 && h > 1, `${where}: “${a.text}” on “${b.text}”`).toBe(false);
          }
        for (const b of labels.filter((l) => /^P_/.test(l.text)))
          points.forEach(([x, y], k) => {
            const dx = Math.max(b.x - x, 0, x - (b.x + b.width));
            const dy = Math.max(b.y - y, 0, y - (b.y + b.height));
            expect(
              Math.hypot(dx, dy),
              `${where}: “${b.text}” on point ${k}`,
            ).toBeGreaterThanOrEqual(radius);
          });
      }
    }
  });

  it('a drag places the names as a fresh page does: the same while (u, v) moves, after the point that moved', () => {
    // The places a name may go are kept while the net and the view stay (a
    // drag of u or v); each state here is drawn after another, then again
    // after a different size, which a fresh page would draw it as.
    const names = (s: SurfaceState) =>
      placedLabels(s, 900, 560)
        .filter((l) => /^P_/.test(l.text))
        .map((l) => `${l.text}@${Math.round(l.x)},${Math.round(l.y)}`);
    const fresh = (s: SurfaceState) => {
      placedLabels(s, 640, 480);
      return names(s);
    };
    const start = sceneState('patch', { step: 0 });
    const net = start.net.map((row) => row.map((p) => [...p] as Point));
    net[1][1] = [net[1][1][0], net[1][1][1] + 1.5, net[1][1][2] + 2];
    const moved = { ...start, net };
    const sequence = [
      start,
      { ...start, u: 0.7 },
      { ...start, v: 0.1 },
      moved,
      { ...moved, u: 0.2 },
    ];
    const seen = sequence.map(names);
    expect(seen).toEqual(sequence.map(fresh));
    // The moved point's name went with it.
    const label11 = (list: string[]) => list.find((t) => t.startsWith('P_{1,1}'));
    expect(label11(seen[3])).toBeDefined();
    expect(label11(seen[3])).not.toBe(label11(seen[0]));
  });

  it('gives the second net’s rows Q₁ … Q₃ handles only in the scene of two patches', () => {
    expect(handles(sceneState('normal'))).toHaveLength(16);
    const pair = handles(sceneState('c1'));
    expect(pair).toHaveLength(28);
    expect(pair.slice(16, 20).map((h) => h.label)).toEqual([
      'Q_{1,0}',
      'Q_{1,1}',
      'Q_{1,2}',
      'Q_{1,3}',
    ]);
    expect(pair.every((h) => h.small)).toBe(true);
  });

  it('moves the point of the handle, and nothing else', () => {
    const s = sceneState('c1');
    const [x11] = handles(s).filter((h) => h.label === 'P_{1,1}');
    const moved = shellFigure.moveHandle!(s, x11.id, [1, 1, 5], derive(s));
    expect(moved.net[1][1]).toEqual([1, 1, 5]);
    expect(moved.net.flat().filter((p, i) => p !== s.net.flat()[i])).toHaveLength(1);
    expect(moved.secondNet).toBe(s.secondNet);
    const [y21] = handles(s).filter((h) => h.label === 'Q_{2,1}');
    const next = shellFigure.moveHandle!(s, y21.id, [5, 1, 2], derive(s));
    expect(next.secondNet[2][1]).toEqual([5, 1, 2]);
    expect(next.secondNet[0]).toBe(s.secondNet[0]);
    expect(next.net).toBe(s.net);
    // A net of 16 fixed points: nothing to add, nothing to delete.
    expect(shellFigure.addPoint).toBeUndefined();
    expect(shellFigure.removeHandle).toBeUndefined();
  });
});

describe('each net worth seeing is a scene of its own idea', () => {
  const presets = ['flat', 'saddle', 'bump', 'wave', 'twisted'];
  const captions = (id: string) => {
    const s = sceneState(id);
    return Array.from({ length: lesson.steps!.count(s) + 1 }, (_, k) =>
      lesson.steps!.describe({ ...s, step: k }, k),
    );
  };

  it('starts where its own idea starts: no two scenes open with the same words', () => {
    // The two joined pairs share their steps on purpose: the same walk, a crease or not at its end.
    const own = SCENES.filter((scene) => scene.id !== 'c1');
    const openings = own.map((scene) => captions(scene.id)[0]);
    expect(new Set(openings).size).toBe(own.length);
    const patch = captions('patch');
    for (const id of presets)
      for (const caption of captions(id)) expect(patch, id).not.toContain(caption);
    expect(captions('flat')[0]).toBe('A flat net: all 16 points in the plane z = 0, evenly spaced');
    expect(captions('twisted')[0]).toMatch(/^Not even the four corners are in one plane/);
  });

  it('every press changes what is drawn, in every scene', () => {
    for (const scene of SCENES) {
      const s = sceneState(scene.id);
      const count = lesson.steps!.count(s);
      for (let k = 1; k <= count; k++)
        expect(drawn({ ...s, step: k }).svg, `${scene.id}: step ${k}`).not.toBe(
          drawn({ ...s, step: k - 1 }).svg,
        );
    }
  });

  it('opens with its own u, v and look, whatever scene came before', () => {
    const afterBump = SCENES.find((s) => s.id === 'bump')!.setup(defaults);
    const afterSaddle = SCENES.find((s) => s.id === 'saddle')!.setup(afterBump);
    for (const id of ['flat', 'wave', 'twisted']) {
      const s = SCENES.find((scene) => scene.id === id)!.setup(afterSaddle);
      expect(s, id).toMatchObject({ u: 0.3, v: 0.6, look: 'shaded', mode: 'patch' });
    }
    expect(afterBump).toMatchObject({ u: 0.5, v: 0.5 });
    expect(afterSaddle).toMatchObject({ look: 'lines', u: 0.3, v: 0.6 });
  });

  it('is told apart by its net; edited away from it, the net is a patch like any other', () => {
    for (const id of presets) expect(sceneOf(sceneState(id))).toBe(id);
    expect(sceneOf(defaults)).toBe('patch');
    const flat = sceneState('flat', { step: 3 });
    const lifted = flat.net.map((row, m) =>
      row.map((p, n) => (m === 1 && n === 1 ? [p[0], p[1], 1] : p)),
    );
    const edited = { ...flat, net: lifted };
    expect(sceneOf(edited)).toBe('patch');
    expect(derive(edited).shown.name).toBe('edges');
    // The link says the same: the net is in it.
    const back = decodeState(schema, encodeState(schema, sceneState('bump', { step: 4 }))).state;
    expect(sceneOf(back)).toBe('bump');
    expect(lesson.steps!.describe(back, 4)).toMatch(/^Why: the four inner points/);
  });

  it('says what is true of its net, in numbers the model agrees with', () => {
    // Flat: Σ m fm(u) = 3u, so P(u, v) = (3u, 3v, 0).
    const flat = derive(sceneState('flat', { step: 4 }));
    expect(flat.point.map((v) => Number(v.toFixed(12)))).toEqual([0.9, 1.8, 0]);
    expect(flat.normal).toEqual([0, 0, 1]);
    // Saddle: z = 9(u − ½)(v − ½)/2 = −0.09 at (0.3, 0.6); the iso-curve's control points on a line.
    const saddle = sceneState('saddle', { step: 5 });
    expect(derive(saddle).point[2]).toBeCloseTo(-0.09, 14);
    expect(lesson.steps!.describe(saddle, 5)).toBe(
      'At P(0.3, 0.6) the height is −0.09: up one way, down the other',
    );
    const [c0, c1, , c3] = derive(saddle).columnPoints;
    const along = (p: readonly number[]) => p.map((v, d) => v - c0[d]);
    const crossed = cross(along(c1), along(c3));
    expect(Math.hypot(...crossed)).toBeLessThan(1e-12);
    // Bump: z = 2(f1 + f2)(u)·(f1 + f2)(v) = 2·(3/4)² = 9/8 at the top.
    const bump = sceneState('bump', { step: 3 });
    expect(lesson.steps!.describe(bump, 3)).toBe('At P(0.5, 0.5) it is 1.125 high, not 2');
    expect(lesson.steps!.formula!(derive(bump), bump)).toMatch(
      /= 2 \\cdot 0\.75 \\cdot 0\.75 = 1\.125$/,
    );
    // Wave: z = 4.5 u(1 − u)(1 − 2u) g(v), g = ½f0 + f1 + f2 + ½f3.
    const wave = derive(sceneState('wave', { step: 5 }));
    const [f0, f1, f2, f3] = wave.columnShares;
    const g = f0 / 2 + f1 + f2 + f3 / 2;
    expect(wave.point[2]).toBeCloseTo(4.5 * 0.3 * 0.7 * 0.4 * g, 13);
    // Not planar: the corners span a volume, 33.3 ≠ 0.
    expect(cornerVolume(sceneState('twisted').net)).toBeCloseTo(33.3, 12);
    expect(cornerVolume(sceneState('flat').net)).toBe(0);
  });
});

describe('the notes', () => {
  it('where the slides build the curve in u “for 0 ≤ v ≤ 1”, the rows scene says u, and kindly why', () => {
    const s = sceneState('rows', { step: 3 });
    expect(lesson.steps!.describe(s, 3)).toBe(
      'r₀ … r₃ are the control points of a curve in u, 0 ≤ u ≤ 1: the iso-curve v = 0.6',
    );
    expect(ROWS_SLIP.written).toMatch(/for 0 ≤ v ≤ 1/);
    expect(ROWS_SLIP.correct).toMatch(/runs in u, for 0 ≤ u ≤ 1/);
  });

  it('writes the net Pₘ,ₙ (the second Qₘ,ₙ) and the point P(u, v), as every lesson writes P₀ … Pₙ and P(t)', () => {
    // The point as the notes write it: x(…), xₘ,ₙ, ∂x, \\mathbf{x} or x_{m,n}, and the second net y.
    // (z(u, v), z_{m,n} and the x, y, z coordinates are coordinates, not points; the matrix
    // scene writes its coordinate, z by default.)
    const plain = /\bx\(|\b[xy][₀-₃ₘ],|∂x|\bnets? [xy]\b|\bof [xy]\b/;
    const tex = /\\mathbf\{[xy]\}|\b[xy]_\{/;
    const said: string[] = [];
    for (const scene of sceneStates(lesson)) {
      for (let k = 0; k <= scene.count; k++) {
        const state = scene.at(k) as unknown as SurfaceState;
        const caption = lesson.steps!.describe(state, k);
        const formula = lesson.steps!.formula!(derive(state), state) ?? '';
        expect(caption, `${scene.id} step ${k}`).not.toMatch(plain);
        expect(formula, `${scene.id} step ${k}`).not.toMatch(tex);
        const labels = placedLabels(state, 900, 560).map((b) => b.text);
        expect(
          labels.filter((t) => /^[xy]_|^x\(|∂x/.test(t)),
          `${scene.id} step ${k}`,
        ).toEqual([]);
        said.push(caption, formula, ...labels);
      }
    }
    const all = said.join('\n');
    for (const written of [
      'P(0.3, 0.6)',
      'P₀,₀',
      '\\mathbf{P}(0.3,0.6)',
      '\\mathbf{P}_{m,n}',
      'P(u,v)',
      'P_{0,0}',
      '∂P/∂u',
      'Q₀,ₙ = P₃,ₙ',
      '\\mathbf{Q}_{0,n}',
    ])
      expect(all, written).toContain(written);
    // The handles' names (what a screen reader hears) follow the labels; their ids keep the links.
    const pair = lesson.figures[0].handles!(derive(sceneState('c1')));
    expect(pair.map((h) => h.label).filter((l) => !/^[PQ]_\{\d,\d\}$/.test(l))).toEqual([]);
    expect(pair.map((h) => h.id.charAt(0))).toEqual([...'x'.repeat(16), ...'y'.repeat(12)]);
  });

  it('keys the lesson’s symbols to the notes’', () => {
    const there = NOTES_SYMBOLS.map(([, notes]) => notes).join(' | ');
    expect(there).toMatch(/pᵢⱼ \(and xᵢⱼ for its x coordinates\) in the continuation notes/);
    expect(there).toMatch(/Bᵢ\(u\) in the continuation notes/);
    // 002 writes the patch's point p(u, v) and keeps x(u, v) for its x coordinate; 001 writes x(u, v).
    expect(there).toMatch(/x\(u, v\) in the lecture slides; p\(u, v\) in the continuation notes/);
    const here = NOTES_SYMBOLS.map(([app]) => app);
    expect(here[0]).toBe('Pₘ,ₙ: m runs along u, n along v');
    expect(here).toContain('P(u, v): the point of the patch');
    expect(here.some((row) => row.startsWith('Qₘ,ₙ: the second patch’s net'))).toBe(true);
  });

  it('names its data after what it shows: the net the construction scenes start from is a leaning hill', () => {
    expect(defaults.net).toEqual(LEANING_HILL_NET);
    for (const scene of SCENES) {
      const s = sceneState(scene.id);
      for (let k = 0; k <= lesson.steps!.count(s); k++)
        expect(lesson.steps!.describe({ ...s, step: k }, k)).not.toMatch(/lecture/i);
    }
  });
});
