import { LiveFormula, SLOT } from '../../render/formula';
import type { FormulaParts } from './formulaParts';

// Writes to the panel that happen only when the value shown changes, so a
// state change touches the few nodes whose text, visibility or style moved.

export function setText(element: HTMLElement, text: string): void {
  if (element.textContent !== text) element.textContent = text;
}

export function setHidden(element: HTMLElement, hidden: boolean): void {
  if (element.hidden !== hidden) element.hidden = hidden;
}

const MATHML = 'http://www.w3.org/1998/Math/MathML';

/**
 * A LiveFormula that keeps its TeX. KaTeX puts the TeX it typeset into the
 * MathML as an annotation (for "copy as TeX", and read by the browser tests);
 * LiveFormula drops it, since its TeX has slots. This one writes it back with
 * the numbers filled in.
 */
export class AnnotatedFormula {
  readonly element: HTMLElement;
  private readonly live: LiveFormula;
  private tex = '';

  constructor(display = false) {
    this.live = new LiveFormula(display);
    this.element = this.live.element;
  }

  set({ shape, values }: FormulaParts): void {
    this.live.set(shape, values);
    const semantics = this.element.querySelector('semantics');
    if (!semantics) return;
    let annotation = semantics.querySelector('annotation');
    if (!annotation) {
      // A new shape was typeset: a new MathML tree without one.
      annotation = document.createElementNS(MATHML, 'annotation');
      annotation.setAttribute('encoding', 'application/x-tex');
      semantics.append(annotation);
      this.tex = '';
    }
    const tex = shape.split(SLOT).reduce((filled, part, i) => filled + values[i - 1] + part);
    if (tex !== this.tex) annotation.textContent = this.tex = tex;
  }
}
