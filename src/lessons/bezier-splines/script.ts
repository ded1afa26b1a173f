import { sub } from '../../kit/format';
import { type Script, repeat, script, step } from '../../kit/script';
import type { Point } from '../../math';
import { texNumber, texPoint } from '../../render/formula';
import type { BezierSplinesModel } from './model';
import type { BezierSplinesState, Part } from './state';
import { type DegreeReveal, degree } from './degreeScript';
import { type SystemReveal, system } from './systemScript';
import { type WorkedReveal, worked } from './workedScript';

/** What each part's steps reveal, by name: the figures and the panel ask for these. */
export type WhyReveal = 'points' | 'single' | 'moved' | 'pieces' | 'local';
export type QuadraticReveal = 'points' | 'firstPiece' | 'mirror' | 'swing';
export type GridReveal = 'points' | 'c0' | 'c1' | 'c2';
export type InspectorReveal = 'joints' | 'pieces' | 'verdicts' | 'tangents' | 'curvature' | 'comb';
export type CatmullReveal =
  'points' | 'hermite' | 'uniform' | 'oneSided' | 'centripetal' | 'chordal' | 'all';
export type { SystemReveal } from './systemScript';
export type { WorkedReveal } from './workedScript';
export type { DegreeReveal } from './degreeScript';
export type Reveal =
  | WhyReveal
  | QuadraticReveal
  | SystemReveal
  | GridReveal
  | InspectorReveal
  | CatmullReveal
  | WorkedReveal
  | DegreeReveal;

type State = BezierSplinesState;
type Model = BezierSplinesModel;

const pt = (p: Point) => texPoint(p, 2);
const num = (v: number, digits = 2) => texNumber(v, digits);
const last = (s: State) => s.points.length - 1;

/** Part 1: one curve through all the points has no local control; pieces do. */
export const why = script<State, Model, WhyReveal>(
  step(
    'points',
    (at) => `The points p${sub(0)} … p${sub(last(at.state))} to join by one smooth curve`,
  ),
  step(
    'single',
    ({ state }) =>
      `One Bézier curve with them as control points: degree ${last(state)}, and it misses the inner points`,
    ({ state }) => `P(t) = \\sum_{i=0}^{${last(state)}} B^{${last(state)}}_i(t)\\,p_i`,
  ),
  step(
    'moved',
    ({ model }) =>
      `Move p${sub(model.moved)} up by 1: every part of that one curve moves — no local control`,
    ({ state, model }) =>
      `\\Delta P(t) = B^{${last(state)}}_{${model.moved}}(t)\\cdot(0,\\,1) \\neq 0 \\text{ for every } t \\in (0,1)`,
  ),
  step(
    'pieces',
    'Pieces instead: one cubic between each two neighbours, joined smoothly (C²)',
    () => 'P_i(t) = \\sum_{j=0}^{3} B^3_j(t)\\,c_{3i+j},\\quad i = 0,\\dots,n-1',
  ),
  step(
    'local',
    ({ model }) =>
      `Move p${sub(model.moved)} again: pieces far from it barely move; the question is how pieces join`,
    ({ model }) => {
      const far = Math.max(
        ...model.spline[0].map((q, k) =>
          Math.hypot(q[0] - model.movedSpline[0][k][0], q[1] - model.movedSpline[0][k][1]),
        ),
      );
      return `\\max_j |\\Delta c_j| \\text{ on the first piece} = ${num(far, 3)}`;
    },
  ),
);

/** Part 2: b0 chosen, every further bᵢ its mirror image, then the swing. */
export const quadratic = script<State, Model, QuadraticReveal>(
  step(
    'points',
    ({ state }) =>
      `The points p${sub(0)} … p${sub(last(state))}: n = ${last(state)} quadratic pieces [pᵢ, bᵢ, pᵢ₊₁] to find`,
  ),
  step(
    'firstPiece',
    `Choose b${sub(0)} (the midpoint of p${sub(0)}p${sub(1)} to start; drag it): the first piece`,
    ({ state }) => `b_0 = ${pt(state.firstControl[0])}`,
  ),
  // One press per further piece: b₁ … bₙ₋₁.
  repeat(
    'mirror',
    (s) => last(s) - 1,
    ({ index: i }) =>
      `C¹ at p${sub(i)}: b${sub(i)} = 2p${sub(i)} − b${sub(i - 1)}, the mirror image of b${sub(i - 1)}`,
    ({ state, model: { quadraticControls: b }, index: i }) =>
      `b_{${i}} = 2p_{${i}} - b_{${i - 1}} = 2\\cdot${pt(state.points[i])} - ${pt(b[i - 1])} = ${pt(b[i])}`,
  ),
  step(
    'swing',
    `Move b${sub(0)} by ±0.5: every bᵢ moves by ∓0.5 in turn — the spline swings and never settles`,
    () =>
      `b_0 \\pm \\delta \\;\\Rightarrow\\; b_i \\pm (-1)^i\\,\\delta,\\quad \\delta = (0,\\ 0.5)`,
  ),
);

