import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { sameFrom, sameFromSamePicture } from '../../../tests/drawnFrom';
import lesson from './lesson';
import { type BlendingState, schema } from './state';

describe('the curve figure, drawn from its state', () => {
  it('draws the same picture whenever it is drawn from the same values, and skips μ until a step uses it', () => {
    const { skipped, used } = sameFromSamePicture(
      lesson,
      'curve',
      (state) => [
        { ...state, mu: 0.3 },
        { ...state, mu: 0.65 },
      ],
      true,
    );
    // The cubic's first steps (the points, their polygon) draw nothing at μ.
    expect(skipped).toBeGreaterThanOrEqual(2);
    expect(used).toBeGreaterThan(skipped);
  });

  it('is drawn again when the points, the comparison or the step change', () => {
    const figure = lesson.figures.find((f) => f.id === 'curve')!;
    const state = { ...(defaultsOf(schema) as BlendingState), step: 0 };
    const from = figure.drawnFrom!(lesson.derive(state));
    const p = state.p.map((q) => [...q] as [number, number]);
    p[1][1] += 0.5;
    for (const change of [
      { p },
      { step: 1 },
      { comparison: 'hermite' },
    ] as Partial<BlendingState>[]) {
      const other = figure.drawnFrom!(lesson.derive({ ...state, ...change }));
      expect(sameFrom(other, from), JSON.stringify(Object.keys(change))).toBe(false);
    }
  });
});
