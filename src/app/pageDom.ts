/**
 * The DOM of a lesson page: its head (the title and the tools), the stage
 * (the caption, the figures, the controls under them) and the side panel;
 * and what keeps that layout in step: the panel's width for its formulas,
 * the room above the stage on a phone, and focus given back after a click.
 */
import { type Child, h } from './dom';

export interface PageParts {
  readonly slug: string;
  readonly title: string;
  /** The lesson's tools beside its title. */
  readonly toolbar: HTMLElement;
  /** What stands in the stage, top to bottom: the caption and figures, then the controls. */
  readonly stage: readonly Child[];
  readonly controls: readonly Child[];
  /** What stands in the side panel, top to bottom. */
  readonly panel: readonly Child[];
  /** The panel's width changed (whole pixels): its formulas fit the new width. */
  panelResized(width: number): void;
}

export interface PageDom {
  readonly element: HTMLElement;
  /** Stops watching the layout. */
  stop(): void;
}

export function buildPageDom(parts: PageParts): PageDom {
  const stage = h(
    'section',
    { class: 'stage', 'aria-label': 'Figure' },
    ...parts.stage,
    h('div', { class: 'controls' }, ...parts.controls),
  );
  const aside = h('aside', { class: 'panel', 'aria-label': 'Explanation' }, ...parts.panel);
  const head = h('div', { class: 'lesson-head' }, h('h1', {}, parts.title), parts.toolbar);
  const element = h(
    'div',
    { class: 'lesson-page', 'data-lesson': parts.slug },
    head,
    h('div', { class: 'lesson-body' }, stage, aside),
  );
  // A control clicked with the pointer gives its focus back: the clicker's
  // arrows and Space then step the construction instead of ticking it again.
  element.addEventListener('click', (e) => {
    const target = document.activeElement;
    if (
      e.detail > 0 &&
      target instanceof HTMLElement &&
      element.contains(target) &&
      (target.tagName === 'BUTTON' ||
        (target instanceof HTMLInputElement && ['checkbox', 'radio'].includes(target.type)))
    )
      target.blur();
  });

  // Formulas fit the panel's width; its height follows its content, so only
  // a change of width may refit them (else fitting could feed itself).
  let panelWidth = -1;
  const panelResize = new ResizeObserver(([entry]) => {
    const width = Math.round(entry.contentRect.width);
    if (width !== panelWidth) {
      panelWidth = width;
      parts.panelResized(width);
    }
  });
  panelResize.observe(aside);
  // On a phone the stage fills the first screen under whatever stands above it.
  const aboveStage = new ResizeObserver(() => {
    const top = Math.round(stage.getBoundingClientRect().top + window.scrollY);
    if (top > 0) element.style.setProperty('--stage-top', `${top}px`);
  });
  for (const el of [document.querySelector('.top-bar'), document.querySelector('.notices')])
    if (el) aboveStage.observe(el);
  aboveStage.observe(head);
  return {
    element,
    stop: () => {
      panelResize.disconnect();
      aboveStage.disconnect();
    },
  };
}
