import { sub } from '../../kit/format';
import { script, step } from '../../kit/script';
import type { Point } from '../../math';
import { texPoint } from '../../render/formula';
import type { BezierSplinesModel } from './model';
import type { BezierSplinesState } from './state';
import { degreeCount } from './workedExample';

/** What the steps of the degree scene reveal, by name. */
export type DegreeReveal = 'points' | 'degree1' | 'degree2' | 'degree3' | 'general' | 'notCd';

type State = BezierSplinesState;
type Model = BezierSplinesModel;

const pt = (p: Point) => texPoint(p, 2);
const pieces = (s: State) => s.points.length - 1;

/** The count for degree d with the state's n, each term under its formula. */
const countTex =
  (d: number) =>
  ({ state }: { state: State }) => {
    const c = degreeCount(d, pieces(state));
    return `d = ${d}:\\quad \\underbrace{${c.unknowns}}_{dn+1} - \\underbrace{${c.interpolation}}_{n+1} - \\underbrace{${c.smoothness}}_{(d-1)(n-1)} = ${c.free}`;
  };

/** Part 8: the same points as splines of degree 1, 2 and 3; what degree d leaves to choose; why not Cᵈ. */
export const degree = script<State, Model, DegreeReveal>(
  step(
    'points',
    ({ state }) =>
      `The points p${sub(0)} … p${sub(pieces(state))}: n = ${pieces(state)} pieces to join, of some degree d`,
  ),
  step(
    'degree1',
    ({ state }) =>
      `Degree 1, order 2: ${degreeCount(1, pieces(state)).unknowns} control points, all of them the points — C⁰, nothing left to choose`,
    countTex(1),
  ),
  step(
    'degree2',
    ({ state }) => {
      const c = degreeCount(2, pieces(state));
      return `Degree 2, order 3: ${c.unknowns} control points; the points and C¹ at the joints leave ${c.free} choice, b₀`;
    },
    countTex(2),
  ),
  step(
    'degree3',
    ({ state }) => {
      const c = degreeCount(3, pieces(state));
      return `Degree 3, order 4: ${c.unknowns} control points; the points, C¹ and C² leave ${c.free}, the natural ends`;
    },
    countTex(3),
  ),
  step(
    'general',
    'Degree d: C¹ up to Cᵈ⁻¹ at every joint, and d − 1 choices left whatever the number of pieces',
    () => `(dn + 1) - (n + 1) - (d - 1)(n - 1) = d - 1`,
  ),
  step(
    'notCd',
    ({ state }) =>
      pieces(state) > 1
        ? `Not C³: a cubic that matches the first piece’s value and three derivatives at p${sub(1)} is that piece continued: it ends at P${sub(0)}(2), not at p${sub(2)}`
        : `Not C³: a cubic that matches the piece’s value and three derivatives at p${sub(1)} is that piece continued`,
    ({ state, model }) => {
      const end = model.degree.continued[3];
      const miss = pieces(state) > 1 ? ` \\neq p_2 = ${pt(state.points[2])}` : '';
      return `P_1(t) = P_0(1 + t):\\quad P_1(1) = P_0(2) = ${pt(end)}${miss}`;
    },
  ),
);
