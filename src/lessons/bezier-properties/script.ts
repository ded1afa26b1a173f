import { type Point, distance } from '../../math';
import { sub, texExponent, texNumber, texPoint, texT, words } from '../../kit/format';
import type { ModelOf, PropertiesModel } from './model';
import { type ExperimentId, type MapKind, type PropertiesState, STAGES, amount } from './state';

// The clicker's script of each experiment: a caption per step, in words, and
// the step's formula with its numbers. The parameter is t throughout.

/** A number in a caption: up to three decimals, trailing zeros dropped, a true minus. */
const plural = (count: number, one: string, many = `${one}s`) =>
  `${count} ${count === 1 ? one : many}`;

const MAP_NAMES: Record<MapKind, string> = {
  rotate: 'a rotation',
  scale: 'a scaling',
  shear: 'a shear',
  perspective: 'a perspective map',
};

/** The control points, in words: "The 4 control points P₀ … P₃". */
const controlPoints = (p: readonly Point[]) =>
  `The ${p.length} control points P₀ … P${sub(p.length - 1)}`;

/** Indices of the points the local-control experiment moved from its "before" curve. */
const movedPoints = (state: PropertiesState) =>
  state.p.flatMap((q, i) => (state.q[i] && distance(q, state.q[i]) > 0 ? [i] : []));

type Captions = (state: PropertiesState, k: number) => string;

const CAPTIONS: Record<ExperimentId, Captions> = {
  ends(s, k) {
    const n = s.p.length - 1;
    return [
      controlPoints(s.p),
      'Join them: the control polygon',
      'The Bézier curve of these points',
      `It starts at P₀ and ends at P${sub(n)}: P(0) = P₀, P(1) = P${sub(n)}`,
      `It leaves along the first leg and arrives along the last, at ${n} times their length`,
      `At t = ${words(s.t)}: the point P(t) and its tangent P′(t)`,
    ][k];
  },
  hull(s, k) {
    return [
      controlPoints(s.p),
      'Join them: the control polygon',
      'Their convex hull: the smallest convex region that holds them all',
      'The curve never leaves the hull',
      `Each P(t) is an average of the control points with weights ≥ 0; here t = ${words(s.t)}`,
    ][k];
  },
  local(s, k) {
    const moved = movedPoints(s);
    const which = moved.length ? moved.map((i) => `P${sub(i)}`).join(', ') : 'no point';
    return [
      `${controlPoints(s.p)}, as they are now`,
      'Before: the curve of the points as they were, dashed',
      `${which} moved; every other control point stayed`,
      'After: the new curve. All of it moved, not just the part near the moved point',
      'The largest move of the curve, marked',
    ][k];
  },
  repeat(s, k) {
    if (k === 0) return controlPoints(s.p);
    if (k === 1) return `The curve with every control point once; P${sub(s.r)} will be repeated`;
    return `P${sub(s.r)} listed ${k} times: its weights add up and pull the curve towards it`;
  },
  closed(s, k) {
    const n = s.p.length;
    return [
      `${controlPoints(s.p)}; P₀ will be repeated at the end`,
      `The closed polygon P₀ … P${sub(n - 1)}, P${sub(n)} = P₀`,
      'The closed Bézier curve: it ends where it starts',
      `At P₀ it leaves along P₁ − P₀ and arrives along P₀ − P${sub(n - 1)}`,
      `P(t) runs once round the closed curve; here t = ${words(s.t)}`,
    ][k];
  },
  elevate(s, k) {
    const n = s.p.length - 1;
    if (k === 0) return controlPoints(s.p);
    if (k === 1) return `The curve of degree ${n} and its polygon`;
    const j = amount(s);
    return `Degree raised ${plural(j, 'time')}, to ${n + j}: the same curve, a polygon closer to it`;
  },
  split(s, k) {
    if (k === 0) return controlPoints(s.p);
    if (k === 1) return `The curve and its polygon; it will be split at t = ${words(s.t)}`;
    const j = amount(s);
    return `${plural(j, 'split')} at t: ${2 ** j} pieces, each with a polygon of its own`;
  },
  affine(s, k) {
    const affine = s.m !== 'perspective';
    return [
      controlPoints(s.p),
      'The curve and its polygon',
      `The control points mapped by ${MAP_NAMES[s.m]}`,
      'The Bézier curve of the mapped points',
      affine
        ? 'The map of the curve itself, dashed: the very same curve'
        : 'The map of the curve itself, dashed: not the same curve',
      `P(t) at t = ${words(s.t)}, and where each image has it`,
    ][k];
  },
  cubic(s, k) {
    return [
      controlPoints(s.p),
      'Join them: the control polygon',
      'The cubic Bézier curve',
      'Coloured by the way it turns: to the left in one colour, to the right in another',
      'Where it changes its turning (inflections) or crosses itself (a loop), with their t',
      `P(t) at t = ${words(s.t)}`,
    ][k];
  },
  hermite(s, k) {
    return [
      controlPoints(s.p),
      'The Bézier cubic and its polygon',
      'Its Hermite data: the end points and the end tangents 3(P₁ − P₀), 3(P₃ − P₂)',
      'The Hermite curve of that data, dashed: the same curve',
      `P(t) at t = ${words(s.t)}, the same from both forms`,
    ][k];
  },
};

/** The caption of step k of the experiment shown. */
export function describeStep(state: PropertiesState, k: number): string {
  return CAPTIONS[state.x](state, k);
}

type Formulas = { [X in ExperimentId]: (m: ModelOf<X>, k: number) => string | null };

