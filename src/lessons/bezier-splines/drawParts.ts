import type { DrawInfo } from '../../app/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import type { BezierSplinesModel } from './model';

// What the main figure shows of each part at each step (the step is the state's).

type Draw = (painter: Painter, m: BezierSplinesModel, info: DrawInfo) => void;

const dashed = (painter: Painter) => ({
  color: painter.theme.polygon,
  width: painter.theme.sizes.line,
  dash: [6, 5],
});

const labelAt = (painter: Painter, text: string, p: Point, color?: string) =>
  painter.label(text, p, {
    dx: 10,
    dy: -10,
    color: color ?? painter.theme.ink,
    halo: true,
    size: painter.theme.sizes.label * 0.9,
  });

/** The control polygon of every piece, dashed, and its inner control points as dots. */
function polygons(painter: Painter, pieces: readonly Point[][], dots = true) {
  for (const piece of pieces) {
    painter.polyline(piece, dashed(painter));
    if (dots) for (const q of piece.slice(1, -1)) painter.dot(q, painter.theme.accent);
  }
}

const why: Draw = (painter, m) => {
  const { step } = m.state;
  const theme = painter.theme;
  if (step === 0) return;
  painter.polyline(m.state.p, dashed(painter));
  const single = step <= 2;
  painter.polylineFlat(m.single, single ? { role: 'curve' } : { color: theme.curveFaint });
  if (step === 2) {
    painter.polylineFlat(m.singleMoved, { color: theme.accent, dash: [10, 6] });
    painter.arrow(m.state.p[m.moved], m.movedPoints[m.moved], { color: theme.accent });
  }
  if (step >= 3) painter.cubicSegments(m.spline, { role: 'curve' });
  if (step === 4) {
    painter.cubicSegments(m.movedSpline, {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [10, 6],
    });
    painter.arrow(m.state.p[m.moved], m.movedPoints[m.moved], { color: theme.accent });
  }
};

const quadratic: Draw = (painter, m, info) => {
  const { step, p } = m.state;
  const n = p.length - 1;
  const theme = painter.theme;
  if (step === 0) return;
  const shown = Math.min(step, n);
  if (step > n) {
    for (const ghost of m.swing)
      painter.cubicSegments(ghost, { color: theme.accent, width: theme.sizes.line, dash: [8, 6] });
  }
  painter.cubicSegments(m.quadratic.slice(0, shown), { role: 'curve' });
  for (let i = 0; i < shown; i++) {
    const b = m.quadraticControls[i];
    painter.polyline([p[i], b, p[i + 1]], dashed(painter));
    if (i > 0) {
      painter.dot(b, theme.accent, theme.sizes.point * 1.3);
      if (!info.thumbnail) labelAt(painter, `b_{${i}}`, b, theme.accent);
    }
  }
};

const system: Draw = (painter, m, info) => {
  const { step, p } = m.state;
  const theme = painter.theme;
  if (step === 0) return;
  if (step < 7) painter.polyline(p, { ...dashed(painter), color: theme.curveFaint });
  const n = p.length - 1;
  // Where the step's equations hold: the inner joints (C¹, C²) or the two ends.
  const marked = step === 3 || step === 4 ? p.slice(1, -1) : step === 5 ? [p[0], p[n]] : [];
  for (const q of marked) painter.ring(q, theme.sizes.handle * 2.2, { color: theme.accent });
  if (step < 7) return;
  if (step === 8)
    painter.cubicSegments(m.natural, { color: theme.curveFaint, width: theme.sizes.curve * 2.4 });
  const controls = m.system.controls;
  const pieces = Array.from({ length: n }, (_, i) => controls.slice(3 * i, 3 * i + 4));
  polygons(painter, pieces);
  painter.cubicSegments(pieces, { role: 'curve' });
  if (!info.thumbnail)
    controls.forEach((q, j) => {
      if (j % 3 !== 0) labelAt(painter, m.names[j], q, theme.accent);
    });
  if (step === 8)
    painter.cubicSegments(m.natural, {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [4, 8],
    });
};

const VERDICT: Record<string, string> = {
  none: '—',
  C0: 'C⁰',
  G1: 'G¹',
  C1: 'C¹',
  G2: 'G²',
  C2: 'C²',
};
export const verdict = (c: string) => VERDICT[c] ?? c;

