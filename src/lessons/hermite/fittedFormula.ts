import { markForFit } from '../../render/fit';
import { LiveFormula } from '../../render/formula';
import type { FormulaParts } from '../../render/formulaParts';

/**
 * A display LiveFormula fitted to the panel again whenever its numbers
 * change, not only when its shape is typeset: numbers that grow can push a
 * matrix past the panel's edge, and the first fit may have been measured
 * before KaTeX's fonts arrived. (The shell fits at the start of the next
 * frame, on a clean layout, so this costs one read of the formula's width.)
 */
export class FittedFormula extends LiveFormula {
  private shown = '';

  constructor() {
    super(true);
  }

  override set(shape: string | FormulaParts, values?: readonly string[]): void {
    super.set(shape, values);
    const parts = typeof shape === 'string' ? { shape, values: values ?? [] } : shape;
    const shown = `${parts.shape}|${parts.values.join('|')}`;
    if (shown === this.shown) return;
    this.shown = shown;
    markForFit(this.element);
  }
}
