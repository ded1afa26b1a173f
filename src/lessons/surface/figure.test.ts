import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { defaultsOf } from '../../app/urlState';
import { makeTheme } from '../../render/theme';
import lesson from './lesson';
import { type SurfaceState, schema } from './state';

// The patch is not drawn again while what it is drawn from stays the same (a
// slider's drag before the step that draws P(u, v)): so the same must give the
// same picture, at every step of every scene.
describe('the patch in space, drawn from its state', () => {
  const figure = lesson.figures.find((f) => f.id === 'patch')!;
  const theme = makeTheme(false, false);
  const drawn = (state: SurfaceState) => {
    const model = lesson.derive(state);
    const { svg } = drawHeadless(figure, model, { width: 640, height: 480, theme });
    return { from: figure.drawnFrom!(model), svg: svg.toSvg(640, 480) };
  };

  it('draws the same picture whenever it is drawn from the same values, and skips u and v until a step uses them', () => {
    let skipped = 0;
    let used = 0;
    for (const scene of lesson.scenes!) {
      const start = scene.apply(defaultsOf(schema) as SurfaceState) as SurfaceState;
      for (let step = 0; step <= lesson.steps!.count(start); step++) {
        const state: SurfaceState = { ...start, step, u: 0.3, v: 0.6 };
        const a = drawn(state);
        const b = drawn({ ...state, u: 0.55, v: 0.2 });
        const same =
          a.from.length === b.from.length && a.from.every((x, i) => Object.is(x, b.from[i]));
        if (same) {
          skipped++;
          expect(b.svg, `${scene.id} step ${step}`).toBe(a.svg);
        } else used++;
      }
    }
    // The patch scene's first steps (the net, its corners, its edges) draw nothing at P(u, v).
    expect(skipped).toBeGreaterThanOrEqual(3);
    expect(used).toBeGreaterThan(skipped);
  });

  it('is drawn again when anything but u and v changes', () => {
    const state = { ...(defaultsOf(schema) as SurfaceState), step: 0 };
    const from = figure.drawnFrom!(lesson.derive(state));
    const net = state.net.map((row) => row.map((p) => [...p]));
    net[1][2][2] += 0.5;
    for (const change of [
      { net },
      { step: 1 },
      { look: state.look === 'shaded' ? 'lines' : 'shaded' },
      { coordinate: state.coordinate === 'z' ? 'x' : 'z' },
      { mode: 'rows' },
    ] as Partial<SurfaceState>[]) {
      const other = figure.drawnFrom!(lesson.derive({ ...state, ...change }));
      expect(
        other.length === from.length && other.every((x, i) => Object.is(x, from[i])),
        JSON.stringify(Object.keys(change)),
      ).toBe(false);
    }
  });
});