const inspector: Draw = (painter, m, info) => {
  const { step } = m.state;
  const theme = painter.theme;
  if (step === 0) return;
  if (step === 5) {
    for (const [a, b] of m.comb)
      painter.segment(a, b, { color: theme.palette[3], width: theme.sizes.thin });
    painter.polyline(
      m.comb.map(([, tip]) => tip),
      { color: theme.palette[3], width: theme.sizes.line },
    );
  }
  polygons(painter, m.pieces, false);
  m.pieces.forEach((piece, k) =>
    painter.cubicSegments([piece], { role: 'curve', color: painter.color(k % 2 === 0 ? 0 : 2) }),
  );
  if (step < 2 || info.thumbnail) return;
  m.joints.forEach((joint, k) => {
    const at = m.pieces[k][3];
    if (step >= 3) {
      painter.arrow(at, [at[0] + joint.leftVelocity[0] / 3, at[1] + joint.leftVelocity[1] / 3], {
        color: painter.color(0),
      });
      painter.arrow(at, [at[0] + joint.rightVelocity[0] / 3, at[1] + joint.rightVelocity[1] / 3], {
        color: painter.color(2),
      });
    }
    const lines = [`joint ${k + 1}: ${verdict(joint.continuity)}`];
    if (step === 3)
      lines.push(
        joint.degenerate
          ? 'P′ = 0: no angle, no ratio'
          : `${joint.angle.toFixed(1)}°, ratio ${joint.lengthRatio.toFixed(2)}`,
      );
    if (step >= 4) lines.push(curvatureText(joint.leftCurvature, joint.rightCurvature));
    // One line, on the side of the joint away from its two neighbours, far enough to clear the handles.
    const k3 = 3 * (k + 1);
    const [dx, dy] = awayFrom(at, m.state.q[k3 - 1], m.state.q[k3 + 1]);
    const reach = theme.sizes.handle * 2 + theme.sizes.label;
    painter.label(lines.join(' · ').replace(/-/g, '−'), at, {
      dx: dx * reach,
      dy: -dy * reach,
      align: dx < -0.3 ? 'right' : dx > 0.3 ? 'left' : 'center',
      baseline: 'middle',
      box: true,
      size: theme.sizes.label * 0.9,
    });
  });
};

/** κ on both sides of a joint; a side whose velocity is zero has none. */
function curvatureText(left: number, right: number): string {
  if (Number.isNaN(left) && Number.isNaN(right)) return 'κ undefined (P′ = 0)';
  const side = (k: number) => (Number.isNaN(k) ? 'undefined' : k.toFixed(2));
  return `κ ${side(left)} | ${side(right)}`;
}

/** The unit direction pointing away from both neighbours of a joint (the normal where they are in line). */
function awayFrom(at: Point, before: Point, after: Point): Point {
  const unit = (v: Point): Point => {
    const size = Math.hypot(v[0], v[1]);
    return size > 0 ? [v[0] / size, v[1] / size] : [0, 0];
  };
  const a = unit([before[0] - at[0], before[1] - at[1]]);
  const b = unit([after[0] - at[0], after[1] - at[1]]);
  const sum: Point = [-(a[0] + b[0]), -(a[1] + b[1])];
  if (Math.hypot(sum[0], sum[1]) > 0.2) return unit(sum);
  // In line: below the curve if it runs right, else on the normal's side.
  const normal: Point = [b[1], -b[0]];
  return unit(normal[1] <= 0 ? normal : [-normal[0], -normal[1]]);
}

const catmull: Draw = (painter, m, info) => {
  const { step, p, tg } = m.state;
  const theme = painter.theme;
  if (step === 0) return;
  const tangents = (list: readonly Point[], color: string) =>
    list.forEach((t, i) => {
      if (Math.hypot(t[0], t[1]) > 0)
        painter.arrow(p[i], [p[i][0] + t[0] / 3, p[i][1] + t[1] / 3], { color });
    });
  if (step === 1) {
    painter.cubicSegments(m.hermite, { role: 'curve' });
    tangents(tg, theme.accent);
    return;
  }
  // Step 2 sets the hand-made Hermite spline beside the Catmull-Rom one: same form, other tangents.
  if (step === 2)
    painter.cubicSegments(m.hermite, { color: theme.curveFaint, width: theme.sizes.line });
  const [uniform, centripetal, chordal] = m.alphas;
  if (step === 2 || step === 3) {
    painter.cubicSegments(uniform.segments, { role: 'curve' });
    tangents(m.crTangents, theme.accent);
    if (step === 3) {
      painter.cubicSegments(m.oneSided, {
        color: painter.color(3),
        width: theme.sizes.line,
        dash: [10, 6],
      });
      tangents(
        [
          m.oneSidedTangents[0],
          ...p.slice(1, -1).map(() => [0, 0]),
          m.oneSidedTangents[p.length - 1],
        ],
        painter.color(3),
      );
    }
  } else {
    const shown = step === 4 ? [uniform, centripetal] : step === 5 ? [uniform, chordal] : m.alphas;
    for (const curve of shown) {
      const k = m.alphas.indexOf(curve);
      const main = (step === 4 && k === 1) || (step === 5 && k === 2) || step === 6;
      painter.cubicSegments(
        curve.segments,
        main
          ? { role: 'curve', color: painter.color(k) }
          : { color: theme.curveFaint, width: theme.sizes.line },
      );
    }
    if (!info.thumbnail) {
      // A legend in the corner: labels at the curves' ends would pile up on the last point.
      shown.forEach((curve, r) => {
        const k = m.alphas.indexOf(curve);
        const main = step === 6 || k > 0;
        painter.screenLabel(
          `${curve.name}, α = ${curve.alpha}`,
          16,
          28 + r * theme.sizes.label * 1.5,
          {
            color: main ? painter.color(k) : theme.muted,
            halo: true,
            bold: main,
          },
        );
      });
    }
  }
  if (step >= 2)
    for (const x of uniform.crossings)
      painter.ring(x, theme.sizes.handle * 2.4, { color: theme.palette[1] });
};

export const drawParts: Record<BezierSplinesModel['state']['part'], Draw> = {
  why,
  quadratic,
  system,
  grid: () => undefined,
  inspector,
  catmull,
};
