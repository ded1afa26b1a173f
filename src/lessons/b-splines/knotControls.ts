import { h, setDisabled, setText } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { clampedUniformKnots } from '../../math';
import type { BSplineModel } from './model';
import { scriptOf } from './scripts';
import { type BSplineState, MAX_DEGREE, isClamped } from './state';

/**
 * Clamped knots whose middle p inner knots are stacked on one value (the curve
 * then passes through a control point there, with a kink). Too few inner knots: just clamped.
 */
export function repeatedKnots(n: number, p: number): number[] {
  const knots = clampedUniformKnots(n, p);
  const inner = n - p - 1;
  if (inner < p) return knots;
  const first = p + 1 + Math.floor((inner - p) / 2);
  for (let j = first + 1; j < first + p; j++) knots[j] = knots[first];
  return knots;
}

/** Uniform knots 0, 1, …, n + p. */
export const uniformKnotVector = (n: number, p: number) =>
  Array.from({ length: n + p + 1 }, (_, j) => j);

/** Degree and knot-vector buttons of the general B-spline. */
export function knotControls(api: LessonApi<BSplineState, BSplineModel>) {
  const button = (label: string, change: (s: BSplineState) => BSplineState | null) => {
    const b = h('button', { type: 'button' }, label);
    b.addEventListener('click', () => {
      const next = change(api.get());
      if (next) api.set(next);
    });
    return b;
  };
  const degree = h('span', { 'aria-live': 'polite' });
  const withDegree = (s: BSplineState, degree: number) => {
    if (degree < 1 || degree > MAX_DEGREE || degree > s.points.length - 1) return null;
    const n = s.points.length;
    const knots = isClamped(s.knots, s.degree)
      ? clampedUniformKnots(n, degree)
      : uniformKnotVector(n, degree);
    const next = { ...s, degree, knots };
    // A row fewer to step through: the step stays within the scene's script.
    return { ...next, step: Math.min(s.step, scriptOf(next).lastStep(next)) };
  };
  const lower = button('Degree − 1', (s) => withDegree(s, s.degree - 1));
  const raise = button('Degree + 1', (s) => withDegree(s, s.degree + 1));
  const element = h(
    'div',
    {},
    h('h2', {}, 'Degree and knots'),
    h('div', { class: 'lesson-tools' }, lower, degree, raise),
    h(
      'div',
      { class: 'lesson-tools' },
      button('Make the knots uniform', (s) => ({
        ...s,
        knots: uniformKnotVector(s.points.length, s.degree),
      })),
      button('Clamp the ends', (s) => ({
        ...s,
        knots: clampedUniformKnots(s.points.length, s.degree),
      })),
      button('Repeat a knot p times', (s) => ({
        ...s,
        knots: repeatedKnots(s.points.length, s.degree),
      })),
    ),
  );
  return {
    element,
    update(state: BSplineState) {
      setText(degree, `degree p = ${state.degree}`);
      setDisabled(lower, state.degree <= 1);
      setDisabled(raise, state.degree >= Math.min(MAX_DEGREE, state.points.length - 1));
    },
  };
}
