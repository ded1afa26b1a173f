import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { sameFrom, sameFromSamePicture } from '../../../tests/drawnFrom';
import lesson from './lesson';
import { type SurfaceState, schema } from './state';

describe('the patch in space, drawn from its state', () => {
  const figure = lesson.figures.find((f) => f.id === 'patch')!;

  it('draws the same picture whenever it is drawn from the same values, and skips u and v until a step uses them', () => {
    const { skipped, used } = sameFromSamePicture(lesson, 'patch', (state) => [
      { ...state, u: 0.3, v: 0.6 },
      { ...state, u: 0.55, v: 0.2 },
    ]);
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
      expect(sameFrom(other, from), JSON.stringify(Object.keys(change))).toBe(false);
    }
  });
});
