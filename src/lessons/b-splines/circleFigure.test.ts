import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import { sceneStep } from '../../../tests/sceneStep';
import lesson from './lesson';

// "The exact circle", last step: "with every weight 1 instead: not a circle".
// The plain B-spline of the same nine points is drawn round the circle, and
// unnamed it was one more dark ring: it is named where it strays farthest.
describe('the circle scene’s curve with every weight 1', () => {
  it('is named, beside its corner bulge (farther from the centre than the radius)', () => {
    const { figure, model } = sceneStep(lesson, 'circle', 'curve');
    const { painter, view } = drawHeadless(figure, model, {
      width: 862,
      height: 600,
      theme: makeTheme(false, true),
    });
    const name = painter.labels.find((l) => l.text === 'all w_{i} = 1');
    expect(name).toBeDefined();
    // The circle of the scene: centre (0, 0), radius 3 (its control square's
    // corners at (±3, ±3)); the name stands outside it.
    const box = glyphBox(name!);
    const [x, y] = view.toWorld([box.x + box.width / 2, box.y + box.height / 2]);
    expect(Math.hypot(x, y)).toBeGreaterThan(3);
  });
});
