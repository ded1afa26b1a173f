import { h, setChildren, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { notesKey } from '../../kit/notes';
import type { QuadraticModel } from './model';
import { parabolaSection } from './parabolaSection';
import { parametricSection } from './parametricSection';
import { rulesSection } from './rulesSection';
import { type Reveal, construction } from './script';
import type { QuadraticState } from './state';

/** What the lecturer says at each step, at more length than the caption. */
const STEP_TEXT: Record<Reveal, string> = {
  points:
    'Three points, and we want a smooth curve through them. Drag them, or step on to see the first idea.',
  parabola:
    'The first idea: a function y = a₂x² + a₁x + a₀, three unknowns for three points. Drag the points; put two of them above one another, or make them go backwards in x, and watch this idea fail. The μ₁ slider belongs to the next step.',
  parametric:
    'Make both coordinates functions of a parameter μ instead: P(μ) = a₂μ² + a₁μ + a₀ starts at P₀ (μ = 0) and ends at P₂ (μ = 1). Nothing says at which μ it should pass P₁: we choose that value, μ₁, with the slider.',
  ticks:
    'The dots sit at μ = 0, 0.1, …, 1, equal steps of the parameter: where they spread out, the point P(μ) moves fast, where they bunch up it moves slowly.',
  family:
    'The same three points give a different curve for every μ₁. With μ₁ small the curve hurries to P1 and then swings wide towards P2; with μ₁ near 1 it is the other way round. One set of points, many curves: the parameter values are part of the data.',
  rules:
    'So choose μ₁ from the points themselves. Uniform ignores the geometry; chord length gives each span its share of μ by its length; centripetal uses square roots of the lengths. Move P1 close to P0 and compare: chord length and centripetal give the natural curve, uniform overshoots.',
};

export function quadraticPanel(
  api: LessonApi<QuadraticState, QuadraticModel>,
): LessonPanel<QuadraticState, QuadraticModel> {
  const stepTitle = h('h2', {});
  const stepText = h('p', {});
  const parabola = parabolaSection();
  const parametric = parametricSection();
  const rules = rulesSection(api);
  const higher = h(
    'section',
    {},
    h('h2', {}, 'Why not just go to a higher degree?'),
    h(
      'p',
      {},
      'Three points, degree 2. Four points need a cubic, n + 1 points a polynomial of degree n, and one polynomial through many points wiggles more and more between them. ',
      h(
        'a',
        { href: '#/lagrange' },
        'See it in the next lesson: one polynomial through n + 1 points',
      ),
      '.',
    ),
  );
  const parameterNote = h(
    'p',
    { class: 'note' },
    'The curve’s parameter is μ, from 0 at P₀ to 1 at P₂; the slider sets μ₁, the value of μ at which the curve passes P₁.',
  );
  // How the lesson's symbols read in the notes (the parameter's row is the kit's).
  const symbols = notesKey([
    ['P₀, P₁, P₂', 'the same in the lecture notes'],
    [
      'a₀, a₁, a₂',
      'P = a₂μ² + a₁μ + a₀ in the lecture notes; a, b, c in y = a + bp + cp², the lecture slides’ quadratic splines (the road lesson)',
    ],
    ['μ₁', 'the parameter at P₁: the lecture notes choose ½ there (their equation 3)'],
  ]);
  const element = h('div', { class: 'lesson-text' });
  // The section each step is about comes first, under the step's text.
  const leading: Record<Reveal, HTMLElement> = {
    points: parabola.element,
    parabola: parabola.element,
    parametric: parametric.element,
    ticks: parametric.element,
    family: parametric.element,
    rules: rules.element,
  };
  let shownStep: Reveal | null = null;

  return {
    element,
    update(m, state) {
      const { shown } = m;
      if (shown.name !== shownStep) {
        shownStep = shown.name;
        setText(stepText, STEP_TEXT[shown.name]);
        const first = leading[shown.name];
        const rest = [parabola.element, parametric.element, rules.element].filter(
          (section) => section !== first,
        );
        setChildren(element, parameterNote, stepTitle, stepText, first, ...rest, higher, symbols);
      }
      setText(
        stepTitle,
        `Step ${shown.k} of ${shown.lastStep}: ${construction.caption(state, m, shown.k)}`,
      );
      parabola.update(m);
      parametric.update(m);
      rules.update(m);
    },
  };
}
