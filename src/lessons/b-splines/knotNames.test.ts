import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import { sceneStep } from '../../../tests/sceneStep';
import lesson from './lesson';

// A 1366 × 768 projector: the knot strip is 476 × 138 px. "Clamped ends" has
// 7 points of degree 3, so 7 + 3 + 1 = 11 knots, u₀ … u₁₀: four equal at each
// end (p + 1 = 4) and u₄, u₅, u₆ between. In one row of names under the line,
// u₄ and the right end's u₇…₁₀ ×4 (what the step is about) went unnamed.
describe('the knot strip of the clamped ends on a 1366 projector', () => {
  it('names every run of knots, inside the strip, no name on another', () => {
    const { figure, model } = sceneStep(lesson, 'clamped', 'knots');
    const { painter } = drawHeadless(figure, model, {
      width: 476,
      height: 138,
      theme: makeTheme(false, true),
    });
    const names = painter.labels.filter((l) => l.text.startsWith('u_'));
    expect(names.map((l) => l.text).sort()).toEqual(
      ['u_{0…3} ×4', 'u_{4}', 'u_{5}', 'u_{6}', 'u_{7…10} ×4'].sort(),
    );
    const boxes = names.map(glyphBox);
    for (const [i, a] of boxes.entries()) {
      expect(a.x, names[i].text).toBeGreaterThanOrEqual(0);
      expect(a.x + a.width, names[i].text).toBeLessThanOrEqual(476);
      for (const b of boxes.slice(i + 1))
        expect(
          a.x + a.width <= b.x ||
            b.x + b.width <= a.x ||
            a.y + a.height <= b.y ||
            b.y + b.height <= a.y,
          `${names[i].text} clear of the others`,
        ).toBe(true);
    }
  });
});
