import type { DrawInfo, FigureSpec, Handle, Point2 } from '../../app/lesson';
import { type Point, bezierPoint } from '../../math';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/viewport';
import {
  asCubic,
  drawCurvatureComb,
  drawFigureNote,
  drawLegend,
  drawOverlayCurve,
  drawParameterTicks,
  drawRoadway,
} from './mapDrawing';
import { villageNotes } from './notes';
import {
  CURVES,
  type Road,
  buildRoad,
  endGradient,
  quadraticControl,
  roadGradients,
  startGradient,
} from './roads';
import { buildSolve, builtPieces, isFixed, solveProgress } from './solve';
import {
  MAX_VILLAGES,
  type RoadState,
  hasSolve,
  insertVillage,
  keepStepEnd,
  roundCoordinate,
  roundPoint,
  stepCount,
} from './state';

/** Up to this many villages every one is labelled and decorated; beyond, the map stays legible. */
const LABEL_VILLAGES = 40;
/** Up to this many segments the parameter ticks are drawn. */
const TICK_SEGMENTS = 60;

/** Are the handles for the end gradients (the other roads) in play? */
export const usesEndGradients = (state: RoadState) =>
  state.overlay
    ? state.compare.includes(4) || (state.ends && state.compare.includes(2))
    : state.road === 'clamped' || (state.road === 'hermite' && state.ends);

export const usesQuadraticHandle = (state: RoadState) =>
  state.overlay ? state.compare.includes(1) : state.road === 'quadratic';

/** The method's road as drawn now: the pieces found so far while stepping through the solve. */
export function primaryRoad(state: RoadState): Road {
  if (hasSolve(state) && state.step < stepCount(state)) {
    const solve = buildSolve(state)!;
    return {
      kind: 'pieces',
      pieces: builtPieces(state, solve, solveProgress(solve.n, state.step)),
      closed: false,
    };
  }
  return buildRoad(state.road, state);
}

/** The piece and local parameter p of the global p̄ on a road of `count` pieces. */
export function localParameter(s: number, count: number): { piece: number; p: number } {
  const piece = Math.max(0, Math.min(Math.floor(s), count - 1));
  return { piece, p: s - piece };
}

const plus = (p: Point, d: Point, k: number): Point2 => [p[0] + d[0] * k, p[1] + d[1] * k];

