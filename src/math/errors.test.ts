import { describe, expect, it } from 'vitest';
import * as math from './index';
import type { Point } from './vec';

// Every function of the contract, fed each kind of bad input the spec names:
// it must throw a RangeError whose message names the function and says what
// was wrong, never return NaN.

const good2D: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];
const mixed: Point[] = [
  [0, 0],
  [1, 2, 3],
  [3, 2],
  [4, 0],
];
const withNaN: Point[] = [
  [0, 0],
  [1, NaN],
  [3, 2],
  [4, 0],
];
const withInfinity: Point[] = [
  [0, 0],
  [1, 2],
  [Infinity, 2],
  [4, 0],
];
const knots = [0, 0, 0, 0, 1, 1, 1, 1];
const helix: Point[] = [
  [1, 0, 0],
  [1, 1, 1],
  [0, 1, 2],
  [-1, 1, 3],
];

/** Each contract function as a function of its point list and its parameter. */
const curves: [string, (points: Point[], parameter: number) => unknown, number][] = [
  ['deCasteljau', (p, t) => math.deCasteljau(p, t), 0.5],
  ['bezierPoint', (p, t) => math.bezierPoint(p, t), 0.5],
  ['splitBezier', (p, t) => math.splitBezier(p, t), 0.5],
  ['bezierDerivative', (p) => math.bezierDerivative(p), 0.5],
  ['elevateDegree', (p) => math.elevateDegree(p), 0.5],
  ['lagrangePoint', (p, t) => math.lagrangePoint([0, 1, 2, 3], p, t), 0.5],
  ['catmullRomTangents', (p) => math.catmullRomTangents(p), 0.5],
  ['cubicSplinePoint', (p, s) => math.cubicSplinePoint(p, good2D, s), 1.5],
  ['quadraticSplineC1', (p) => math.quadraticSplineC1(p, [0, 1]), 0.5],
  ['cubicSplineC2', (p) => math.cubicSplineC2(p), 0.5],
  ['uniformBSplinePoint', (p, s) => math.uniformBSplinePoint(p, s), 0.5],
  ['nurbsPoint', (p, t) => math.nurbsPoint(p, [1, 1, 1, 1], knots, 3, t), 0.5],
  ['bezierSurfacePoint', (p, u) => math.bezierSurfacePoint([p, good2D], u, 0.5), 0.5],
  ['bezierCurvature', (p, t) => math.bezierCurvature(p, t), 0.5],
  ['flattenBezier', (p) => math.flattenBezier(p, 0.1), 0.5],
  ['catmullRomSegments', (p, alpha) => math.catmullRomSegments(p, alpha), 0.5],
  ['catmullRomPoint', (p, s) => math.catmullRomPoint(p, 0.5, s), 1.5],
  ['bezierJointContinuity', (p) => math.bezierJointContinuity(p, good2D), 0.5],
  ['bezierFrenetFrame', (p, t) => math.bezierFrenetFrame(p, t), 0.5],
];

describe('every contract function rejects bad points', () => {
  it.each(curves)('%s', (name, call, parameter) => {
    expect(call(good2D, parameter)).toBeDefined();
    for (const bad of [mixed, withNaN, withInfinity]) {
      expect(() => call(bad, parameter)).toThrow(RangeError);
      expect(() => call(bad, parameter)).toThrow(new RegExp(`^${name}: `));
    }
    expect(() => call([], parameter)).toThrow(/needs at least \d+ points?, but got 0/);
  });
});

