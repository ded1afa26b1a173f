import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { bsplineBasis } from '../../math';
import { knotFigure } from './knotFigure';
import lesson from './lesson';
import type { BSplineModel } from './model';
import { SCENES } from './scenes';
import { type BSplineState, SEVEN_POINTS, normalize, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: BSplineState) => lesson.derive(s) as BSplineModel;
/** The model of a scene family, by its kind. */
function modelOf<K extends BSplineModel['kind']>(kind: K, s: BSplineState) {
  const m = derive(s);
  if (m.kind !== kind) throw new Error(`a ${m.kind} model, not ${kind}`);
  return m as Extract<BSplineModel, { kind: K }>;
}
const steps = lesson.steps!;
const describeStep = (s: BSplineState, k: number) => steps.describe(s, k);
const stepCount = (s: BSplineState) => steps.count(s);

const defaults = normalize(defaultsOf(schema)).state;
const sceneState = (id: string, changes: Partial<BSplineState> = {}): BSplineState => {
  const scene = SCENES.find((s) => s.id === id)!;
  return normalize({ ...scene.setup(defaults), ...changes }).state;
};
const gap = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);

describe('the uniform cubic B-spline in the slides’ matrix form', () => {
  it('m + 1 = 7 points give m − 2 = 4 segments; open at (P0 + 4P1 + P2)/6, closed gives m + 1', () => {
    const m = derive(sceneState('uniform'));
    expect(m.segments).toHaveLength(4);
    // (0 + 4·1 + 3)/6 = 7/6 and (0 + 4·3 + 4)/6 = 16/6; the end (4.5·0 + … ) = (6.5 + 32 + 10)/6, (0 + 12 + 3.5)/6.
    expect(m.start[0]).toBeCloseTo(7 / 6, 14);
    expect(m.start[1]).toBeCloseTo(16 / 6, 14);
    expect(m.end[0]).toBeCloseTo(48.5 / 6, 14);
    expect(m.end[1]).toBeCloseTo(15.5 / 6, 14);
    expect(derive(sceneState('closed')).segments).toHaveLength(6);
  });

  it('segment i blends P_i … P_{i+3} with the 1/6 matrix: at local t = 1/2 the weights are 1/48, 23/48, 23/48, 1/48', () => {
    // s = 1.5: segment 1 (Q4, P1 … P4) at t = 1/2.
    const m = derive({ ...sceneState('uniform'), t: 1.5 / 4 });
    expect(m.segment).toBe(1);
    expect(m.basis.slice(1, 5).map((b) => b * 48)).toEqual(
      [1, 23, 23, 1].map((v) => expect.closeTo(v, 12)),
    );
    const [P1, P2, P3, P4] = SEVEN_POINTS.slice(1, 5);
    const expected = [0, 1].map((d) => (P1[d] + 23 * P2[d] + 23 * P3[d] + P4[d]) / 48);
    expect(gap(m.point, expected)).toBeLessThan(1e-12);
  });

  it('moving one control point changes the curve only on its (at most four) segments, to 1e-12 elsewhere', () => {
    const ten = sceneState('local');
    fc.assert(
      fc.property(
        fc.integer({ min: 0, max: ten.points.length - 1 }),
        fc.double({ min: -5, max: 5, noNaN: true }),
        fc.double({ min: -5, max: 5, noNaN: true }),
        (j, dx, dy) => {
          const before = derive({ ...ten, part: 'uniform', points: ten.before });
          const points = ten.before.map((point, i) =>
            i === j ? [point[0] + dx, point[1] + dy] : point,
          );
          const after = derive({ ...ten, part: 'uniform', points });
          return before.segments.every((segment, i) => {
            const acts = i <= j && j <= i + 3;
            let largest = 0;
            for (let k = 0; k < segment.samples.length; k++) {
              largest = Math.max(
                largest,
                Math.abs(segment.samples[k] - after.segments[i].samples[k]),
              );
            }
            return acts || largest <= 1e-12;
          });
        },
      ),
    );
  });

  it('the local-control scene says which segments changed: P4 moved, Q4 … Q7 of Q3 … Q9', () => {
    const m = modelOf('local', sceneState('local'));
    expect(m.localControl.moved).toEqual([4]);
    expect(m.localControl.changed).toEqual([false, true, true, true, true, false, false]);
  });
});

