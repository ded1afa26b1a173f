import { SLOT } from '../../render/formula';
import type { FormulaParts } from '../../render/formulaParts';

/** A decimal as the lesson writes it (texNumber, toExponential): never an index or a structural digit. */
const DECIMAL = /-?\d+\.\d+(?:e[-+]?\d+)?/g;

/**
 * A step formula's TeX as a LiveFormula's parts: every decimal becomes a live
 * number and the rest (indices, integers, layout) is the shape. Moving the
 * cursor or a point then writes numbers as text; only a new shape (another
 * segment, another step) typesets again.
 */
export function liveParts(tex: string): FormulaParts {
  const values: string[] = [];
  const shape = tex.replace(DECIMAL, (value) => {
    values.push(value);
    return SLOT;
  });
  return { shape, values };
}
