import { h } from '../../app/dom';
import {
  bezierCurvature,
  bezierPoint,
  cubicInflections,
  cubicSelfIntersection,
  sampleBezier,
} from '../../math';
import { formula, texPoint } from '../../render/formula';
import type { Painter } from '../../render/painter';
import { type Experiment, drawMarked, drawPolygon, texT } from './experiment';

const SAMPLES = 240;

/** Signed curvature at the samples; NaN where the speed is zero (a cusp). */
function curvatureSigns(p: readonly (readonly number[])[]): number[] {
  return Array.from({ length: SAMPLES + 1 }, (_, k) => {
    try {
      return Math.sign(bezierCurvature(p, k / SAMPLES));
    } catch {
      return Number.NaN;
    }
  });
}

/** The curve coloured by the sign of its curvature: one colour turning left, another turning right. */
function drawBySign(painter: Painter, p: readonly (readonly number[])[]): void {
  const flat = sampleBezier(p, SAMPLES);
  const signs = curvatureSigns(p);
  const colorOf = (sign: number) =>
    sign > 0 ? painter.color(0) : sign < 0 ? painter.color(1) : painter.theme.curve;
  let start = 0;
  for (let k = 1; k <= SAMPLES; k++) {
    if (k === SAMPLES || signs[k] !== signs[start]) {
      const piece = flat.slice(2 * start, 2 * k + 2);
      painter.polylineFlat(piece, { color: colorOf(signs[start]) });
      start = k;
    }
  }
}

export const cubic: Experiment = {
  id: 'cubic',
  title: 'Inflection and self-intersection',
  sentence:
    'A cubic can turn both ways (an inflection, where the curvature changes sign) or cross itself (a loop); where the control points are decides which, and at most two inflections or one loop fit in a cubic.',
  draw(painter, state, info) {
    const p = state.p;
    drawPolygon(painter, p);
    drawBySign(painter, p);
    cubicInflections(p).forEach((t, j) =>
      drawMarked(
        painter,
        bezierPoint(p, t),
        `inflection${j === 0 ? '' : ' 2'}, t = ${t.toFixed(2)}`,
        info,
        painter.theme.accent,
      ),
    );
    const loop = cubicSelfIntersection(p);
    if (loop) {
      const point = bezierPoint(p, loop[0]);
      painter.ring(point, painter.theme.sizes.point * 2.2, {
        color: painter.theme.accent,
        width: painter.theme.sizes.line * 1.5,
      });
      if (!info.thumbnail) {
        painter.label(`crossing, t = ${loop[0].toFixed(2)} and ${loop[1].toFixed(2)}`, point, {
          dx: painter.theme.sizes.point * 3,
          dy: -painter.theme.sizes.label * 0.9,
          color: painter.theme.accent,
          halo: true,
          bold: true,
        });
      }
    }
    drawMarked(painter, bezierPoint(p, state.t), 'P(t)', info, painter.theme.ink);
  },
  explain(state, api) {
    const p = state.p;
    const palette = api.theme().palette;
    const inflections = cubicInflections(p);
    const loop = cubicSelfIntersection(p);
    const signs = curvatureSigns(p);
    const nodes: Node[] = [
      h(
        'p',
        {},
        h('span', { class: 'swatch', style: `background:${palette[0]}` }),
        'turning left (curvature > 0)   ',
        h('span', { class: 'swatch', style: `background:${palette[1]}` }),
        'turning right (curvature < 0)',
      ),
      formula("\\kappa(t) = \\frac{x'y'' - y'x''}{(x'^2 + y'^2)^{3/2}}", true),
    ];
    let curvatureText: string;
    try {
      curvatureText = `κ(${texT(state.t)}) = ${bezierCurvature(p, state.t).toFixed(4)}`;
    } catch {
      curvatureText = `At t = ${texT(state.t)} the speed is zero (a cusp): the curvature is not defined there.`;
    }
    nodes.push(h('p', {}, curvatureText));
    if (signs.every((s) => s === 0)) {
      nodes.push(
        h(
          'p',
          {},
          'All four control points lie on one line: the curve is straight, its curvature is zero everywhere, so it has neither inflection nor loop.',
        ),
      );
      return nodes;
    }
    nodes.push(
      h(
        'p',
        {},
        inflections.length === 0
          ? 'No inflection on [0, 1]: the curve turns one way only.'
          : `Inflection${inflections.length > 1 ? 's' : ''} at t = ${inflections.map((t) => t.toFixed(4)).join(' and ')}, where P′ × P″ = 0 and the curvature changes sign.`,
      ),
    );
    if (loop) {
      nodes.push(
        formula(
          `P(${loop[0].toFixed(4)}) = P(${loop[1].toFixed(4)}) = ${texPoint(bezierPoint(p, loop[0]), 3)}`,
          true,
        ),
        h(
          'p',
          {},
          'The curve crosses itself: a loop. Along a loop the curve turns one way, so a loop and an inflection exclude each other on a cubic.',
        ),
      );
    } else {
      nodes.push(h('p', {}, 'No self-intersection on [0, 1].'));
    }
    if (signs.some((s) => Number.isNaN(s))) {
      nodes.push(
        h('p', {}, 'Somewhere the speed is zero: a cusp, between a loop and an inflection.'),
      );
    }
    return nodes;
  },
};
