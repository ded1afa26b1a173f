import { h } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { formula } from '../../render/formula';
import { notesKey } from '../../kit/notes';
import { NOTES_KEY } from './notesKey';
import { compareSection } from './compareSection';
import { formsSection } from './formsSection';
import type { BlendingModel } from './model';
import { controlPoints } from './points';
import type { BlendingState } from './state';
import { weightsSection } from './weightsSection';
import { capital, gestures } from '../../kit/gestures';

export function blendingPanel(
  api: LessonApi<BlendingState, BlendingModel>,
): LessonPanel<BlendingState, BlendingModel> {
  const pointCount = controlPoints.buttons(api);
  const weights = weightsSection(api);
  const forms = formsSection();
  const compare = compareSection(api);

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'Every point of a Bézier curve is a weighted average of its control points. The weights are the blending functions W(N, i, μ): as μ runs from 0 to 1 the weight moves from P0 to PN, and the point follows. In this lesson the parameter is μ, from 0 to 1.',
    ),
    formula('P(\\mu) = \\sum_{i=0}^{N} W(N,i,\\mu)\\,P_i', true),
    formula('W(N,i,\\mu) = \\binom{N}{i}\\mu^{i}(1-\\mu)^{N-i}', true),
    notesKey(NOTES_KEY),
    h(
      'p',
      { class: 'note' },
      `Drag the cursor on the plot, or the μ slider. ${capital(gestures().point)} a curve of the plot or a row of the table to find its control point. To add a point, ${gestures().add}; to remove one, ${gestures().remove}.`,
    ),
    pointCount.element,
    ...weights.elements,
    ...forms.elements,
    compare.element,
  );

  return {
    element,
    update(m, state) {
      pointCount.update(state);
      weights.update(m);
      forms.update(m);
      compare.update(m);
    },
    hover(id) {
      weights.hover(id);
      compare.hover(id);
    },
  };
}
