// The maths of Spline Lab: pure functions, numbers in, fresh numbers out.
// The contract is shared/spec/math-api.md; everything else here is for lessons.

export type { Point } from './vec';
export { add, subtract, scale, pointBetween, dot, norm, distance, cross, zeroVector } from './vec';
export {
  checkNumber,
  checkInteger,
  checkParameter,
  checkOpenParameter,
  checkNumbers,
  checkSameLength,
} from './validate';
export { checkPoint, checkPoints } from './checkPoints';
export { checkCoordinateArrays } from './checkCoordinateArrays';

// Bézier curves
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
export { samplePlanarCubic } from './planarCubic';
export { bezierBasisMatrix, bezierToPowerBasis, powerBasisToBezier } from './powerBasis';
export { type BasisExtreme, type BasisSamples, basisValuesAt, sampleBasis } from './basisSamples';

// Interpolation through points
export { parabolaThrough, parametricQuadratic, parametricQuadraticPoint } from './parabola';
export { chordLengthMu, centripetalMu, parameterValues } from './parameterisation';
export { lagrangeBasis, lagrangePoint } from './lagrange';
export { lebesgueConstant } from './lebesgueConstant';
export {
  hermiteMatrix,
  hermiteBasis,
  hermiteBasisDerivatives,
  hermiteCoefficients,
  hermitePoint,
  hermiteToBezier,
  bezierToHermite,
} from './hermite';

// Splines through the villages
export type { TridiagonalSystem, TridiagonalTrace } from './tridiagonal';
export { solveTridiagonal, traceTridiagonal } from './tridiagonal';
export { solveCyclicTridiagonal } from './cyclicTridiagonal';
export {
  naturalCubicSystem,
  clampedCubicSystem,
  naturalCubicDerivatives,
  clampedCubicDerivatives,
  naturalCubicTangents,
  clampedCubicTangents,
  naturalCubicCoefficients,
  sampleNaturalCubicSpline,
} from './naturalCubic';
export {
  closedCubicSystem,
  naturalCubicDerivativesClosed,
  closedCubicTangents,
} from './closedCubic';
export type { CubicBezierControls } from './naturalCubicBatch';
export { naturalCubicDerivativesBatch, naturalCubicBezierBatch } from './naturalCubicBatch';
export {
  cubicSplinePoint,
  closedCubicSplinePoint,
  cubicSplineSegments,
  cubicSplineCoefficients,
  sampleCubicSpline,
} from './cubicSpline';
export { catmullRomTangents, catmullRomSegments, catmullRomPoint } from './catmullRom';
export { quadraticSplineC1, cubicSplineC2, bezierSplinePoint } from './bezierSpline';

// B-splines and NURBS
export {
  uniformBSplineMatrix,
  uniformBSplineBasis,
  uniformBSplinePoint,
  uniformBSplineToBezier,
  bezierToUniformBSpline,
  uniformBSplineSegments,
} from './uniformBSpline';
export type { BSplineBezierControls } from './uniformBSplineBatch';
export { sampleUniformBSpline, uniformBSplineBezierBatch } from './uniformBSplineBatch';
export { bsplineBasis, clampedUniformKnots, uniformKnots } from './bsplineBasis';
export { coxDeBoorTable } from './coxDeBoorTable';
export type { NurbsCurve } from './nurbs';
export { nurbsPoint, nurbsCircle } from './nurbs';

// Surfaces, geometry, drawing
export type { SurfaceJet } from './surface';
export { bezierSurfacePoint, bezierSurfaceDerivatives, bezierSurfaceNormal } from './surface';
export type { SurfaceConstruction, SurfaceOrder } from './surfaceConstruction';
export {
  surfaceRowPoints,
  surfaceColumnPoints,
  surfaceDeCasteljau,
  surfaceWeights,
} from './surfaceConstruction';
export { bezierTangent, bezierCurvature } from './curvature';
export type { FrenetFrame } from './frenetFrame';
export { bezierFrenetFrame, bezierNormal } from './frenetFrame';
export { bezierTorsion } from './bezierTorsion';
export type { Circle } from './osculatingCircle';
export { osculatingCircle } from './osculatingCircle';
export type { Continuity } from './continuity';
export { bezierJointContinuity } from './continuity';
export { bezierArcLength } from './arcLength';
export { convexHull, convexHullContains } from './convexHull';
export { flattenBezier } from './flatten';
export { rasterizeLine } from './rasterizeLine';
export { bezierPieceBoxes, nearestOnBezierPieces } from './nearestOnBezierPieces';
export { clipToBand } from './clipToBand';

// Cost of solving the spline's system, and the counting argument
export type { ConstraintCount } from './solveCost';
export {
  thomasOperationCount,
  gaussianEliminationOperationCount,
  constraintCount,
} from './solveCost';
export { cubicInflections } from './cubicInflections';
export { cubicSelfIntersection } from './cubicSelfIntersection';
export { projectiveMap } from './projectiveMap';
export { projectiveMapWeighted } from './projectiveNurbs';
export type { Deviation } from './curveDeviation';
export { bezierDeviation, sampledDeviation } from './curveDeviation';
export { controlPolygonGap } from './controlPolygonGap';
export { rationalBezierPoint, sampleRationalBezier } from './rationalBezier';
export { subdivisionLevels } from './subdivision';
export { multiplyPlaneMatrices, translationMatrix, homogeneousWeight } from './homogeneousMatrix';
export { signedAngle } from './signedAngle';
export type { HelixFrame } from './helix';
export { helixPoint, helixFrame, helixCurvature, helixTorsion } from './helix';
export type { ArcLengthRow } from './arcLengthParameter';
export { bezierArcLengthTable, bezierParameterAtLength } from './arcLengthParameter';
export { helixDerivatives } from './helix';
export type { FrenetInvariants } from './frenetInvariants';
export { frenetInvariants } from './frenetInvariants';
export type { ChordDeviation } from './chordDeviation';
export { chordDeviation } from './chordDeviation';
export { nearestOnSegment } from './nearestOnSegment';
export { uniformParameters, uniformCountWithin } from './uniformCount';
export type { FlatteningNode } from './flatteningTree';
export { flatteningTree } from './flatteningTree';
export { segmentCoverage } from './strokeCoverage';
export type {
  SplineEquation,
  SplineEquationKind,
  SplineSystemSolution,
} from './bezierSplineSystem';
export {
  cubicSplineC2System,
  solveDense,
  solveCubicSplineC2System,
  controlPointName,
} from './bezierSplineSystem';
export type { JointReport } from './jointReport';
export { bezierJointReport, snapJoint } from './jointReport';
export { bezierChainSelfIntersections } from './chainIntersections';
export { uniformCountEstimate } from './uniformCount';
export type { PixelBox } from './rasterizeLine';
export { rasterizeLineInBox } from './rasterizeLine';
export { onOneSpot } from './oneSpot';
export { bezierChainSegments, bezierInflections } from './bezierChain';
export { type PointsShape, pointsShape } from './pointsShape';