export const mapFigure: FigureSpec<RoadState> = {
  id: 'map',
  title: 'Map: the villages and the road through them',
  kind: 'geometry',
  bounds(state) {
    const points: Point[] = [...state.v];
    if (usesQuadraticHandle(state)) points.push(quadraticControl(state));
    if (usesEndGradients(state)) points.push(...endHandlePositions(state), ...otherRoadEnds(state));
    // A cubic road stays within its control points: fit them too (the ring road bulges out).
    // The quadratic's may fly far off: its swings are the lesson, shown to the edge of the map.
    if (!state.overlay && state.road !== 'quadratic' && state.road !== 'roman') {
      const road = buildRoad(state.road, state);
      if (road.kind === 'pieces' && road.pieces.length <= 100) points.push(...road.pieces.flat());
    }
    return boundsOf(points);
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    const few = state.v.length <= LABEL_VILLAGES;
    if (few && !info.thumbnail) {
      for (const village of state.v)
        painter.ring(village, theme.sizes.handle * 2.2, { alpha: 0 }, painter.color(2), 0.16);
    }
    if (state.overlay) {
      drawOverlay(painter, state, info);
      return;
    }
    if (usesEndGradients(state)) drawOtherRoads(painter, state);
    const road = primaryRoad(state);
    const solving = hasSolve(state) && state.step < stepCount(state);
    if (solving) drawSolveProgress(painter, state);
    if (road.kind === 'pieces') {
      // The comb first: the road covers the bases of its teeth.
      if (state.comb) drawComb(painter, state, road.pieces);
      drawRoadway(painter, road.pieces, painter.color(4));
      const hovered = info.hover?.startsWith('seg') ? Number(info.hover.slice(3)) : -1;
      if (hovered >= 0 && hovered < road.pieces.length && !solving) {
        painter.cubicSegments([asCubic(road.pieces[hovered])], {
          color: theme.accent,
          width: theme.sizes.curve * 1.2,
        });
      }
    } else if (road.kind === 'missing' && !info.thumbnail) {
      painter.polyline(state.v, { color: theme.curveFaint, width: theme.sizes.line, dash: [6, 6] });
    }
    drawMethodAids(painter, state, info);
    if (info.thumbnail) return;
    if (road.kind === 'pieces' && !solving && road.pieces.length) {
      if (road.pieces.length <= TICK_SEGMENTS) drawParameterTicks(painter, road.pieces);
      drawMarkerLabel(painter, state, road.pieces);
    }
    const notes = villageNotes(state).map(shorten);
    if (road.kind === 'missing') notes.unshift(shorten(road.why));
    if (notes.length) drawFigureNote(painter, notes);
  },
  drawOver(painter, state, info) {
    if (info.thumbnail || state.overlay) return;
    if (hasSolve(state) && state.step < stepCount(state)) drawFixedGradients(painter, state);
  },
  handles(state) {
    const handles: Handle[] = [];
    if (usesQuadraticHandle(state)) {
      handles.push({ id: 'q', label: 'B_0', position: quadraticControl(state), shape: 'square' });
    }
    if (usesEndGradients(state)) {
      const [a, b] = endHandlePositions(state);
      handles.push({ id: 'a', label: 'D_0', position: a, shape: 'square' });
      handles.push({ id: 'b', label: `D_${state.v.length - 1}`, position: b, shape: 'square' });
    }
    const road = state.overlay ? null : primaryRoad(state);
    if (
      road?.kind === 'pieces' &&
      road.pieces.length &&
      !(hasSolve(state) && state.step < stepCount(state))
    ) {
      const { piece, p } = localParameter(state.s, road.pieces.length);
      const at = bezierPoint(road.pieces[piece], p);
      handles.push({
        id: 's',
        label: 'p̄',
        position: [at[0], at[1]],
        shape: 'diamond',
        showLabel: false,
      });
    }
    const few = state.v.length <= LABEL_VILLAGES;
    state.v.forEach((village, i) =>
      handles.push({
        id: `p${i}`,
        label: `P_${i}`,
        position: village,
        showLabel: few,
        small: !few,
      }),
    );
    return handles;
  },
  moveHandle(state, id, to) {
    const v = state.v;
    switch (id) {
      case 'q':
        return { ...state, q: gradient(to, v[0], 2) };
      case 'a':
        return { ...state, a: gradient(to, v[0], 3) };
      case 'b':
        return { ...state, b: gradient(to, v[v.length - 1], 3) };
      case 's':
        return { ...state, s: nearestParameter(state, to) };
      default: {
        const i = Number(id.slice(1));
        return { ...state, v: v.map((p, k) => (k === i ? roundPoint(to) : p)) };
      }
    }
  },
  addPoint(state, at) {
    if (state.v.length >= MAX_VILLAGES) return null;
    return keepStepEnd(state, { ...state, v: insertVillage(state.v, at) });
  },
  removeHandle(state, id) {
    if (!id.startsWith('p') || state.v.length <= 2) return null;
    const i = Number(id.slice(1));
    return keepStepEnd(state, { ...state, v: state.v.filter((_, k) => k !== i) });
  },
  hoverAt(state, at, tolerance) {
    if (state.overlay) return null;
    const road = primaryRoad(state);
    if (road.kind !== 'pieces') return null;
    const near = nearestOnPieces(road.pieces, at, 8);
    return near && near.distance <= tolerance * 2 ? `seg${near.piece}` : null;
  },
};

/** Where the end-gradient handles sit: the tips of D0/3 and Dm/3 (the Bézier control points' offsets). */
function endHandlePositions(state: RoadState): [Point2, Point2] {
  const v = state.v;
  return [
    plus(v[0], startGradient(state), 1 / 3),
    plus(v[v.length - 1], endGradient(state), 1 / 3),
  ];
}

