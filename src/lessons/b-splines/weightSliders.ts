import { h, setChildren, setText } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { trimmed } from '../../kit/format';
import { WEIGHT_MAX, WEIGHT_MIN } from './halo';
import type { BSplineModel } from './model';
import type { BSplineState } from './state';

/** One line per weight: name, slider, value. */
const ROW = 'display: grid; grid-template-columns: 2.5em 1fr 4em; gap: 0.5em; align-items: center';

/** A slider per weight (WEIGHT_MIN … WEIGHT_MAX, as a halo drag), with its value written beside it. */
export function weightSliders(api: LessonApi<BSplineState, BSplineModel>) {
  const list = h('div', { class: 'weights' });
  const element = h('div', {}, h('h2', {}, 'Weights'), list);
  let inputs: HTMLInputElement[] = [];
  let outputs: HTMLElement[] = [];
  let count = -1;
  return {
    element,
    update(state: BSplineState) {
      if (state.weights.length !== count) {
        count = state.weights.length;
        inputs = state.weights.map((_, i) => {
          const input = h('input', {
            type: 'range',
            min: String(WEIGHT_MIN),
            max: String(WEIGHT_MAX),
            step: '0.01',
            'aria-label': `w${i}`,
          });
          input.addEventListener('input', () => {
            const s = api.get();
            const weights = s.weights.map((v, k) => (k === i ? Number(input.value) : v));
            api.set({ ...s, weights }, { coalesce: `weight-${i}` });
          });
          return input;
        });
        outputs = state.weights.map(() => h('output', {}));
        setChildren(
          list,
          inputs.map((input, i) =>
            h('label', { class: 'weight-row', style: ROW }, `w${i}`, input, outputs[i]),
          ),
        );
      }
      state.weights.forEach((w, i) => {
        if (Number(inputs[i].value) !== w) inputs[i].value = String(w);
        setText(outputs[i], trimmed(w, 4));
      });
    },
  };
}
