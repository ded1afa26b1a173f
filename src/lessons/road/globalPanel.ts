import { dataTable, h, setHidden, setText } from '../../app/dom';
import { type RowSpec, LiveRows } from '../../app/liveTable';
import { fixed, sub, words } from '../../kit/format';
import { LiveFormula } from '../../render/formula';
import { type FormulaParts, live, livePoint, tex } from '../../render/formulaParts';
import { texNumber, texResidue } from '../../kit/format';
import type { GlobalChange } from './globalChange';
import type { RoadModel } from './model';
import { LABEL_VILLAGES } from './points';

/** What the panel says at each step of the global view. */
function stepText(step: string, { moved, mapped }: GlobalChange): string {
  switch (step) {
    case 'gradients':
      return 'The gradients D₀ … Dₘ of the natural road, solved from the whole system at once: each one depends on every village.';
    case 'move':
      return `P${sub(moved.index)} moves up by ${words(moved.shift[1])}; the system is solved again with the new right-hand side.`;
    case 'changes':
      return 'Every gradient changes, even at the far ends: the natural spline is global. Local control belongs to Bézier pieces and B-splines: there a control point moves only the pieces that use it (at most four for a cubic B-spline). Passing through every village with C² cubics is paid for with a road that moves everywhere.';
    case 'map':
      return `An affine map x ↦ A x + t: here A turns by ${mapped.map.turn}° and scales by ${words(mapped.map.scale)}, and t moves the villages beside the old ones. The old road, mapped by the same map, is dashed.`;
    case 'mapped':
      return 'The natural road through the mapped villages runs along the dashes: the spline of the mapped villages is the mapped spline. S(P) is the natural road through villages P, compared at the same p̄.';
    default:
      return 'The natural spline through these villages, then one village moved, then all of them mapped.';
  }
}

/** Why the road maps with its villages, and what would not. */
const WHY =
  'Why it holds: the road is parametric. x(p̄) and y(p̄) are each solved with the same matrix, which depends only on how many villages there are (p̄ᵢ = i), and the right-hand sides are differences of villages, 3(Pᵢ₊₁ − Pᵢ₋₁): a shift t drops out and A carries through. The gradients of the mapped villages are A Dᵢ, and every piece maps with its ends and gradients. It would not hold for a road drawn as a graph y(x) over the map’s x: turn the map a quarter and the villages’ x no longer increase, so no graph goes through them.';

/** The gradients before and after the move, row by row (the first LABEL_VILLAGES). */
function gradientRows(change: GlobalChange, moved: boolean): RowSpec[] {
  const point = (d: readonly number[]) => `(${fixed(d[0], 2)}, ${fixed(d[1], 2)})`;
  return change.road.gradients.slice(0, LABEL_VILLAGES).map((d, i) => ({
    heading: true,
    className: moved && i === change.moved.index ? 'current' : '',
    cells: [
      `D${sub(i)}`,
      point(d),
      moved ? point(change.moved.road.gradients[i]) : '—',
      moved ? fixed(change.moved.changes[i], 2) : '—',
    ],
  }));
}

/**
 * The map, and once the road through the mapped villages is drawn, how far it
 * is from the mapped road: a rounding residue reads 0, as in the step's formula
 * (it read 0.000000).
 */
export function mapFormula(change: GlobalChange, compared: boolean): FormulaParts {
  const { map, gap } = change.mapped;
  const entry = (v: number) => live(texNumber(v, 4));
  const [[a, b], [c, d]] = map.matrix;
  const matrix = tex`A = \begin{bmatrix}${entry(a)} & ${entry(b)}\\ ${entry(c)} & ${entry(d)}\end{bmatrix},\ t = ${livePoint(map.shift)}`;
  return compared
    ? tex`${matrix},\quad \max_{\bar p} |{S(AP_i + t) - (A\,S(P_i) + t)}| = ${live(texResidue(gap))}`
    : matrix;
}

/** The global view's section: the step in words, the gradients before and after, the map. */
export function globalSection() {
  const title = h('h2', {}, 'Global, and affine-invariant');
  const text = h('p', {});
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  // The rows' heading is their name, Dᵢ (a phone's panel: "Gradient" took
  // the room the |change| column needed, 384 px in 336); columns set close.
  const table = dataTable(
    'Gradients before and after the move',
    ['Dᵢ', 'before', 'after', '|change|'],
    body,
    'road-gradients matrix',
  );
  const formula = new LiveFormula(true);
  const why = h('p', { class: 'note' }, WHY);
  const element = h(
    'section',
    { 'aria-label': 'Global, and affine-invariant' },
    title,
    text,
    table,
    formula.element,
    why,
  );

  return {
    element,
    update(m: RoadModel) {
      const change = m.globalChange;
      setHidden(element, !change);
      if (!change) return;
      const { shown } = m;
      setText(text, stepText(shown.name, change));
      setHidden(table, !shown.has('gradients'));
      rows.set(gradientRows(change, shown.has('changes')));
      setHidden(formula.element, !shown.has('map'));
      if (shown.has('map')) formula.set(mapFormula(change, shown.has('mapped')));
    },
  };
}