const FORMULAS: Formulas = {
  ends(m, k) {
    const n = m.n;
    const [start, end, at] = m.tangents;
    if (k === STAGES.ends.ends)
      return `P(0) = P_0 = ${texPoint(m.controls[0], 3)},\\quad P(1) = P_{${n}} = ${texPoint(m.controls[n], 3)}`;
    if (k === STAGES.ends.tangents)
      return `P'(0) = ${n}(P_1 - P_0) = ${texPoint(start.vector, 3)},\\quad P'(1) = ${n}(P_{${n}} - P_{${n - 1}}) = ${texPoint(end.vector, 3)}`;
    if (k === STAGES.ends.point)
      return `P(${texT(m.state.t)}) = ${texPoint(m.point, 3)},\\quad P'(${texT(m.state.t)}) = ${texPoint(at.vector, 3)}`;
    return null;
  },
  hull(m, k) {
    if (k === STAGES.hull.curve)
      return `\\text{${m.inside} of ${m.total} curve samples in the hull}`;
    if (k === STAGES.hull.point) {
      const n = m.controls.length - 1;
      return `P(t) = \\sum_{i=0}^{${n}} W(${n},i,t)\\,P_i,\\quad W \\ge 0,\\quad \\sum_i W(${n},i,t) = 1`;
    }
    return null;
  },
  local(m, k) {
    const single = m.single;
    if (!single) return null;
    const i = single.index;
    const shift = `${texNumber(single.shift, 3)}`;
    if (k === STAGES.local.moved) return `|\\Delta P_{${i}}| = ${shift}`;
    if (k === STAGES.local.curve)
      return `P_{\\text{after}}(t) - P_{\\text{before}}(t) = W(${m.n},${i},t)\\,\\Delta P_{${i}}`;
    if (k === STAGES.local.largest)
      return `\\max_t |\\Delta P(t)| = W(${m.n},${i},\\tfrac{${i}}{${m.n}})\\cdot ${shift} = ${texNumber(single.peak * single.shift, 3)}`;
    return null;
  },
  repeat(m, k) {
    if (k < 1) return null;
    const { r, t } = m.state;
    return `\\text{weight of } P_{${r}} \\text{ at } t = ${texT(t)}:\\ ${texNumber(m.weight, 4)}\\quad(\\text{once: } ${texNumber(m.weightOnce, 4)})`;
  },
  closed(m, k) {
    if (k !== STAGES.closed.tangents) return null;
    const n = m.n;
    const angle = m.corner === null ? '' : `,\\quad \\text{angle } ${m.corner.toFixed(1)}^\\circ`;
    return `P'(0) = ${n}(P_1 - P_0),\\quad P'(1) = ${n}(P_0 - P_{${n - 1}})${angle}`;
  },
  elevate(m, k) {
    if (k < 2) return null;
    const gap = m.gaps[m.gaps.length - 1];
    return `Q_i = \\tfrac{i}{N+1}P_{i-1} + \\bigl(1 - \\tfrac{i}{N+1}\\bigr)P_i,\\quad \\max_i |Q_i - P(\\tfrac{i}{${m.n}})| = ${texNumber(gap, 4)}`;
  },
  split(m, k) {
    if (k < 2) return null;
    return `\\text{largest gap between a polygon and its piece: } ${texNumber(m.gaps[m.gaps.length - 1], 5)}`;
  },
  affine(m, k) {
    const images = m.images;
    if (!images.ok || k < STAGES.affine.mappedCurve) return null;
    return `\\max_t |\\text{map of } P(t) - \\text{curve of mapped points}| = ${images.distance < 1e-9 ? texExponent(images.distance) : texNumber(images.distance, 4)}`;
  },
  cubic(m, k) {
    if (k !== STAGES.cubic.marks) return null;
    const parts = m.inflections.map(({ t }) => `t = ${t.toFixed(3)}`);
    if (m.loop)
      parts.push(
        `\\text{crossing at } t = ${m.loop.t[0].toFixed(3)} \\text{ and } ${m.loop.t[1].toFixed(3)}`,
      );
    return parts.length ? parts.join(',\\quad ') : '\\text{no inflection, no loop}';
  },
  hermite(m, k) {
    if (k === STAGES.hermite.tangents)
      return `x_0' = 3(P_1 - P_0) = ${texPoint(m.d0, 3)},\\quad x_1' = 3(P_3 - P_2) = ${texPoint(m.d1, 3)}`;
    if (k === STAGES.hermite.hermite)
      return `\\max_t |\\text{Bézier} - \\text{Hermite}| = ${texExponent(m.deviation)}`;
    if (k === STAGES.hermite.point) return `P(${texT(m.state.t)}) = ${texPoint(m.point, 3)}`;
    return null;
  },
};

function formulaOf<X extends ExperimentId>(x: X, m: ModelOf<X>, k: number): string | null {
  return (FORMULAS[x] as (m: ModelOf<X>, k: number) => string | null)(m, k);
}

/** The formula of the current step with its numbers (TeX); null where the step has none. */
export function stepFormula(m: PropertiesModel, state: PropertiesState): string | null {
  return formulaOf(m.x, m as ModelOf<typeof m.x>, state.k);
}

/** The point P(t) the figure shows at this step, for presenter view's trail; null before it. */
export function movingPoint(m: PropertiesModel): Point | null {
  const k = m.state.k;
  switch (m.x) {
    case 'ends':
    case 'hull':
    case 'closed':
    case 'affine':
    case 'cubic':
    case 'hermite':
      return k >= STAGES[m.x].point ? m.point : null;
    case 'repeat':
    case 'split':
      return k >= STAGES[m.x].curve ? m.point : null;
    default:
      return null;
  }
}