/** The gradient whose tip (scaled by 1/k) is at `to`, kept to 0.01. */
const gradient = (to: Point2, from: Point, k: number) => [
  roundCoordinate((to[0] - from[0]) * k),
  roundCoordinate((to[1] - from[1]) * k),
];

/** The p̄ of the road point nearest to `to`, to 0.01. */
function nearestParameter(state: RoadState, to: Point2): number {
  const road = primaryRoad(state);
  if (road.kind !== 'pieces' || !road.pieces.length) return state.s;
  const near = nearestOnPieces(road.pieces, to, road.pieces.length > 100 ? 16 : 64)!;
  return Math.round((near.piece + near.t) * 100) / 100;
}

function nearestOnPieces(
  pieces: readonly Point[][],
  at: readonly number[],
  samples: number,
): { piece: number; t: number; distance: number } | null {
  let best: { piece: number; t: number; distance: number } | null = null;
  pieces.forEach((piece, i) => {
    for (let j = 0; j <= samples; j++) {
      const p = bezierPoint(piece, j / samples);
      const d = Math.hypot(p[0] - at[0], p[1] - at[1]);
      if (!best || d < best.distance) best = { piece: i, t: j / samples, distance: d };
    }
  });
  return best;
}

function drawOverlay(painter: Painter, state: RoadState, info: DrawInfo): void {
  const entries = [...state.compare]
    .sort((x, y) => x - y)
    .map((index) => {
      const road = buildRoad(CURVES[index].id, state);
      drawOverlayCurve(painter, road, index);
      return { index, missing: road.kind === 'missing' ? road.why : null };
    });
  drawMethodAids(painter, state, info);
  if (info.thumbnail) return;
  const below = entries.length ? drawLegend(painter, entries) : undefined;
  // Curves left out say why in the legend and the panel; the map keeps the villages' notes.
  const notes = villageNotes(state);
  if (notes.length) drawFigureNote(painter, notes.map(shorten), below);
}

/** The figure says the first sentence; the panel has the whole text. */
const shorten = (text: string) => text.split(/(?<=\.)\s/)[0];

/** Where the existing roads at P0 and Pm start and end: a quarter of the map along ∓D0, ±Dm. */
function otherRoadEnds(state: RoadState): [Point2, Point2] {
  const v = state.v;
  const a = startGradient(state);
  const b = endGradient(state);
  const length = Math.max(...boundsSpan(v), 1) * 0.25;
  const unit = (g: Point) => length / Math.max(1e-9, Math.hypot(g[0], g[1]));
  return [plus(v[0], a, -unit(a)), plus(v[v.length - 1], b, unit(b))];
}

/** The roads the new one must join at P0 and Pm, leaving along the chosen gradients. */
function drawOtherRoads(painter: Painter, state: RoadState): void {
  const v = state.v;
  const [start, end] = otherRoadEnds(state);
  const faint = painter.theme.curveFaint;
  drawRoadway(painter, [[start, v[0]]], faint);
  drawRoadway(painter, [[v[v.length - 1], end]], faint);
  const style = {
    size: painter.theme.sizes.small,
    color: painter.theme.muted,
    halo: true,
    align: 'center' as const,
  };
  painter.label('existing road', start, { ...style, dy: -painter.theme.sizes.curve * 3 });
  painter.label('existing road', end, { ...style, dy: -painter.theme.sizes.curve * 3 });
}

function boundsSpan(points: readonly Point[]): [number, number] {
  const b = boundsOf(points);
  return [b.maxX - b.minX, b.maxY - b.minY];
}

