import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { curveFigure } from './curveFigure';
import { WEIGHT_MAX, WEIGHT_MIN, haloAt, haloRadius, haloUnit, weightForRadius } from './halo';
import lesson from './lesson';
import type { NurbsModel } from './model';
import { SCENES } from './scenes';
import { type BSplineState, normalize, schema } from './state';

/** The NURBS scene's model as the shell gets it from the kit. */
const derive = (s: BSplineState) => lesson.derive(s) as NurbsModel;
const defaults = normalize(defaultsOf(schema)).state;
const nurbs = (step: number) =>
  normalize({ ...SCENES.find((s) => s.id === 'nurbs')!.setup(defaults), step }).state;

describe('the weight halo', () => {
  it('one unit is 6% of the diagonal of the points’ box: the seven points’ 10 × 4 gives 0.06·√116', () => {
    expect(haloUnit(nurbs(2).points)).toBeCloseTo(0.06 * Math.sqrt(116), 14);
    // All points on one spot: a unit of 0.06, not 0.
    expect(haloUnit([[2, 2]])).toBe(0.06);
  });

  it('radius 0.3 + 0.7·√w units: weight 1 is one unit, weight 4 is 1.7 units', () => {
    expect(haloRadius(1, 2)).toBe(2);
    expect(haloRadius(4, 2)).toBeCloseTo(3.4, 14);
    expect(haloRadius(0.25, 1)).toBeCloseTo(0.65, 14);
  });

  it('the weight of a radius undoes the radius, to the slider’s 0.01, clamped to its range', () => {
    for (const w of [0.1, 0.25, 1, 2.37, 4, 5])
      expect(weightForRadius(haloRadius(w, 0.7), 0.7)).toBe(w);
    // 1.8 units: √w = 1.5/0.7, w = 2.25/0.49 = 4.5918…
    expect(weightForRadius(1.8, 1)).toBe(4.59);
    expect(weightForRadius(0, 1)).toBe(WEIGHT_MIN);
    expect(weightForRadius(100, 1)).toBe(WEIGHT_MAX);
  });

  it('the ring is picked near its circle, not at its centre; the nearest ring wins', () => {
    const points = [
      [0, 0],
      [10, 0],
    ];
    expect(haloAt(points, [1, 4], 1, [1.05, 0], 0.1)).toBe('w0');
    expect(haloAt(points, [1, 4], 1, [10, 1.65], 0.1)).toBe('w1');
    expect(haloAt(points, [1, 4], 1, [0, 0], 0.1)).toBeNull();
    expect(haloAt(points, [1, 4], 1, [5, 0], 0.1)).toBeNull();
  });

  it('the curve figure picks a halo only on the steps that show them, and its drag sets that weight alone', () => {
    const before = derive(nurbs(1));
    const state = nurbs(2);
    const m = derive(state);
    const unit = m.rational.haloUnit;
    const [x, y] = state.points[3];
    const ring: number[] = [x + haloRadius(state.weights[3], unit), y];
    expect(curveFigure.pickAt!(before, ring, unit * 0.1)).toBeNull();
    expect(curveFigure.pickAt!(m, ring, unit * 0.1)).toBe('w3');
    const next = curveFigure.moveHandle!(state, 'w3', [x + 1.8 * unit, y], m);
    expect(next.weights).toEqual(state.weights.map((w, i) => (i === 3 ? 4.59 : w)));
    expect(next.points).toBe(state.points);
  });
});
