import type { Scene, StepsSpec } from '../../app/lesson';
import { defaultsOf } from '../../app/urlState';
import { sub, texExponent } from '../../kit/format';
import { controlPointName, type Point } from '../../math';
import { texNumber, texPoint } from '../../render/formula';
import type { BezierSplinesModel } from './model';
import {
  type BezierSplinesState,
  FOUR_POINTS,
  HAIRPIN,
  HAND_BUILT,
  LECTURE_POINTS,
  type Part,
  handTangents,
  midpoint,
  schema,
  stepCount,
} from './state';

const pt = (p: Point) => texPoint(p, 2);
const num = (v: number, digits = 2) => texNumber(v, digits);

/** The name of the spline's control point j (A … J for four points, else c_j) in captions. */
const name = (j: number, n: number) => {
  const text = controlPointName(j, 3 * n + 1);
  return text.startsWith('c_') ? `c${sub(j)}` : text;
};

const captions: Record<Part, (s: BezierSplinesState, k: number) => string> = {
  why(s, k) {
    const n = s.p.length - 1;
    const m = Math.floor(s.p.length / 2);
    return [
      `The points p${sub(0)} … p${sub(n)} to join by one smooth curve`,
      `One Bézier curve with them as control points: degree ${n}, and it misses the inner points`,
      `Move p${sub(m)} up by 1: every part of that one curve moves — no local control`,
      `Pieces instead: one cubic between each two neighbours, joined smoothly (C²)`,
      `Move p${sub(m)} again: pieces far from it barely move; the question is how pieces join`,
    ][k];
  },
  quadratic(s, k) {
    const n = s.p.length - 1;
    if (k === 0)
      return `The points p${sub(0)} … p${sub(n)}: n = ${n} quadratic pieces [pᵢ, bᵢ, pᵢ₊₁] to find`;
    if (k === 1)
      return `Choose b${sub(0)} (the midpoint of p${sub(0)}p${sub(1)} to start; drag it): the first piece`;
    if (k <= n)
      return `C¹ at p${sub(k - 1)}: b${sub(k - 1)} = 2p${sub(k - 1)} − b${sub(k - 2)}, the mirror image of b${sub(k - 2)}`;
    return `Move b${sub(0)} by ±0.5: every bᵢ moves by ∓0.5 in turn — the spline swings and never settles`;
  },
  system(s, k) {
    const n = s.p.length - 1;
    const size = 3 * n + 1;
    const joints = Array.from({ length: n + 1 }, (_, i) => name(3 * i, n)).join(', ');
    const four = size === 10;
    return [
      `The points ${joints} to interpolate`,
      four
        ? 'Three cubic pieces [A B C D], [D E F G], [G H I J]: 10 control points, 6 of them unknown'
        : `${n} cubic pieces: ${size} control points c${sub(0)} … c${sub(3 * n)}, unknowns all`,
      `Interpolation: ${joints} are the given points (${n + 1} equations; shared ends give C⁰)`,
      four
        ? 'C¹ at D and G: C − 2D + E = 0 and F − 2G + H = 0 (2 equations)'
        : `C¹ at each inner joint: c₃ᵢ₋₁ − 2c₃ᵢ + c₃ᵢ₊₁ = 0 (${n - 1} equations)`,
      four
        ? 'C² at D and G: B − 2C + 2E − F = 0 and E − 2F + 2H − I = 0: the practical’s 8 equations'
        : `C² at each inner joint: c₃ᵢ₋₂ − 2c₃ᵢ₋₁ + 2c₃ᵢ₊₁ − c₃ᵢ₊₂ = 0 (${n - 1} equations)`,
      four
        ? 'Natural ends, P″ = 0: A − 2B + C = 0 and H − 2I + J = 0 — 10 equations, 10 unknowns'
        : `Natural ends, P″ = 0 at both: ${size} equations for ${size} unknowns`,
      `The whole ${size} × ${size} system with the current numbers (x and y share the matrix)`,
      'Solved: the control points, drawn, and the residual of every equation',
      'The same control points as the natural cubic spline of the road lesson',
    ][k];
  },
  grid: (_s, k) =>
    [
      'The practical’s three datasets: infinity, spiral and a half circle',
      'C⁰: straight pieces through the points, a corner at every point',
      'C¹: quadratic pieces, b₀ the midpoint of p₀p₁ — smooth, but swinging',
      'C²: cubic pieces from the linear system — smooth and calm',
    ][k],
  inspector: (_s, k) =>
    [
      'The joints of a piecewise cubic Bézier built by hand',
      'Its cubic pieces and their control polygons: drag any point',
      'The verdict at each joint: C⁰, G¹, C¹, G² or C²',
      'At each joint, the two tangent vectors: their angle decides G¹, their lengths C¹',
      'The second derivatives and the curvature on both sides decide C² and G²',
      'The curvature comb: where its teeth jump, the curvature jumps (not G²)',
    ][k],
  catmull(s, k) {
    const n = s.p.length - 1;
    return [
      `The points p${sub(0)} … p${sub(n)}`,
      'Hermite: a tangent Tᵢ set by hand at each point; the control points are pᵢ ± Tᵢ/3',
      'Catmull-Rom takes Tᵢ = (pᵢ₊₁ − pᵢ₋₁)/2 from the neighbours, zero at the ends (uniform, α = 0)',
      'One-sided ends instead of zero: T₀ = p₁ − p₀ and Tₙ = pₙ − pₙ₋₁',
      'Centripetal, α = ½: knot gaps |pᵢ₊₁ − pᵢ|^½ — no loop, no cusp',
      'Chordal, α = 1: knot gaps |pᵢ₊₁ − pᵢ| — rounder, wider',
      'All three: the uniform one crosses itself at the hairpin, the centripetal never does',
    ][k];
  },
};

