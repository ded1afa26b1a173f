import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { glyphBox } from '../../render/labels';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import { propertiesFigure } from './figure';
import lesson from './lesson';
import type { PropertiesModel } from './model';
import { SCENES } from './scenes';
import { normalize, schema } from './state';

/** Draws a scene's figure into a recording context, as the shell would (fitted to its bounds). */
function draw(id: string, thumbnail = false): SvgContext {
  const scene = SCENES.find((s) => s.id === id)!;
  const model = lesson.derive(normalize(scene.setup(defaultsOf(schema))).state) as PropertiesModel;
  const view = new Viewport(800, 500);
  view.resize(800, 500);
  view.fit(propertiesFigure.bounds(model), 18, true);
  const svg = new SvgContext();
  propertiesFigure.draw(new Painter(svg, view, makeTheme(false, false)), model, {
    hover: null,
    thumbnail,
  });
  return svg;
}

describe('the experiment figure', () => {
  it('draws every scene, and no label in a thumbnail', () => {
    for (const { id } of SCENES) {
      expect(draw(id).elements.length, id).toBeGreaterThan(3);
      expect(draw(id, true).texts, id).toEqual([]);
    }
  });

  it('names what each experiment measures', () => {
    // The loop of (0,0), (5,3), (−1,3), (4,0) is crossed at t = ½ ± √33/22 ≈ 0.24 and 0.76.
    expect(draw('loop').texts).toContain('crossing, t = 0.24 and 0.76');
    // P5 of twelve moved by 2: the curve moves at most 2·W(11, 5, 5/11) ≈ 0.472.
    expect(draw('local').texts).toContain('max 0.472');
    expect(draw('perspective').texts).toEqual(
      expect.arrayContaining(['map of the curve', 'curve of the mapped points']),
    );
    // Shown whole, the scene lists P1 six times (five extra copies): the ring says so.
    expect(draw('repeat').texts).toContain('×6');
  });
});

// A 1366 × 768 projector: the figure is 1348 × 600 px. Over the affine image
// the two names had no clear place within 3.4 label heights: "curve of the
// mapped points" was boxed over both curves, with a clear band under them.
describe('the affine scene’s names on a 1366 presenter figure', () => {
  it('stand where no stroke runs through them, the far one on a leader', () => {
    const figure = lesson.figures.find((f) => f.id === propertiesFigure.id)!;
    const scene = lesson.scenes!.find((s) => s.id === 'affine')!;
    const start = scene.apply(defaultsOf(schema) as never) as never;
    const state = { ...(start as object), step: lesson.steps!.count(start) } as never;
    const { painter } = drawHeadless(figure, lesson.derive(state), {
      width: 1348,
      height: 600,
      theme: makeTheme(false, true),
    });
    for (const text of ['map of the curve', 'curve of the mapped points']) {
      const label = painter.labels.find((l) => l.text === text);
      expect(label, text).toBeDefined();
      expect(label!.boxed, `${text} boxed`).toBeFalsy();
      expect(painter.ink.crossing(glyphBox(label!)), `through ${text}`).toBeNull();
    }
  });
});
