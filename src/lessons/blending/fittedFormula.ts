import { markForFit } from '../../render/fit';
import { LiveFormula } from '../../render/formula';

/**
 * A display LiveFormula fitted to the panel again whenever its numbers take
 * another width (a sign or a digit more or fewer; KaTeX's digits are all
 * equally wide, so only that pattern matters). LiveFormula itself asks for a
 * fit only when it typesets a new shape, so a matrix whose numbers grow would
 * run past the panel's edge.
 */
export class FittedFormula extends LiveFormula {
  private pattern = '';

  constructor() {
    super(true);
  }

  override set(shape: string, values: readonly string[]): void {
    super.set(shape, values);
    const pattern = `${shape}|${values.join('|').replace(/\d/g, '0')}`;
    if (pattern === this.pattern) return;
    this.pattern = pattern;
    markForFit(this.element);
  }
}