const matrixTex = (m: BezierSplinesModel) => {
  const { equations, controls } = m.system;
  const cell = (v: number) => (v === 0 ? '\\cdot' : num(v, 0));
  const rows = equations.map(
    (e, r) =>
      `${e.coefficients.map(cell).join(' & ')} & ${m.names[r].length === 1 ? m.names[r] : `c_{${r}}`} & ${num(e.right[0])} & ${num(e.right[1])}`,
  );
  void controls;
  return `\\left[\\begin{array}{${'c'.repeat(equations.length)}|c|cc}${rows.join('\\\\')}\\end{array}\\right]`;
};

/** The formula of each part's step, with the current numbers (TeX), or null. */
const formulas: Record<Part, (m: BezierSplinesModel, s: BezierSplinesState) => string | null> = {
  why(m, s) {
    const n = s.p.length - 1;
    if (s.step === 1) return `P(t) = \\sum_{i=0}^{${n}} B^{${n}}_i(t)\\,p_i`;
    if (s.step === 2)
      return `\\Delta P(t) = B^{${n}}_{${m.moved}}(t)\\cdot(0,\\,1) \\neq 0 \\text{ for every } t \\in (0,1)`;
    if (s.step === 3) return 'P_i(t) = \\sum_{j=0}^{3} B^3_j(t)\\,c_{3i+j},\\quad i = 0,\\dots,n-1';
    if (s.step === 4) {
      const far = Math.max(
        ...m.spline[0].map((q, k) =>
          Math.hypot(q[0] - m.movedSpline[0][k][0], q[1] - m.movedSpline[0][k][1]),
        ),
      );
      return `\\max_j |\\Delta c_j| \\text{ on the first piece} = ${num(far, 3)}`;
    }
    return null;
  },
  quadratic(m, s) {
    const n = s.p.length - 1;
    const k = s.step;
    if (k === 1) return `b_0 = ${pt(s.b[0])}`;
    if (k >= 2 && k <= n) {
      const i = k - 1;
      return `b_{${i}} = 2p_{${i}} - b_{${i - 1}} = 2\\cdot${pt(s.p[i])} - ${pt(m.quadraticControls[i - 1])} = ${pt(m.quadraticControls[i])}`;
    }
    if (k === n + 1)
      return `b_0 \\pm \\delta \\;\\Rightarrow\\; b_i \\pm (-1)^i\\,\\delta,\\quad \\delta = (0,\\ 0.5)`;
    return null;
  },
  system(m, s) {
    const n = s.p.length - 1;
    const c = (j: number) => (m.names[j].length === 1 ? m.names[j] : `c_{${j}}`);
    const list = (rows: string[]) => `\\begin{aligned}${rows.join('\\\\')}\\end{aligned}`;
    const inner = Array.from({ length: n - 1 }, (_, i) => 3 * (i + 1));
    switch (s.step) {
      case 2:
        return list(s.p.map((q, i) => `${c(3 * i)} &= ${pt(q)}`));
      case 3:
        return list(inner.map((k) => `${c(k - 1)} - 2${c(k)} + ${c(k + 1)} &= 0`));
      case 4:
        return list(
          inner.map((k) => `${c(k - 2)} - 2${c(k - 1)} + 2${c(k + 1)} - ${c(k + 2)} &= 0`),
        );
      case 5:
        return list([
          `${c(0)} - 2${c(1)} + ${c(2)} &= 0`,
          `${c(3 * n - 2)} - 2${c(3 * n - 1)} + ${c(3 * n)} &= 0`,
        ]);
      case 6:
        return matrixTex(m);
      case 7: {
        // Three inner points to a line, so the numbers stay large in presenter view.
        const inner = m.system.controls.flatMap((q, j) =>
          j % 3 === 0 ? [] : [`${c(j)} = ${pt(q)}`],
        );
        const lines = Array.from({ length: Math.ceil(inner.length / 3) }, (_, r) =>
          inner.slice(3 * r, 3 * r + 3).join(',\\quad '),
        );
        return list(
          [...lines, `\\max|A c - r| = ${texExponent(m.system.residual)}`].map((l) => `&${l}`),
        );
      }
      case 8:
        return `\\max_j |c_j - c_j^{\\text{natural}}| = ${texExponent(m.difference)}`;
      default:
        return null;
    }
  },
  // The grid needs every pixel of height in presenter view: its captions say it all.
  grid: () => null,
  inspector(m, s) {
    const j = m.joints[0];
    if (!j) return null;
    // A zero velocity has no direction and no length: say so instead of NaN.
    const undefinedHere = `\\text{undefined}`;
    if (s.step === 3) {
      const velocities = `P_0'(1) = ${pt(j.leftVelocity)},\\ P_1'(0) = ${pt(j.rightVelocity)}`;
      if (j.degenerate)
        return `${velocities}:\\ \\angle,\\ \\tfrac{|P_1'|}{|P_0'|}\\ ${undefinedHere}`;
      return `${velocities},\\ \\angle = ${num(j.angle, 1)}^\\circ,\\ \\tfrac{|P_1'|}{|P_0'|} = ${num(j.lengthRatio, 3)}`;
    }
    if (s.step === 4) {
      const kappa = (k: number) => (Number.isNaN(k) ? undefinedHere : num(k, 3));
      return `P_0''(1) = ${pt(j.leftSecond)},\\ P_1''(0) = ${pt(j.rightSecond)},\\ \\kappa = ${kappa(j.leftCurvature)} \\mid ${kappa(j.rightCurvature)}`;
    }
    if (s.step === 2)
      return m.joints
        .map((r, i) => `\\text{joint ${i + 1}: ${r.continuity.replace(/(\d)/, '^$1')}}`)
        .join(',\\quad ');
    return null;
  },
  catmull(m, s) {
    const p = s.p;
    if (s.step === 1)
      return `c_1 = p_1 + \\tfrac{1}{3}T_1 = ${pt(p[1])} + \\tfrac{1}{3}${pt(s.tg[1])}`;
    if (s.step === 2 && p.length > 2)
      return `T_1 = \\tfrac{1}{2}(p_2 - p_0) = ${pt(m.crTangents[1])}`;
    if (s.step === 3) return `T_0 = p_1 - p_0 = ${pt(m.oneSidedTangents[0])}`;
    if (s.step === 4 || s.step === 5) {
      const alpha = s.step === 4 ? 0.5 : 1;
      const gaps = p.slice(1).map((q, i) => Math.hypot(q[0] - p[i][0], q[1] - p[i][1]) ** alpha);
      return `\\Delta_i = |p_{i+1} - p_i|^{${alpha === 1 ? 1 : '1/2'}} = ${gaps.map((g) => num(g)).join(',\\ ')}`;
    }
    if (s.step === 6)
      return m.alphas
        .map(
          (a) =>
            `\\text{${a.name}: ${a.crossings.length} crossing${a.crossings.length === 1 ? '' : 's'}}`,
        )
        .join(',\\quad ');
    return null;
  },
};

