import type { KitFigure } from '../../kit/lesson';
import type { Painter } from '../../render/painter';
import { type Bounds, niceStep } from '../../render/projection';
import { words } from '../../kit/format';
import { valueColumn } from '../../kit/cursorValues';
import { lineName } from '../../kit/plotMarks';
import { COLOURS } from './marks';
import type { CurvatureModel } from './model';
import { drawJoinMarks, joinSeries } from './joinsMarks';
import { cursorValues, valuesRoom } from './plotValues';
import type { Join } from './sources';
import type { CurvatureState } from './state';

const clampT = (t: number) => Math.min(1, Math.max(0, Number(t.toFixed(4))));

/** A curve of the plot: its name at the cursor, its runs, its colour (dashed for a second spline). */
export interface Series {
  name: string;
  runs: Float64Array[];
  colour: number;
  dash?: number[];
}

/** What the plot shows now: κ (or the speed first) against t or p̄, κ and τ in space, s(t) for arc length. */
function series(m: CurvatureModel): Series[] {
  const { part } = m.state;
  const { shown } = m;
  if (part === 'joins') return joinSeries(m);
  if (part === 'plane') {
    if (shown.has('curvature'))
      return [{ name: 'κ', runs: m.plane!.kappa, colour: COLOURS.curvature }];
    return shown.has('velocity') ? [{ name: '|P′|', runs: m.plane!.speed, colour: 4 }] : [];
  }
  if (part === 'space') {
    const out = [];
    if (shown.has('normal'))
      out.push({ name: 'κ', runs: m.space.kappa, colour: COLOURS.curvature });
    if (shown.has('binormal')) out.push({ name: 'τ', runs: m.space.tau, colour: COLOURS.torsion });
    return out;
  }
  return shown.has('arcLength') ? [{ name: 's', runs: [m.arc!.plot], colour: 3 }] : [];
}

function plotBounds(m: CurvatureModel): Bounds {
  let [low, high] = [0, 0];
  const { part } = m.state;
  // κ of the plane curve from the step that names it on; the speed before.
  const kappa = part === 'plane' && m.shown.has('curvature');
  // The axes are set by everything the part will show, so stepping does not rescale them.
  const runs =
    part === 'joins'
      ? [...m.plane!.kappa, ...m.joins!.catmull.kappa]
      : part === 'plane'
        ? kappa
          ? m.plane!.kappa
          : m.plane!.speed
        : part === 'space'
          ? [...m.space.kappa, ...m.space.tau]
          : [m.arc!.plot];
  for (const run of runs)
    for (let i = 1; i < run.length; i += 2) {
      low = Math.min(low, run[i]);
      high = Math.max(high, run[i]);
    }
  const cap =
    part === 'joins'
      ? 1.25 * Math.max(m.plane!.kappaCap, m.joins!.catmull.kappaCap)
      : kappa
        ? 1.25 * m.plane!.kappaCap
        : part === 'space'
          ? 1.25 * m.space.cap
          : Infinity;
  low = Math.max(low, -cap);
  high = Math.min(high, cap);
  const pad = 0.08 * (high - low || 1);
  return { minX: 0, maxX: pieces(m), minY: low - (low < 0 ? pad : 0), maxY: high + pad };
}

/** The plane curve's pieces: the plot runs over the global p̄ ∈ [0, pieces], p̄ = pieces·t. */
const pieces = (m: CurvatureModel) =>
  m.state.part === 'plane' || m.state.part === 'joins' ? m.plane!.pieces.segments.length : 1;

/** The plot's x: t for one piece; the global p̄ = i + p across pieces (piece i, local p), as in the lecture slides. */
const axisName = (m: CurvatureModel) => (pieces(m) > 1 ? 'p̄ = i + p' : 't');

export const plotFigure: KitFigure<CurvatureState, CurvatureModel> = {
  id: 'plot',
  title: 'κ(t), τ(t) or s(t) plotted against t (or the global p̄ across pieces), with a cursor at t',
  kind: 'plot',
  bounds: plotBounds,
  // The values at the cursor in a row above the plot, off the curves they
  // read (boxed in its corner they stood on κ's peak): as many as the part
  // plots at once, the widest its longest name with a two-digit negative.
  cursorValues: (m) => valuesRoom(m.state.part),
  draw(painter, m, info) {
    const theme = painter.theme;
    const bounds = plotBounds(m);
    const shown = series(m);
    const t = m.state.t * pieces(m);
    if (!info.thumbnail)
      painter.plotAxes(
        bounds,
        pieces(m) > 1 ? niceStep(pieces(m) / 8) : 0.1,
        yStep(painter, bounds),
        axisName(m),
        // Both of the joins' curves are κ (their values above say whose is whose).
        m.state.part === 'joins' ? 'κ' : shown.map((s) => s.name).join(', '),
      );
    const entries = cursorValues(m).filter((e) => shown.some((s) => s.name === e.name));
    // The values at the cursor, boxed in the top corner away from it, off the
    // curves they name. Labels are placed when all is drawn, in the order
    // given: these first, and the lines' names (drawMarks) find room round them.
    if (!info.thumbnail)
      valueColumn(
        painter,
        t,
        bounds,
        Math.max(painter.view.toScreen([bounds.minX, bounds.maxY])[1], 0),
        entries
          .filter((e) => e.y >= bounds.minY && e.y <= bounds.maxY)
          .sort((a, b) => b.y - a.y)
          .map((e) => ({ text: `${e.name} = ${words(e.y)}`, color: painter.color(e.colour) })),
      );
    drawMarks(painter, m, bounds, info.thumbnail);
    for (const s of shown)
      for (const run of s.runs)
        painter.polylineFlat(run, {
          color: painter.color(s.colour),
          width: theme.sizes.curve,
          dash: s.dash,
        });
    painter.segment([t, bounds.minY], [t, bounds.maxY], {
      color: theme.accent,
      width: theme.sizes.line,
    });
    for (const e of entries)
      if (e.y >= bounds.minY && e.y <= bounds.maxY) painter.dot([t, e.y], painter.color(e.colour));
  },
  handles: (m) => [
    {
      id: 'cursor',
      label: 't',
      position: [m.state.t * pieces(m), plotBounds(m).minY],
      shape: 'diamond',
      showLabel: false,
    },
  ],
  moveHandle: (state, _id, to, m) => ({ ...state, t: clampT(to[0] / pieces(m)) }),
  pickAt: (m, at, tolerance) =>
    Math.abs(at[0] - m.state.t * pieces(m)) <= tolerance ? 'cursor' : null,
  weight: 2,
};

