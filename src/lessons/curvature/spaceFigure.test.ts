import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import lesson from './lesson';
import type { CurvatureModel } from './model';
import { spaceFigure } from './spaceFigure';
import { type CurvatureState, schema } from './state';

describe('the curve in space is fitted with its osculating circle', () => {
  it('at the plane scene’s first step, the circle its last step shows is inside the fitted box', () => {
    const first = { ...defaultsOf(schema), step: 0 } as CurvatureState;
    const m = lesson.derive(first) as CurvatureModel;
    expect(m.space.circle.length).toBeGreaterThan(0);
    const box = spaceFigure.bounds(m);
    for (const [x, y] of m.space.circle) {
      expect(x).toBeGreaterThanOrEqual(box.minX - 1e-9);
      expect(x).toBeLessThanOrEqual(box.maxX + 1e-9);
      expect(y).toBeGreaterThanOrEqual(box.minY - 1e-9);
      expect(y).toBeLessThanOrEqual(box.maxY + 1e-9);
    }
  });
});
