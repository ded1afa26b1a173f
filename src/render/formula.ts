import katex from 'katex';
import 'katex/dist/katex.min.css';
import { markForFit } from './fit';

/**
 * Typesets TeX into `el` with the bundled KaTeX (no CDN). The TeX is built by
 * the lessons from numbers they computed; KaTeX builds DOM nodes, not markup.
 */
export function renderFormula(el: HTMLElement, tex: string, display = false): void {
  if (el.dataset.tex === tex) return;
  el.dataset.tex = tex;
  katex.render(tex, el, { displayMode: display, throwOnError: false, output: 'htmlAndMathml' });
  if (display) markForFit(el);
}

/** A new element holding a typeset formula. */
export function formula(tex: string, display = false): HTMLElement {
  const el = document.createElement(display ? 'div' : 'span');
  el.className = display ? 'formula display' : 'formula';
  renderFormula(el, tex, display);
  return el;
}

/** A number as TeX: fixed digits, no "-0". */
export function texNumber(value: number, digits = 2): string {
  const text = value.toFixed(digits);
  return /^-0\.?0*$/.test(text) ? text.slice(1) : text;
}

export function texPoint(p: readonly number[], digits = 2): string {
  return `(${p.map((v) => texNumber(v, digits)).join(',\\ ')})`;
}
