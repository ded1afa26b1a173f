import { notesKey } from '../../kit/notes';
import { h, setAttr, setText } from '../../app/dom';
import type { LessonPanel } from '../../app/lesson';
import { affinePanel } from './affine/details';
import { closedPanel } from './closed/details';
import { cubicPanel } from './cubic/details';
import { elevatePanel } from './elevate/details';
import { endsPanel } from './ends/details';
import type { Details, ExperimentPanel, PanelApi } from './experimentPanel';
import { hermitePanel } from './hermite/details';
import { hodographPanel } from './hodograph/details';
import { hullPanel } from './hull/details';
import { localPanel } from './local/details';
import type { ModelOf, PropertiesModel } from './model';
import { repeatPanel } from './repeat/details';
import { splitPanel } from './split/details';
import type { ExperimentId, PropertiesState } from './state';
import { experimentTools } from './tools';
import { gestures } from '../../kit/gestures';

/** What the panel says about each experiment, in the order of the lesson's list of properties. */
const PANELS: { [X in ExperimentId]: ExperimentPanel<ModelOf<X>> } = {
  ends: endsPanel,
  hull: hullPanel,
  local: localPanel,
  repeat: repeatPanel,
  closed: closedPanel,
  elevate: elevatePanel,
  split: splitPanel,
  affine: affinePanel,
  cubic: cubicPanel,
  hermite: hermitePanel,
  hodograph: hodographPanel,
};

export function propertiesPanel(api: PanelApi): LessonPanel<PropertiesState, PropertiesModel> {
  const title = h('h2', {});
  const sentence = h('p', { class: 'experiment-sentence' });
  const details = h('div', { class: 'experiment-details', 'aria-live': 'off' });
  const tools = experimentTools(api);
  // Each experiment's details are built the first time it is shown, then kept.
  const built = new Map<ExperimentId, Details<PropertiesModel>>();
  const detailsOf = (x: ExperimentId) => {
    let made = built.get(x);
    if (!made) built.set(x, (made = PANELS[x].build(api)));
    return made;
  };
  let shownX: ExperimentId | null = null;
  let shownNodes: readonly Node[] = [];

  const element = h(
    'div',
    { class: 'lesson-text' },
    title,
    sentence,
    tools.elements,
    details,
    h(
      'p',
      { class: 'note' },
      `Each preset sets up one experiment. To move a control point, ${gestures().move}; t moves the point P(t) and, in subdivision, where the curve is split.`,
    ),
    notesKey([
      [
        'P₀, P₁, …, the control points',
        'P₀ … P₃ in the lecture notes; x₀ … xₙ in the continuation notes; p₀ … pₙ in the “Splines” slides',
      ],
      [
        'W(N, i, t)',
        'the blending functions of the lecture notes, Bᵢ(t) (Bernstein polynomials) in the continuation notes',
      ],
      ['P′(t)', 'P′(μ) in the lecture notes, ẋ in the practical (TP2)'],
    ]),
  );

  return {
    element,
    update(m, state) {
      if (state.experiment !== shownX) {
        shownX = state.experiment;
        const panel = PANELS[state.experiment];
        setText(title, `${panel.number}. ${panel.title}`);
        setText(sentence, panel.sentence);
      }
      tools.update(m, state);
      const nodes = detailsOf(m.kind).update(m);
      if (nodes !== shownNodes) {
        shownNodes = nodes;
        details.replaceChildren(...nodes);
      }
      setAttr(details, 'data-control-points', String(m.controls.length));
    },
  };
}