describe('knots and Cox–de Boor', () => {
  it('the triangle’s last row sums to 1 and matches bsplineBasis at every t tried', () => {
    for (const id of ['knots', 'clamped', 'repeated', 'circle']) {
      fc.assert(
        fc.property(fc.double({ min: 0, max: 1, noNaN: true }), (t) => {
          const m = derive(sceneState(id, { t }));
          const last = m.table[m.degree];
          const sum = last.reduce((a, b) => a + b, 0);
          return (
            Math.abs(sum - 1) < 1e-12 &&
            last.every((v, i) => v === bsplineBasis(m.knots, m.degree, i, m.u))
          );
        }),
      );
    }
  });

  it('clamped knots: the curve starts at P0 and ends at the last point', () => {
    const m = derive(sceneState('clamped'));
    expect(gap(m.start, SEVEN_POINTS[0])).toBeLessThan(1e-12);
    expect(gap(m.end, SEVEN_POINTS[6])).toBeLessThan(1e-12);
    // Uniform (unclamped) knots pass through neither.
    const open = derive(sceneState('knots'));
    expect(gap(open.start, SEVEN_POINTS[0])).toBeGreaterThan(0.5);
  });

  it('a knot of multiplicity p makes the curve C⁰ there and pass through a control point', () => {
    // Knots 0,0,0,0, 1,1,1, 2,2,2,2: at u = 1 only N(3,3) is non-zero, so P(1) = P3.
    const m = derive(sceneState('repeated'));
    expect(m.joins).toHaveLength(1);
    const [join] = m.joins;
    expect(join).toMatchObject({ u: 1, multiplicity: 3, continuity: 0, through: 3 });
    expect(gap(join.at, SEVEN_POINTS[3])).toBeLessThan(1e-12);
    // Multiplicity 2 instead: C¹ there, and no longer through P3.
    const double = derive(sceneState('repeated', { knots: [0, 0, 0, 0, 1, 1, 1.5, 2, 2, 2, 2] }));
    expect(double.joins[0]).toMatchObject({ multiplicity: 2, continuity: 1, through: null });
  });

  it('a knot dropped near its neighbour lands on it; the domain never closes', () => {
    const state = sceneState('knots');
    const m = derive(state);
    const stacked = knotFigure.moveHandle!(state, 'u5', [4.05, 0], m);
    expect(stacked.knots[5]).toBe(4);
    // u3 up to u7 would leave [u_p, u_{m+1}] = [u3, u7] empty: refused.
    const tight = { ...state, knots: [0, 1, 2, 3, 7, 7, 7, 7, 8, 9, 10] };
    expect(knotFigure.moveHandle!(tight, 'u3', [7, 0], derive(tight)).knots[3]).toBe(3);
  });
});

describe('properties', () => {
  it('variation diminishing: the line y = 1.5 crosses the seven points’ polygon 3 times and the curve twice', () => {
    // Polygon heights 0, 3, 4, 1, 0, 3, 3.5: three sign changes. Joints 8/3, 10/3, 4/3, 2/3, 31/12: two.
    const m = modelOf(
      'properties',
      sceneState('properties', {
        line: [
          [0, 1.5],
          [10, 1.5],
        ],
      }),
    );
    expect(m.properties.crossings.polygon).toBe(3);
    expect(m.properties.crossings.curve).toBe(2);
  });

  it('affine invariance: the curve of the mapped points is the mapped curve', () => {
    expect(modelOf('properties', sceneState('properties')).properties.deviation).toBeLessThan(
      1e-12,
    );
  });
});

describe('NURBS', () => {
  it('the circle’s sampled points lie on the circle within 1e-9; with weights 1 they do not', () => {
    const m = modelOf('circle', sceneState('circle'));
    expect(m.circle.deviation).toBeLessThan(1e-9);
    for (const point of m.circle.samples)
      expect(Math.abs(Math.hypot(point[0], point[1]) - 3)).toBeLessThan(1e-9);
    expect(m.circle.plainDeviation).toBeGreaterThan(0.1);
  });

  it('raising a weight pulls the curve towards its point', () => {
    const plain = derive(sceneState('nurbs', { weights: SEVEN_POINTS.map(() => 1), t: 0.3 }));
    const heavy = derive(sceneState('nurbs', { t: 0.3 }));
    expect(gap(heavy.point, SEVEN_POINTS[2])).toBeLessThan(gap(plain.point, SEVEN_POINTS[2]));
  });

  it('a projective map of the points with their weights keeps the curve; the old weights do not', () => {
    const m = modelOf('projective', sceneState('projective'));
    expect(m.projective.error).toBeNull();
    expect(m.projective.deviation).toBeLessThan(1e-9);
    expect(m.projective.plainDeviation).toBeGreaterThan(0.05);
  });
});

describe('the script', () => {
  it('every scene steps from 0 to its count with a caption, and every step’s formula builds', () => {
    for (const scene of SCENES) {
      const state = sceneState(scene.id);
      expect(state.part).toBe(scene.id);
      for (let k = 0; k <= stepCount(state); k++) {
        const at = { ...state, step: k };
        expect(describeStep(at, k).length).toBeGreaterThan(5);
        expect(() => steps.formula!(derive(at), at)).not.toThrow();
      }
    }
  });

  it('a link with knots or weights that do not fit the points is mended, and says so', () => {
    const { state, issues } = normalize({ ...sceneState('knots'), knots: [0, 1, 2], weights: [2] });
    expect(state.knots).toEqual([0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1]);
    expect(state.weights).toEqual([2, 1, 1, 1, 1, 1, 1]);
    expect(issues).toHaveLength(2);
  });
});
