import { describe, expect, it } from 'vitest';
import { drawHeadless } from '../../app/headless';
import { glyphBox } from '../../render/labels';
import { makeTheme } from '../../render/theme';
import { sceneStep } from '../../../tests/sceneStep';
import lesson from './lesson';

// Presenter view's curve figure (1228 × 820 px) at the last step of "Repeated
// knots": P(u) sits on the curve's crest under P₁P₂, where the name's first
// place is crossed. Shifted by its own width it stood by the polygon, 60 px
// from its point; it must stay beside the point it names.
describe('the name of P(u)', () => {
  it('stays beside its point', () => {
    const { figure, model } = sceneStep(lesson, 'repeated', 'curve');
    const theme = makeTheme(false, true);
    const { painter, view } = drawHeadless(figure, model, { width: 1228, height: 820, theme });
    const name = painter.labels.find((l) => l.text === 'P(u)');
    expect(name).toBeDefined();
    const box = glyphBox(name!);
    const [x, y] = view.toScreen(model.point);
    const gap = Math.hypot(
      Math.max(box.x - x, 0, x - box.x - box.width),
      Math.max(box.y - y, 0, y - box.y - box.height),
    );
    expect(gap).toBeLessThanOrEqual(theme.sizes.label);
  });
});