/** Construction lines of each method: gradients, control points, chosen ends. */
function drawMethodAids(painter: Painter, state: RoadState, info: DrawInfo): void {
  if (info.thumbnail) return;
  const theme = painter.theme;
  const v = state.v;
  const few = v.length <= LABEL_VILLAGES;
  if (usesQuadraticHandle(state)) {
    const road = buildRoad('quadratic', state);
    if (road.kind === 'pieces' && v.length <= 60 && !state.overlay) {
      // The control polygon P0 B0 P1 B1 …: each Bi is the reflection of B(i−1) in Pi.
      const polygon: Point[] = road.pieces.flatMap((piece) => piece.slice(0, 2));
      polygon.push(v[v.length - 1]);
      painter.polyline(polygon, { color: theme.polygon, width: theme.sizes.thin, dash: [5, 5] });
      road.pieces
        .slice(1)
        .forEach((piece) => painter.dot(piece[1], theme.polygon, theme.sizes.point * 0.7));
    }
    painter.arrow(v[0], quadraticControl(state), { color: theme.accent, width: theme.sizes.line });
  }
  if (usesEndGradients(state)) {
    const [a, b] = endHandlePositions(state);
    painter.arrow(v[0], a, { color: theme.accent, width: theme.sizes.line });
    painter.arrow(v[v.length - 1], b, { color: theme.accent, width: theme.sizes.line });
  }
  if (!state.overlay && state.road === 'hermite' && few) {
    // The gradient of each piece at each village, from the parabola through it and its neighbours.
    const tangents = roadGradients('hermite', state)!;
    v.forEach((p, i) => {
      if (state.ends && (i === 0 || i === v.length - 1)) return;
      painter.arrow(p, plus(p, tangents[i], 1 / 3), {
        color: painter.color(0),
        width: theme.sizes.line,
      });
    });
  }
}

/** While the solve is under way: the road not yet built, and each gradient as it is fixed. */
function drawSolveProgress(painter: Painter, state: RoadState): void {
  const theme = painter.theme;
  const solve = buildSolve(state)!;
  const progress = solveProgress(solve.n, state.step);
  painter.polyline(state.v, { color: theme.curveFaint, width: theme.sizes.line, dash: [6, 6] });
  if (state.v.length > LABEL_VILLAGES) return;
  // Row i of the system belongs to village Pi: mark the rows swept so far.
  state.v.forEach((p, i) => {
    if (i >= progress.swept) return;
    const current = i === progress.row && state.step <= solve.n;
    painter.ring(p, theme.sizes.handle * (current ? 2.4 : 1.7), {
      color: current ? theme.accent : painter.color(0),
      width: current ? theme.sizes.line * 1.5 : theme.sizes.thin,
    });
  });
}

/** Each gradient fixed so far, as an arrow D/3: over the villages' labels, so the new one is seen. */
function drawFixedGradients(painter: Painter, state: RoadState): void {
  const theme = painter.theme;
  const solve = buildSolve(state)!;
  const progress = solveProgress(solve.n, state.step);
  if (state.v.length > LABEL_VILLAGES) return;
  state.v.forEach((p, i) => {
    if (!isFixed(solve.n, progress, i)) return;
    const d = [solve.trace[0].solution[i], solve.trace[1].solution[i]];
    painter.arrow(p, plus(p, d, 1 / 3), {
      color: i === progress.row ? theme.accent : painter.color(0),
      width: theme.sizes.line * (i === progress.row ? 1.4 : 1),
    });
  });
}

function drawComb(painter: Painter, state: RoadState, pieces: readonly Point[][]): void {
  const [w, h] = boundsSpan(state.v);
  drawCurvatureComb(painter, pieces, Math.max(w, h, 1e-9) / 10, painter.color(3));
}

function drawMarkerLabel(painter: Painter, state: RoadState, pieces: readonly Point[][]): void {
  const { piece, p } = localParameter(state.s, pieces.length);
  const at = bezierPoint(pieces[piece], p);
  painter.label(`p̄ = ${state.s.toFixed(2)}: segment ${piece}, p = ${p.toFixed(2)}`, at, {
    dx: painter.theme.sizes.handle + 6,
    dy: painter.theme.sizes.handle + painter.theme.sizes.small,
    size: painter.theme.sizes.small,
    box: true,
  });
}
