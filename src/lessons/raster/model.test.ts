import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { chordDeviation, flattenBezier } from '../../math';
import { type RasterModel, derive, instructiveSegment, zoomAtStep } from './model';
import { coveragePolyline, farPixels, lineSteps, rasterizePolyline } from './raster';
import { scenes, stepCount, steps } from './script';
import { type RasterState, schema } from './state';

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
      const m = at({ x: 'compare', z });
      expect(m.adaptive.points).toEqual(flattenBezier(defaults.p, 0.5 / z));
      expect(m.adaptive.deviation.distance * z).toBeLessThanOrEqual(0.5);
      const same = m.sameError!;
      expect(same.deviation.distance).toBeLessThanOrEqual(m.adaptive.deviation.distance);
      expect(m.adaptive.points.length).toBeLessThan(same.points.length);
      // One segment fewer is not enough for uniform sampling.
      const fewer = same.points.length - 2;
      const parameters = Array.from({ length: fewer + 1 }, (_, k) => k / fewer);
      expect(chordDeviation(defaults.p, parameters).distance).toBeGreaterThan(
        m.adaptive.deviation.distance,
      );
    }
  });

  it('the hairpin at zoom 1: 6 uniform segments stray more than τ, the bound plans for more than adaptive uses', () => {
    const m = at({ x: 'compare' });
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
    expect([0, 1, 2, 3, 4].map(zoomAtStep)).toEqual([0.5, 1, 2, 4, 8]);
    const views = [0, 1, 2, 3, 4].map((step) => at({ x: 'zoom', n: 4, step }).zoom!);
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
    expect(pixels.seg).toBe(instructiveSegment(m.adaptive.points, 1));
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
});