/** Inflections and cusps (plane), frame flips (space), the table and its inverse (arc length). */
function drawMarks(painter: Painter, m: CurvatureModel, bounds: Bounds, thumbnail: boolean): void {
  const theme = painter.theme;
  const { part } = m.state;
  const { shown } = m;
  const vertical = (t: number, text: string | null) => {
    painter.segment([t, bounds.minY], [t, bounds.maxY], {
      color: theme.muted,
      width: theme.sizes.thin,
      dash: [4, 4],
    });
    if (!thumbnail && text) lineName(painter, t, bounds, text, { color: theme.muted, halo: true });
  };
  if (part === 'plane') drawJoins(painter, m, bounds, thumbnail);
  if (part === 'joins') drawJoinMarks(painter, m, bounds, thumbnail);
  if (part === 'plane' && shown.has('inflections')) {
    // At the cursor the value column already says "κ = 0": the line is not named twice.
    const [cursor] = painter.view.toScreen([m.state.t * pieces(m), 0]);
    const atCursor = (t: number) => Math.abs(painter.view.toScreen([t, 0])[0] - cursor) < 1;
    for (const t of m.plane!.inflections)
      if (atCursor(t)) vertical(t, null);
      else vertical(t, 'κ = 0');
    for (const t of m.plane!.cusps) vertical(t, t === 0 || t === pieces(m) ? 'P′ = 0' : 'cusp');
  }
  if (part === 'space' && shown.has('flips')) for (const t of m.space.flips) vertical(t, 'flip');
  if (part !== 'arc') return;
  const arc = m.arc!;
  if (shown.has('table'))
    for (const row of arc.table) painter.dot([row.t, row.s], painter.color(0), theme.sizes.point);
  if (shown.has('equalLength'))
    for (const row of arc.equal) {
      const colour = painter.color(1);
      painter.segment([0, row.s], [row.t, row.s], {
        color: colour,
        width: theme.sizes.thin,
        dash: [5, 4],
      });
      painter.segment([row.t, row.s], [row.t, bounds.minY], {
        color: colour,
        width: theme.sizes.thin,
      });
    }
}

/**
 * The joins of a piecewise curve: a line at each, named by its continuity once
 * κ is shown, where a C¹ or G¹ join also says how far κ jumps.
 */
function drawJoins(painter: Painter, m: CurvatureModel, bounds: Bounds, thumbnail: boolean): void {
  const theme = painter.theme;
  const labels = !thumbnail && m.shown.has('curvature');
  const { joins } = m.plane!.pieces;
  // Many joins would bury each other's names: then only the one nearest the cursor is named.
  const cursor = m.state.t * pieces(m);
  const nearest = joins.reduce(
    (best, join) => (Math.abs(join.s - cursor) < Math.abs(best - cursor) ? join.s : best),
    Infinity,
  );
  for (const join of joins) {
    painter.segment([join.s, bounds.minY], [join.s, bounds.maxY], {
      color: theme.polygon,
      width: theme.sizes.thin,
      dash: [2, 4],
    });
    if (labels && (joins.length <= 8 || join.s === nearest))
      lineName(painter, join.s, bounds, joinLabel(join), {
        color: theme.muted,
        halo: true,
        from: 'foot',
      });
  }
}

/** "C²", or "C¹: κ 0.52 → 0.61" where κ jumps (three decimals at most: a residue reads 0). */
export function joinLabel(join: Join): string {
  const name = join.continuity.replace('1', '¹').replace('2', '²').replace('0', '⁰');
  const { before, after } = join;
  if (before === null || after === null) return name;
  const [from, to] = [words(before), words(after)];
  const jumps = Math.abs(after - before) > 1e-9 * Math.max(1, Math.abs(before)) && from !== to;
  return jumps ? `${name}: κ ${from} → ${to}` : name;
}

/** A y step whose tick numbers have room: about one per three text heights. */
function yStep(painter: Painter, bounds: Bounds): number {
  const fits = Math.max(1, Math.floor(painter.view.height / (3 * painter.theme.sizes.small)));
  return niceStep((bounds.maxY - bounds.minY) / Math.min(4, fits));
}