/** Part 4: the practical's figure, one column per press. The grid needs every pixel of height in presenter view: its captions say it all. */
export const grid = script<State, Model, GridReveal>(
  step('points', 'The practical’s three datasets: infinity, spiral and a half circle'),
  step('c0', 'C⁰: straight pieces through the points, a corner at every point'),
  step('c1', 'C¹: quadratic pieces, b₀ the midpoint of p₀p₁ — smooth, but swinging'),
  step('c2', 'C²: cubic pieces from the linear system — smooth and calm'),
);

// A zero velocity has no direction and no length: say so instead of NaN.
const undefinedHere = `\\text{undefined}`;

/** Part 5: the joints, the pieces, then what decides each verdict. */
export const inspector = script<State, Model, InspectorReveal>(
  step('joints', 'The joints of a piecewise cubic Bézier built by hand'),
  step('pieces', 'Its cubic pieces and their control polygons: drag any point'),
  step('verdicts', 'The verdict at each joint: C⁰, G¹, C¹, G² or C²', ({ model }) =>
    model.joints.length === 0
      ? null
      : model.joints
          .map((r, i) => `\\text{joint ${i + 1}: }${r.continuity.replace(/(\d)/, '^$1')}`)
          .join(',\\quad '),
  ),
  step(
    'tangents',
    'At each joint, the two tangent vectors: their angle decides G¹, their lengths C¹',
    ({ model }) => {
      const j = model.joints[0];
      if (!j) return null;
      const velocities = `P_0'(1) = ${pt(j.leftVelocity)},\\ P_1'(0) = ${pt(j.rightVelocity)}`;
      if (j.degenerate) return `${velocities}:\\ \\angle,\\ |P_1'|/|P_0'|\\ ${undefinedHere}`;
      return `${velocities},\\ \\angle = ${num(j.angle, 1)}^\\circ,\\ |P_1'|/|P_0'| = ${num(j.lengthRatio, 3)}`;
    },
  ),
  step(
    'curvature',
    'The second derivatives and the curvature on both sides decide C² and G²',
    ({ model }) => {
      const j = model.joints[0];
      if (!j) return null;
      const kappa = (k: number) => (Number.isNaN(k) ? undefinedHere : num(k, 3));
      return `P_0''(1) = ${pt(j.leftSecond)},\\ P_1''(0) = ${pt(j.rightSecond)},\\ \\kappa = ${kappa(j.leftCurvature)} \\mid ${kappa(j.rightCurvature)}`;
    },
  ),
  step('comb', 'The curvature comb: where its teeth jump, the curvature jumps (not G²)'),
);

/** Knot gaps |pᵢ₊₁ − pᵢ|^α, for the centripetal and chordal steps. */
const gaps = (p: readonly Point[], alpha: 0.5 | 1) =>
  `\\Delta_i = |p_{i+1} - p_i|^{${alpha === 1 ? 1 : '1/2'}} = ${p
    .slice(1)
    .map((q, i) => num(Math.hypot(q[0] - p[i][0], q[1] - p[i][1]) ** alpha))
    .join(',\\ ')}`;

/** Part 6: hand-set tangents, then Catmull-Rom's, uniform, centripetal and chordal. */
export const catmull = script<State, Model, CatmullReveal>(
  step('points', ({ state }) => `The points p${sub(0)} … p${sub(last(state))}`),
  step(
    'hermite',
    'Hermite: a tangent Tᵢ set by hand at each point; the control points are pᵢ ± Tᵢ/3',
    ({ state: { points: p, tangents } }) =>
      `c_1 = p_1 + \\tfrac{1}{3}T_1 = ${pt(p[1])} + \\tfrac{1}{3}${pt(tangents[1])}`,
  ),
  step(
    'uniform',
    'Catmull-Rom takes Tᵢ = (pᵢ₊₁ − pᵢ₋₁)/2 from the neighbours, zero at the ends (uniform, α = 0)',
    ({ state, model }) =>
      state.points.length > 2
        ? `T_1 = \\tfrac{1}{2}(p_2 - p_0) = ${pt(model.crTangents[1])}`
        : null,
  ),
  step(
    'oneSided',
    'One-sided ends instead of zero: T₀ = p₁ − p₀ and Tₙ = pₙ − pₙ₋₁',
    ({ model }) => `T_0 = p_1 - p_0 = ${pt(model.oneSidedTangents[0])}`,
  ),
  step(
    'centripetal',
    'Centripetal, α = ½: knot gaps |pᵢ₊₁ − pᵢ|^½ — no loop, no cusp',
    ({ state }) => gaps(state.points, 0.5),
  ),
  step('chordal', 'Chordal, α = 1: knot gaps |pᵢ₊₁ − pᵢ| — rounder, wider', ({ state }) =>
    gaps(state.points, 1),
  ),
  step(
    'all',
    'All three: the uniform one crosses itself at the hairpin, the centripetal never does',
    ({ model }) =>
      model.alphas
        .map(
          (a) =>
            `\\text{${a.name}: ${a.crossings.length} crossing${a.crossings.length === 1 ? '' : 's'}}`,
        )
        .join(',\\quad '),
  ),
);

/** Each part's script, by the part (the state's `part` says which scene a state is in). */
export const scripts: Record<Part, Script<State, Model, Reveal>> = {
  why,
  quadratic,
  system,
  grid,
  inspector,
  catmull,
  worked,
  degree,
};

/** What the current step of a state's part reveals (for handles, which see only the state). */
export const revealedAt = (s: State) => scripts[s.part].shown(s, s.step);
