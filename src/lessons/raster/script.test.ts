import { describe, expect, it } from 'vitest';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { checkScript } from '../../kit/scriptChecks';
import { curveFigure } from './curveFigure';
import lesson from './lesson';
import type { RasterModel } from './model';
import { type RasterState, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: RasterState) => lesson.derive(s) as RasterModel;
const defaults = defaultsOf(schema);
/** The scene `id` as the clicker opens it, at step `step`. */
const sceneAt = (id: string, step: number, change: Partial<RasterState> = {}): RasterState => {
  const scene = lesson.scenes!.find((s) => s.id === id)!;
  return { ...scene.apply({ ...defaults, ...change }), step };
};
const caption = (s: RasterState) => lesson.steps!.describe(s, s.step);
const formula = (s: RasterState) => lesson.steps!.formula!(derive(s), s);
const steps = (s: RasterState) => lesson.steps!.count(s);

describe('the script of the raster lesson', () => {
  it('every scene steps from little to all, in at most 20 steps, with plain captions', () =>
    checkScript(lesson));

  it('plots the hairpin: 7 points of degree 6, P(k/6) for k = 0 … 6, 6 segments, the curve, the gap', () => {
    const at = (step: number) => sceneAt('plot', step);
    expect(steps(at(0))).toBe(4);
    expect(caption(at(0))).toBe(
      'Given: the 7 control points of a Bézier curve of degree 6. Task: plot the curve.',
    );
    expect(formula(at(0))).toBeNull();
    expect(caption(at(1))).toBe(
      'Compute 7 points P(k/6) on the curve, k = 0 … 6: the only exact points we will have.',
    );
    expect(formula(at(1))).toBe('P\\!\\left(\\tfrac{k}{6}\\right),\\quad k = 0,1,\\dots,6');
    expect(caption(at(2))).toBe(
      'Join them by 6 straight segments: this polyline is what the screen draws.',
    );
    expect(caption(at(4))).toMatch(
      /^Largest gap \d+\.\d\d px, at t = 0\.\d{3} in segment \d of 6\.$/,
    );
    // What each step reveals, by name.
    const shown = [0, 1, 2, 3, 4].map((step) => derive(at(step)).shown);
    expect(
      shown.map((s) => [s.has('samples'), s.has('polyline'), s.has('curve'), s.has('gap')]),
    ).toEqual([
      [false, false, false, false],
      [true, false, false, false],
      [true, true, false, false],
      [true, true, true, false],
      [true, true, true, true],
    ]);
  });

  it('subdivides the hairpin from its root: flatness 6·5/8 · ‖(−14, −18)‖ = 85.51 px > τ', () => {
    const at = (step: number) => sceneAt('subdivide', step);
    const m = derive(at(0));
    // One press per piece looked at (17 of them, fewer than 20), the last one "done".
    expect(m.tree).toHaveLength(17);
    expect(steps(at(0))).toBe(17);
    expect(formula(at(0))).toBe(
      '\\tfrac{n(n-1)}{8}\\max_i \\|P_{i+2} - 2P_{i+1} + P_i\\| \\le \\tau = 0.50',
    );
    expect(caption(at(1))).toBe(
      'Piece t ∈ [0, 1]: flatness 85.51 px > τ, so split it at its middle.',
    );
    expect(formula(at(1))).toBe('\\tfrac{6\\cdot5}{8}\\max\\|\\Delta^2 P\\| = 85.51\\ >\\ 0.50');
    expect(derive(at(1)).piecesShown).toBe(1);
    expect(caption(at(17))).toBe(
      'Done: 9 segments from 17 pieces looked at, halved at most 4 times.',
    );
    expect(derive(at(17)).piecesShown).toBe(17);
  });

  it('lights a line from pixel (0, 0) to (8, 3) one pixel per press: rows 0 0 1 1 2 2 2 3 3', () => {
    // A straight "curve" of degree 1 is its own single segment.
    const line = {
      points: [
        [0.5, 0.5],
        [8.5, 3.5],
      ],
    };
    const at = (step: number) => sceneAt('pixels', step, line);
    // The raster, the ends, 9 pixels, every segment.
    expect(steps(at(0))).toBe(11);
    expect(caption(at(0))).toBe('32 × 24 pixels and the 1 segment to draw on them.');
    expect(caption(at(1))).toBe('Segment 1: its ends rounded to the pixels (0, 0) and (8, 3).');
    expect(formula(at(1))).toBeNull();
    expect(caption(at(2))).toBe(
      'Step along x one pixel at a time, take the nearest row: 1 of 9 pixels, the last (0, 0).',
    );
    expect(formula(at(2))).toBe('x = 0:\\ y = 0.00 \\to 0');
    // At x = 3 the ideal line is at y = 9/8, nearest row 1.
    expect(formula(at(5))).toBe('x = 3:\\ y = 1.13 \\to 1');
    expect(formula(at(10))).toBe('x = 8:\\ y = 3.00 \\to 3');
    expect([2, 5, 10].map((step) => derive(at(step)).pixelsShown)).toEqual([1, 4, 9]);
    expect(caption(at(11))).toBe('Every segment drawn the same way: 9 pixels make the curve.');
    expect(formula(at(11))).toBeNull();
  });

  it('steps the hairpin’s most instructive segment, (17, 3) to (22, 4): y = 3 + (x − 17)/5', () => {
    const at = (step: number) => sceneAt('pixels', step);
    expect(caption(at(1))).toBe('Segment 3: its ends rounded to the pixels (17, 3) and (22, 4).');
    expect([2, 3, 4, 5, 6, 7].map((step) => formula(at(step)))).toEqual([
      'x = 17:\\ y = 3.00 \\to 3',
      'x = 18:\\ y = 3.20 \\to 3',
      'x = 19:\\ y = 3.40 \\to 3',
      'x = 20:\\ y = 3.60 \\to 4',
      'x = 21:\\ y = 3.80 \\to 4',
      'x = 22:\\ y = 4.00 \\to 4',
    ]);
  });

  it('anti-aliases in three steps, the share of a pixel the strip covers in the middle one', () => {
    const at = (step: number) => sceneAt('coverage', step);
    expect(steps(at(0))).toBe(2);
    expect(caption(at(0))).toBe('Anti-aliasing: draw segment 3 as a strip one pixel wide.');
    expect(formula(at(1))).toBe(
      '\\text{grey} = \\frac{\\text{area of pixel} \\cap \\text{strip}}{\\text{area of pixel}}',
    );
    expect(caption(at(2))).toMatch(
      /^The whole curve: \d+ pixels in shades instead of 41 on or off\.$/,
    );
  });

  it('zooms ×½ … ×8: the same 4 segments stray the same units, zoom times as many pixels', () => {
    const at = (step: number) => sceneAt('zoom', step);
    expect(steps(at(0))).toBe(4);
    const units = derive(at(0)).uniform.deviation.distance;
    const zooms = [0.5, 1, 2, 4, 8];
    zooms.forEach((zoom, step) => {
      expect(derive(at(step)).zoom!.size.zoom).toBe(zoom);
      const gap = (units * zoom).toFixed(2);
      expect(formula(at(step))).toBe(
        `${units.toFixed(3)}\\ \\text{units} \\times ${zoom} \\tfrac{\\text{px}}{\\text{unit}} = ${gap}\\ \\text{px}`,
      );
      expect(caption(at(step))).toContain(`4 segments stray ${gap} px`);
    });
    expect(caption(at(0))).toMatch(/^Zoom ×½, the curve on 16 × 12 pixels: /);
    expect(caption(at(4))).toMatch(/^Zoom ×8, the curve on 256 × 192 pixels: /);
  });

  it('compares uniform and adaptive: the bound ⌈√(85.51 / 0.5)⌉ = 14 segments', () => {
    const at = (step: number) => sceneAt('compare', step);
    expect(caption(at(4))).toBe(
      'Without measuring, uniform sampling must plan for the sharpest bend: 14 segments to be sure of τ; they stray 0.31 px.',
    );
    expect(formula(at(4))).toBe(
      'N = \\left\\lceil \\sqrt{\\frac{n(n-1)\\,\\max\\|\\Delta^2 P\\|}{8\\,\\tau}} \\right\\rceil = \\left\\lceil \\sqrt{\\frac{85.51}{0.50}} \\right\\rceil = 14',
    );
    expect([0, 1].map((step) => formula(at(step)))).toEqual([null, null]);
  });

  it('a clicker press computes nothing again: the same curve, flattening and pixels', () => {
    for (const id of ['plot', 'compare', 'subdivide', 'pixels', 'coverage']) {
      const [first, next] = [0, 1].map((step) => derive(sceneAt(id, step)));
      expect(next.curve, id).toBe(first.curve);
      expect(next.tree, id).toBe(first.tree);
      expect(next.pixels, id).toBe(first.pixels);
      expect(next.line, id).toBe(first.line);
      expect(next.gaps, id).toBe(first.gaps);
      expect(next.coverage, id).toBe(first.coverage);
    }
  });

  it('keeps the link’s short keys, in their order: a link from before opens the same picture', () => {
    expect(encodeState(schema, defaults)).toBe(
      'x=plot&p=2,3;9,3;16,3;23,3;30,3;31,21;18,21&n=6&tol=0.5&z=1&seg=0&step=0',
    );
    const { state, issues } = decodeState(
      schema,
      'x=pixels&p=1,1;5,5;9,1&n=3&tol=0.3&z=2&seg=1&step=3',
    );
    expect(issues).toEqual([]);
    expect(state).toEqual({
      view: 'pixels',
      points: [
        [1, 1],
        [5, 5],
        [9, 1],
      ],
      uniformSegments: 3,
      tolerance: 0.3,
      zoom: 2,
      steppedSegment: 1,
      step: 3,
    });
  });

  it('moves, adds and removes control points through one declared list, within 2 … 10', () => {
    const figure = lesson.figures.find((f) => f.id === curveFigure.id)!;
    const m = derive(defaults);
    expect(figure.handles!(m).map((h) => [h.id, h.label, h.small])).toEqual(
      defaults.points.map((_, i) => [`p${i}`, `P_{${i}}`, false]),
    );
    expect(figure.moveHandle!(defaults, 'p3', [7, 8], m).points[3]).toEqual([7, 8]);
    expect(figure.removeHandle!(defaults, 'p2', m)!.points).toHaveLength(6);
    expect(figure.addPoint!(defaults, [20, 10], m)!.points).toHaveLength(8);
    const two = { ...defaults, points: defaults.points.slice(0, 2) };
    expect(figure.removeHandle!(two, 'p0', derive(two))).toBeNull();
    // Outside the first scene the handles are small, to hide no pixel.
    expect(figure.handles!(derive(sceneAt('pixels', 0))).every((h) => h.small)).toBe(true);
  });
});