describe('every parameter has its range', () => {
  const cases: [string, () => unknown][] = [
    ['bernstein t', () => math.bernstein(3, 1, 1.5)],
    ['deCasteljau t', () => math.deCasteljau(good2D, -0.1)],
    ['bezierPoint t', () => math.bezierPoint(good2D, NaN)],
    ['splitBezier t', () => math.splitBezier(good2D, 2)],
    ['parametricQuadratic mu', () => math.parametricQuadratic([0, 0], [1, 1], [2, 0], 1)],
    ['lagrangePoint t', () => math.lagrangePoint([0, 1], [[0], [1]], Infinity)],
    ['hermiteBasis t', () => math.hermiteBasis(1.01)],
    ['cubicSplinePoint s', () => math.cubicSplinePoint(good2D, good2D, 3.5)],
    ['uniformBSplinePoint s', () => math.uniformBSplinePoint(good2D, 1.01)],
    ['bsplineBasis t', () => math.bsplineBasis(knots, 3, 0, 1.2)],
    ['nurbsPoint t', () => math.nurbsPoint(good2D, [1, 1, 1, 1], knots, 3, -1)],
    ['bezierSurfacePoint v', () => math.bezierSurfacePoint([good2D], 0.5, 7)],
    ['bezierCurvature t', () => math.bezierCurvature(good2D, 1.5)],
    ['flattenBezier tolerance', () => math.flattenBezier(good2D, 0)],
    ['catmullRomSegments alpha', () => math.catmullRomSegments(good2D, 1.5)],
    ['catmullRomPoint s', () => math.catmullRomPoint(good2D, 0.5, 3.5)],
    ['bezierFrenetFrame t', () => math.bezierFrenetFrame(good2D, -1)],
    ['bezierTorsion t', () => math.bezierTorsion(helix, 2)],
    ['coxDeBoorTable t', () => math.coxDeBoorTable(knots, 3, 1.5)],
    ['rasterizeLine x1', () => math.rasterizeLine(0, 0, NaN, 0)],
  ];
  it.each(cases)('%s', (_, call) => {
    expect(call).toThrow(RangeError);
    expect(call).toThrow(/outside the allowed range|must be a finite number|tolerance/);
  });
});

describe('the other named failures', () => {
  it('too few points for the closed spline and the B-spline', () => {
    expect(() => math.naturalCubicDerivativesClosed([1, 2])).toThrow(
      /at least 3 values, but got 2/,
    );
    expect(() => math.uniformBSplinePoint(good2D.slice(0, 3), 0)).toThrow(
      /at least 4 points, but got 3/,
    );
  });

  it('coincident abscissae and coincident parameters', () => {
    expect(() => math.parabolaThrough([1, 0], [2, 1], [1, 4])).toThrow(/same x = 1/);
    expect(() => math.lagrangePoint([0, 0], [[0], [1]], 0.5)).toThrow(/both 0/);
  });

  it('zero speed for the curvature', () => {
    expect(() =>
      math.bezierCurvature(
        [
          [1, 1],
          [1, 1],
          [2, 2],
        ],
        0,
      ),
    ).toThrow(/zero speed/);
  });

  it('torsion needs a 3D curve with a well-defined osculating plane', () => {
    expect(() => math.bezierTorsion(good2D, 0.5)).toThrow(/^bezierTorsion: points are 2D/);
    expect(() => math.bezierTorsion(helix.slice(0, 2), 0.5)).toThrow(/P′ × P″ = 0/);
  });

  it('non-finite scalar values', () => {
    expect(() => math.naturalCubicDerivatives([0, NaN, 1])).toThrow(/ys\[1\] is NaN/);
    expect(() => math.binomial(Infinity, 1)).toThrow(RangeError);
  });
});

describe('degenerate but legal input works', () => {
  it('repeated, collinear, two-point and low-degree input gives finite numbers', () => {
    const repeated: Point[] = [
      [1, 1],
      [1, 1],
      [1, 1],
    ];
    const collinear: Point[] = [
      [0, 0],
      [1, 1],
      [2, 2],
      [3, 3],
    ];
    const finite = (value: unknown) => expect(JSON.stringify(value)).not.toMatch(/null|NaN/);
    finite(math.cubicSplineC2(repeated));
    finite(math.cubicSplineC2(collinear));
    finite(math.cubicSplineC2(collinear.slice(0, 2)));
    finite(math.quadraticSplineC1(repeated, [1, 1]));
    finite(math.catmullRomSegments(repeated, 0.5));
    finite(math.naturalCubicDerivativesClosed([2, 2, 2]));
    finite(math.bezierPoint([[4, 2]], 0.3));
    finite(math.bezierPoint(collinear.slice(0, 2), 0.3));
    finite(math.flattenBezier(repeated, 0.1));
    finite(math.uniformBSplinePoint(collinear, 0.5));
    finite(math.bsplineBasis([0, 1], 0, 0, 1));
    finite(math.nurbsPoint([[1, 2]], [1], [0, 1], 0, 0.5));
    finite(math.bezierSurfacePoint([[[1, 2, 3]]], 0.5, 0.5));
    finite(math.bezierTorsion(helix.slice(0, 3), 0.5));
    finite(math.coxDeBoorTable([0, 1], 0, 1));
    finite(math.rasterizeLine(0.2, 0.2, 0.3, 0.3));
    finite(math.cubicSplineC2(repeated.map(([x, y]) => [x, y, 0])));
    finite(math.naturalCubicDerivatives([5, 5, 5]));
  });
});
