// bezier-js ships no types. This declares the few members our tests and
// benchmark use as a peer reference (dev-only; never imported by src/math code).
declare module 'bezier-js' {
  export interface BezierPoint {
    x: number;
    y: number;
    z?: number;
    t?: number;
  }

  export class Bezier {
    constructor(points: BezierPoint[]);
    constructor(...coordinates: number[]);
    points: BezierPoint[];
    order: number;
    compute(t: number): BezierPoint;
    derivative(t: number): BezierPoint;
    split(t: number): { left: Bezier; right: Bezier };
    split(t1: number, t2: number): Bezier;
    length(): number;
    curvature(t: number): { k: number; r: number };
  }
}