export const steps: StepsSpec<BezierSplinesState, BezierSplinesModel> = {
  key: 'step',
  count: stepCount,
  describe: (s, k) => captions[s.part](s, k),
  formula: (m, s) => formulas[s.part](m, s),
};

const defaults = defaultsOf(schema);
const scene = (
  id: Part,
  label: string,
  change: Partial<BezierSplinesState> = {},
): Scene<BezierSplinesState> => ({
  id,
  label,
  apply: (current) => ({ ...current, ...change, part: id, step: 0 }),
});

export const scenes: Scene<BezierSplinesState>[] = [
  { id: 'why', label: 'Why pieces', apply: () => defaults },
  scene('quadratic', 'C¹ quadratic spline', {
    p: LECTURE_POINTS,
    b: [midpoint(LECTURE_POINTS[0], LECTURE_POINTS[1])],
    tg: handTangents(LECTURE_POINTS),
  }),
  scene('system', 'C² by a linear system', { p: FOUR_POINTS, tg: handTangents(FOUR_POINTS) }),
  scene('grid', 'C⁰ · C¹ · C² grid'),
  scene('inspector', 'Continuity inspector', { q: HAND_BUILT }),
  scene('catmull', 'Catmull-Rom', { p: HAIRPIN, tg: handTangents(HAIRPIN) }),
];
