import { describe, expect, it } from 'vitest';
import { lagrangeBasis } from './lagrange';
import { lebesgueConstant } from './lebesgueConstant';

/** The Lagrange basis of the nodes ts at t = i / count, one interleaved [t, L_k(t), …] per node. */
function sampled(ts: number[], count: number): Float64Array[] {
  const curves = ts.map(() => new Float64Array(2 * (count + 1)));
  for (let i = 0; i <= count; i++) {
    lagrangeBasis(ts, i / count).forEach((value, k) => {
      curves[k][2 * i] = i / count;
      curves[k][2 * i + 1] = value;
    });
  }
  return curves;
}

describe('lebesgueConstant', () => {
  it('is 1 for a line: the weights 1 − t and t are never negative', () => {
    expect(lebesgueConstant(sampled([0, 1], 10)).value).toBeCloseTo(1, 12);
  });

  it('is 5/4 at t = 1/4 for three equally spaced nodes', () => {
    // On [0, 1/2]: |L0| + |L1| + |L2| = L0 + L1 − L2 = −4t² + 2t + 1, largest at t = 1/4.
    const worst = lebesgueConstant(sampled([0, 0.5, 1], 800));
    expect(worst.value).toBeCloseTo(1.25, 12);
    expect(worst.t).toBe(0.25);
  });

  it('grows with the number of equally spaced nodes (Runge)', () => {
    const nodes = (n: number) => Array.from({ length: n + 1 }, (_, k) => k / n);
    const small = lebesgueConstant(sampled(nodes(4), 400)).value;
    const large = lebesgueConstant(sampled(nodes(12), 400)).value;
    expect(large).toBeGreaterThan(10 * small);
  });

  it('is 0 with no curves', () => {
    expect(lebesgueConstant([])).toEqual({ value: 0, t: 0 });
  });
});
