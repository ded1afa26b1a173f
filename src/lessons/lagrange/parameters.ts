/**
 * The node parameters t_k of the Lagrange polynomial: equally spaced, or by
 * chord length when the points allow it.
 */
import { parameterValues } from '../../math';
import type { LagrangeModel } from './model';
import type { LagrangeState } from './state';

/** What the parameters (and the polynomial) are computed from: the points and the spacing. */
export type Nodes = Pick<LagrangeState, 'points' | 'spacing'>;

/** t_k by the chosen spacing; chord length with two equal neighbours falls back to uniform. */
export function parameters({ points, spacing }: Nodes): Pick<LagrangeModel, 'ts' | 'collapsed'> {
  if (spacing === 'chord') {
    const ts = parameterValues(points, 1);
    for (let k = 1; k < ts.length; k++) {
      // Equal values: no polynomial can be at two places at one t.
      if (ts[k] === ts[k - 1]) return { ts: parameterValues(points, 0), collapsed: [k - 1, k] };
    }
    return { ts, collapsed: null };
  }
  return { ts: parameterValues(points, 0), collapsed: null };
}
