import { h, setChildren, setHidden } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { segmentIds } from './ids';
import type { BSplineModel } from './model';
import { segmentName } from './notation';
import { type BSplineState, isUniformPart } from './state';

/** One button per segment: hover or focus it to see its four control points (the keyboard's hover). */
export function segmentButtons(api: LessonApi<BSplineState, BSplineModel>) {
  const list = h('div', { class: 'lesson-tools', role: 'group', 'aria-label': 'Segments' });
  const element = h('div', {}, h('h2', {}, 'Segments'), list);
  let buttons: HTMLButtonElement[] = [];
  let key = '';
  return {
    element,
    update(m: BSplineModel, state: BSplineState) {
      setHidden(element, !isUniformPart(state.part));
      const next = `${state.part}:${m.segments.length}:${state.points.length}`;
      if (next === key) return;
      key = next;
      buttons = m.segments.map((segment, i) => {
        const first = segment.points[0];
        const last = segment.points[segment.points.length - 1];
        const button = h('button', { type: 'button' }, `${segmentName(i)}: P${first} … P${last}`);
        button.style.borderColor = api.theme().palette[i % api.theme().palette.length];
        const on = () => api.setHover(segmentIds.id(i));
        const off = () => api.setHover(null);
        button.addEventListener('mouseenter', on);
        button.addEventListener('focus', on);
        button.addEventListener('mouseleave', off);
        button.addEventListener('blur', off);
        return button;
      });
      setChildren(list, buttons);
    },
    hover(id: string | null) {
      buttons.forEach((button, i) => button.classList.toggle('current', id === segmentIds.id(i)));
    },
  };
}
