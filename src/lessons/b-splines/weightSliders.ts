import { h, setChildren } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { type RangeField, rangeField } from '../../app/rangeControls';
import { sub, trimmed } from '../../kit/format';
import { WEIGHT_MAX, WEIGHT_MIN } from './halo';
import type { BSplineModel } from './model';
import type { BSplineState } from './state';

/** A slider per weight (WEIGHT_MIN … WEIGHT_MAX, as a halo drag), with its value written beside it. */
export function weightSliders(api: LessonApi<BSplineState, BSplineModel>) {
  const list = h('div', { class: 'weights' });
  const element = h('div', {}, h('h2', {}, 'Weights'), list);
  let rows: RangeField<BSplineState>[] = [];
  return {
    element,
    update(state: BSplineState) {
      if (state.weights.length !== rows.length) {
        rows = state.weights.map((_, i) =>
          rangeField(api, {
            label: `w${i}`,
            name: `w${sub(i)}`,
            min: WEIGHT_MIN,
            max: WEIGHT_MAX,
            step: 0.01,
            get: (s) => s.weights[i],
            set: (s, w) => ({ ...s, weights: s.weights.map((v, k) => (k === i ? w : v)) }),
            coalesce: `weight-${i}`,
            readout: true,
            readoutEm: 2.5,
          }),
        );
        setChildren(
          list,
          rows.map((row) => row.element),
        );
      }
      rows.forEach((row, i) => row.update(state, trimmed(state.weights[i], 4)));
    },
  };
}
