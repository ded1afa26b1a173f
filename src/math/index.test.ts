import { describe, expect, it } from 'vitest';
import * as math from './index';

// The names in shared/spec/math-api.md: other tools import exactly these.
const contract = [
  'binomial',
  'bernstein',
  'deCasteljau',
  'bezierPoint',
  'bezierDerivative',
  'splitBezier',
  'elevateDegree',
  'bezierBasisMatrix',
  'parabolaThrough',
  'parametricQuadratic',
  'lagrangePoint',
  'hermiteBasis',
  'hermiteCoefficients',
  'naturalCubicDerivatives',
  'naturalCubicDerivativesClosed',
  'catmullRomTangents',
  'cubicSplinePoint',
  'quadraticSplineC1',
  'cubicSplineC2',
  'uniformBSplinePoint',
  'bsplineBasis',
  'nurbsPoint',
  'bezierSurfacePoint',
  'bezierCurvature',
  'flattenBezier',
  'catmullRomSegments',
  'catmullRomPoint',
  'bezierJointContinuity',
  'bezierFrenetFrame',
  'bezierTorsion',
  'coxDeBoorTable',
  'rasterizeLine',
];

describe('src/math/index.ts', () => {
  it('exports every function of the contract', () => {
    for (const name of contract)
      expect(typeof (math as Record<string, unknown>)[name], name).toBe('function');
  });
});
