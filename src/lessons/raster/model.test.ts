import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { chordDeviation, flattenBezier, rasterizeLine, uniformParameters } from '../../math';
import lesson from './lesson';
import { type RasterModel, SAME_ERROR_MAX, instructiveSegment } from './model';
import {
  LINE_LIMIT,
  coveragePolyline,
  curveNear,
  farPixels,
  lineSteps,
  rasterizePolyline,
} from './raster';
import { type RasterState, schema } from './state';
import { zoomAt } from './zoomView';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: RasterState) => lesson.derive(s) as RasterModel;
const scenes = lesson.scenes!;
const steps = lesson.steps!;
const stepCount = (s: RasterState) => steps.count(s);
const defaults = defaultsOf(schema);
const at = (change: Partial<RasterState>): RasterModel => derive({ ...defaults, ...change });
const raster = { zoom: 1, left: 0, bottom: 0, width: 32, height: 24 };

describe('raster lesson model', () => {
  it('opens on its first scene, and every scene starts at step 0', () => {
    expect(scenes[0].apply(defaults)).toEqual(defaults);
    for (const scene of scenes) expect(scene.apply(defaults).step).toBe(0);
    expect(scenes.map((s) => s.id)).toEqual([
      'plot',
      'compare',
      'subdivide',
      'pixels',
      'coverage',
      'zoom',
    ]);
  });

  it('adaptive flattening stays within τ with fewer segments than uniform sampling needs for the same gap', () => {
    for (const z of [0.5, 1, 2, 4]) {
      const m = at({ view: 'compare', zoom: z });
      expect(m.adaptive.points).toEqual(flattenBezier(defaults.points, 0.5 / z));
      expect(m.adaptive.deviation.distance * z).toBeLessThanOrEqual(0.5);
      const same = m.sameError!;
      expect(same.deviation.distance).toBeLessThanOrEqual(m.adaptive.deviation.distance);
      expect(m.adaptive.points.length).toBeLessThan(same.points.length);
      // One segment fewer is not enough for uniform sampling.
      const fewer = same.points.length - 2;
      const parameters = Array.from({ length: fewer + 1 }, (_, k) => k / fewer);
      expect(chordDeviation(defaults.points, parameters).distance).toBeGreaterThan(
        m.adaptive.deviation.distance,
      );
    }
  });

  it('the hairpin at zoom 1: 6 uniform segments stray more than τ, the bound plans for more than adaptive uses', () => {
    const m = at({ view: 'compare' });
    expect(m.uniform.points).toHaveLength(7);
    expect(m.uniform.deviation.distance).toBeGreaterThan(0.5);
    // The bound is the root piece's flatness: 6·5/8 · max‖Δ²P‖ = 30/8 · ‖P6 − 2P5 + P4‖ = 30/8 · ‖(−14, −18)‖.
    expect(m.tree[0].flatness).toBeCloseTo((30 / 8) * Math.hypot(14, 18), 12);
    expect(m.boundCount).toBe(Math.ceil(Math.sqrt(m.tree[0].flatness / 0.5)));
    expect(m.boundCount).toBeGreaterThan(m.adaptive.points.length - 1);
  });

  it('a line from pixel (0, 0) to (8, 3) steps along x, rows 0 0 1 1 2 2 2 3 3 (a tie rounds up)', () => {
    const line = lineSteps([0.5, 0.5], [8.5, 3.5], 1);
    expect(line.major).toBe('x');
    expect(line.pixels).toEqual(
      [0, 1, 2, 3, 4, 5, 6, 7, 8].map((x, k) => [x, [0, 0, 1, 1, 2, 2, 2, 3, 3][k]]),
    );
    expect(line.ideal).toEqual([0, 3 / 8, 6 / 8, 9 / 8, 12 / 8, 15 / 8, 18 / 8, 21 / 8, 3]);
    // At zoom 2 the same segment is twice as many pixels.
    expect(lineSteps([0.5, 0.5], [8.5, 3.5], 2).pixels).toHaveLength(17);
  });

  it('pixels off the raster are not lit; a level line through pixel centres is fully covered, half at its butt ends', () => {
    const lit = rasterizePolyline(
      [
        [-3.5, 2.5],
        [4.5, 2.5],
      ],
      raster,
    );
    expect([...lit.keys()]).toEqual(['0,2', '1,2', '2,2', '3,2', '4,2']);
    const covered = coveragePolyline(
      [
        [1.5, 2.5],
        [4.5, 2.5],
      ],
      raster,
    );
    expect([...covered.values()].map((p) => [p.i, p.j, p.value])).toEqual([
      [1, 2, 0.5],
      [2, 2, 1],
      [3, 2, 1],
      [4, 2, 0.5],
    ]);
  });

  it('pixels more than a pixel from the curve are counted as wrong', () => {
    const lit = rasterizePolyline(
      [
        [0.5, 0.5],
        [6.5, 0.5],
      ],
      raster,
    );
    // The "curve" one and two pixels above: none of the row is within 1 px of the higher one.
    expect(
      farPixels(
        lit,
        [
          [
            [0.5, 1.5],
            [6.5, 1.5],
          ],
        ],
        1,
      ),
    ).toHaveLength(0);
    expect(
      farPixels(
        lit,
        [
          [
            [0.5, 2.6],
            [6.5, 2.6],
          ],
        ],
        1,
      ),
    ).toHaveLength(7);
  });

  it('zoom steps ½ to 8: the screen is 32 × 24 pixels of 1/z units, the error grows with z, adaptive adds segments', () => {
    // Steps 0 … 4 are the zoom scene's presses 1 … 5.
    expect([1, 2, 3, 4, 5].map(zoomAt)).toEqual([0.5, 1, 2, 4, 8]);
    const views = [0, 1, 2, 3, 4].map(
      (step) => at({ view: 'zoom', uniformSegments: 4, step }).zoom!,
    );
    expect(views.map((v) => [v.full.width, v.full.height])).toEqual([
      [16, 12],
      [32, 24],
      [64, 48],
      [128, 96],
      [256, 192],
    ]);
    for (const v of views) expect([v.size.width, v.size.height]).toEqual([32, 24]);
    const counts = views.map((v) => v.adaptive.length);
    for (let k = 1; k < counts.length; k++) expect(counts[k]).toBeGreaterThanOrEqual(counts[k - 1]);
    expect(views[0].uniformFar).toHaveLength(0);
    expect(views[4].uniformFar.length).toBeGreaterThan(0);
    expect(views[4].adaptiveFar.length).toBeLessThan(views[4].uniformFar.length);
  });

  it('steps: the pixel scene lights the chosen segment in at most 12 clicks; every caption is one sentence with numbers', () => {
    const pixels = scenes[3].apply(defaults);
    const m = derive(pixels);
    expect(pixels.steppedSegment).toBe(instructiveSegment(m.adaptive.points, 1));
    expect(stepCount(pixels)).toBe(2 + Math.min(12, m.line.pixels.length));
    for (const scene of scenes) {
      const state = scene.apply(defaults);
      for (let k = 0; k <= stepCount(state); k++) {
        const text = steps.describe({ ...state, step: k }, k);
        expect(text.length).toBeGreaterThan(20);
        expect(text).not.toMatch(/NaN|undefined|\\/);
      }
    }
  });

  it('at zoom 16 and τ = 0.05 px the same-gap count reaches the adaptive gap and one fewer does not', () => {
    const m = at({ view: 'compare', zoom: 16, tolerance: 0.05 });
    const gap = m.adaptive.deviation.distance;
    const count = m.sameError!.points.length - 1;
    expect(count).toBeLessThanOrEqual(SAME_ERROR_MAX);
    expect(m.sameErrorBeyond).toBe(false);
    expect(chordDeviation(defaults.points, uniformParameters(count)).distance).toBeLessThanOrEqual(
      gap,
    );
    expect(chordDeviation(defaults.points, uniformParameters(count - 1)).distance).toBeGreaterThan(
      gap,
    );
  });

  it('past 512 uniform segments the compare scene says "more than 512" instead of searching on', () => {
    // A parabola 2000 units wide: P″ = 2·(P2 − 2P1 + P0) = (0, −8000), so a piece of 1/n
    // in t sags 8000/(8n²) = 1000/n² vertically: 0.0038 for n = 512, more than τ = 0.05/16.
    const p = [
      [0, 0],
      [1000, 2000],
      [2000, 0],
    ];
    const m = at({ view: 'compare', points: p, zoom: 16, tolerance: 0.05 });
    const gap = m.adaptive.deviation.distance;
    expect(m.sameErrorBeyond).toBe(true);
    expect(m.sameError).toBeNull();
    expect(chordDeviation(p, uniformParameters(SAME_ERROR_MAX)).distance).toBeGreaterThan(gap);
    expect(steps.describe({ ...m.state, step: 3 }, 3)).toContain(
      `more than ${SAME_ERROR_MAX} segments`,
    );
  });

  it('a segment a million pixels long: all its pixels on the raster, the first 512 listed, and its count', () => {
    const a = [0.5, 0.5];
    const b = [1_000_000.5, 300_000.5];
    // Pixel coordinates (0, 0) to (1 000 000, 300 000): one pixel per x, 1 000 001 of them.
    const line = lineSteps(a, b, 1);
    expect(line.count).toBe(1_000_001);
    expect(line.pixels).toHaveLength(LINE_LIMIT);
    expect(line.first).toEqual([0, 0]);
    expect(line.last).toEqual([1_000_000, 300_000]);
    // The first pixels of the whole line, and y = 0.3x at each.
    expect(line.pixels).toEqual(rasterizeLine(0, 0, 1_000_000, 300_000).slice(0, LINE_LIMIT));
    line.ideal.forEach((y, k) => expect(y).toBeCloseTo(0.3 * k, 9));
    // On the 32 × 24 raster it lights x = 0 … 31, y = ⌊0.3x + ½⌋ (up to 9).
    const lit = rasterizePolyline([a, b], raster);
    expect([...lit.values()].map(({ i, j }) => [i, j])).toEqual(
      Array.from({ length: 32 }, (_, x) => [x, Math.floor(0.3 * x + 0.5)]),
    );
  });

  it('the curve near a window is the flattened curve where it passes the window, and nothing far away', () => {
    // The parabola (0,0), (1,2), (2,0): y = 4t(1 − t), x = 2t, its top (1, 1) at t = ½.
    const parabola = [
      [0, 0],
      [1, 2],
      [2, 0],
    ];
    const paths = curveNear(parabola, { minX: 0.9, minY: 0.9, maxX: 1.1, maxY: 1.1 }, 0.05, 1e-3);
    const all = paths.flat();
    expect(all.length).toBeGreaterThan(0);
    // Every vertex is on the curve (y = x(2 − x)) and near the window; the top is in one piece.
    for (const [x, y] of all) {
      expect(y).toBeCloseTo(x * (2 - x), 12);
      expect(Math.abs(x - 1)).toBeLessThan(0.6);
    }
    expect(all.some(([x]) => x <= 0.9) && all.some(([x]) => x >= 1.1)).toBe(true);
    expect(curveNear(parabola, { minX: 5, minY: 5, maxX: 6, maxY: 6 }, 0.1, 1e-3)).toEqual([]);
  });

  it('the coverage scene keeps the stepped segment’s shaded pixels in the model, each at most the whole curve’s shade', () => {
    const m = derive(scenes[4].apply(defaults));
    const pixels = m.segmentCoverage!;
    expect(pixels.length).toBeGreaterThan(0);
    for (const { i, j, value } of pixels) {
      expect(value).toBeGreaterThan(0);
      expect(value).toBeLessThanOrEqual(m.coverage!.get(`${i},${j}`)!.value);
    }
    expect(at({ view: 'pixels' }).segmentCoverage).toBeNull();
  });
});
