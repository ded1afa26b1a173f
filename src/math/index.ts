// The maths of Spline Lab: pure functions, numbers in, fresh numbers out.
// The contract is /shared/spec/math-api.md; everything else here is for lessons.

export type { Point } from './vec';
export { add, subtract, scale, pointBetween, dot, norm, distance, cross, zeroVector } from './vec';
export {
  checkNumber,
  checkInteger,
  checkParameter,
  checkOpenParameter,
  checkPoint,
  checkPoints,
  checkNumbers,
  checkSameLength,
} from './validate';
export { binomial } from './binomial';
export { bernstein, bernsteinBasis } from './bernstein';
export {
  deCasteljau,
  bezierPoint,
  splitBezier,
  bezierDerivative,
  elevateDegree,
  sampleBezier,
} from './bezier';
export { bezierBasisMatrix, bezierToPowerBasis, powerBasisToBezier } from './powerBasis';
