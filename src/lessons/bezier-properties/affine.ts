import { h } from '../../app/dom';
import {
  bezierPoint,
  clampedUniformKnots,
  nurbsPoint,
  projectiveMap,
  sampleBezier,
  sampledDeviation,
} from '../../math';
import { formula, texNumber } from '../../render/formula';
import { type Experiment, drawBezier, drawPolygon, samplesFor } from './experiment';
import type { MapKind, PropertiesState } from './state';

type Matrix = number[][];

const multiply = (a: Matrix, b: Matrix): Matrix =>
  a.map((row) => b[0].map((_, j) => row.reduce((sum, v, k) => sum + v * b[k][j], 0)));

const translate = (x: number, y: number): Matrix => [
  [1, 0, x],
  [0, 1, y],
  [0, 0, 1],
];

/** The centre the maps act about, and how far right the image is drawn (lecture cubic's frame). */
const CENTRE: [number, number] = [2, 1];
const SHIFT = 6;

const LINEAR: Record<MapKind, Matrix> = {
  rotate: [
    [Math.cos(0.6), -Math.sin(0.6), 0],
    [Math.sin(0.6), Math.cos(0.6), 0],
    [0, 0, 1],
  ],
  scale: [
    [1.4, 0, 0],
    [0, 0.6, 0],
    [0, 0, 1],
  ],
  shear: [
    [1, 0.8, 0],
    [0, 1, 0],
    [0, 0, 1],
  ],
  // A perspective map: the last row makes w depend on the point.
  perspective: [
    [1, 0, 0],
    [0, 1, 0],
    [0.22, 0.12, 1],
  ],
};

/** The 3×3 matrix of the map: about the centre, then shifted right so both figures show. */
export function mapMatrix(kind: MapKind): Matrix {
  return multiply(
    translate(SHIFT + CENTRE[0], CENTRE[1]),
    multiply(LINEAR[kind], translate(-CENTRE[0], -CENTRE[1])),
  );
}

const homogeneousWeight = (m: Matrix, point: readonly number[]) =>
  m[2][0] * point[0] + m[2][1] * point[1] + m[2][2];

/** Both images, or why there are none: the map of the curve, and the curve of the mapped points. */
export function images(state: PropertiesState) {
  const matrix = mapMatrix(state.m);
  const n = state.p.length - 1;
  const count = samplesFor(n);
  const samples = sampleBezier(state.p, count);
  const curvePoints: number[][] = [];
  for (let k = 0; k < samples.length; k += 2) curvePoints.push([samples[k], samples[k + 1]]);
  try {
    const mappedControls = projectiveMap(matrix, state.p);
    const mappedCurve = projectiveMap(matrix, curvePoints).flatMap((point) => [...point]);
    const curveOfMapped = sampleBezier(mappedControls, count);
    const { at, distance } = sampledDeviation(mappedCurve, curveOfMapped);
    return {
      ok: true as const,
      matrix,
      mappedControls,
      mappedCurve,
      curveOfMapped,
      at: at / count,
      distance,
    };
  } catch (error) {
    return {
      ok: false as const,
      matrix,
      why: error instanceof Error ? error.message : String(error),
    };
  }
}

export const affine: Experiment = {
  id: 'affine',
  title: 'Affine invariance',
  sentence:
    'Mapping the control points and then drawing the curve gives the same as mapping the curve itself, for every affine map; for a perspective map it does not, which is what rational curves (NURBS) repair.',
  extent(state) {
    const result = images(state);
    return result.ok ? result.mappedControls : [];
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    drawPolygon(painter, state.p);
    drawBezier(painter, state.p, { color: theme.curve });
    const result = images(state);
    if (!result.ok) return;
    painter.polyline(result.mappedControls, {
      color: painter.color(0),
      width: theme.sizes.line,
      dash: [6, 5],
    });
    for (const point of result.mappedControls)
      painter.dot(point, painter.color(0), theme.sizes.point);
    painter.polylineFlat(result.curveOfMapped, {
      color: painter.color(0),
      width: theme.sizes.curve * 1.6,
    });
    painter.polylineFlat(result.mappedCurve, {
      color: painter.color(1),
      width: theme.sizes.curve * 0.8,
      dash: [10, 6],
    });
    const t = state.t;
    const onMapped = bezierPoint(result.mappedControls, t);
    const [imageOfPoint] = projectiveMap(result.matrix, [bezierPoint(state.p, t)]);
    painter.dot(bezierPoint(state.p, t), theme.accent, theme.sizes.point * 1.3);
    painter.dot(onMapped, painter.color(0), theme.sizes.point * 1.4);
    painter.ring(imageOfPoint, theme.sizes.point * 1.8, {
      color: painter.color(1),
      width: theme.sizes.line * 1.3,
    });
    if (!info.thumbnail) {
      // Name each image at its middle: the map of the curve above, the curve of the mapped points below.
      const middle = 2 * Math.floor(result.mappedCurve.length / 4);
      painter.label(
        'map of the curve',
        [result.mappedCurve[middle], result.mappedCurve[middle + 1]],
        {
          dy: -theme.sizes.label * 1.3,
          align: 'center',
          color: painter.color(1),
          halo: true,
          bold: true,
        },
      );
      painter.label(
        'curve of the mapped points',
        [result.curveOfMapped[middle], result.curveOfMapped[middle + 1]],
        {
          dy: theme.sizes.label * 1.3,
          align: 'center',
          color: painter.color(0),
          halo: true,
          bold: true,
        },
      );
    }
  },
  explain(state) {
    const result = images(state);
    const m = result.matrix;
    const linear = LINEAR[state.m];
    const nodes: Node[] = [
      h(
        'p',
        {},
        `The map, in coordinates centred at (${CENTRE.join(', ')}) (its image is drawn ${SHIFT} units to the right):`,
      ),
      formula(
        `\\begin{pmatrix}x'w\\\\ y'w\\\\ w\\end{pmatrix} = \\begin{pmatrix}${linear.map((row) => row.map((v) => texNumber(v, 3)).join(' & ')).join('\\\\')}\\end{pmatrix}\\begin{pmatrix}x\\\\ y\\\\ 1\\end{pmatrix}`,
        true,
      ),
    ];
    if (!result.ok) {
      nodes.push(
        h(
          'p',
          {},
          'A control point is on or beyond the vanishing line of this perspective map (w ≤ 0): its image is at infinity or on the far side, so no image is drawn. Move the points back to the right.',
        ),
        h('p', { class: 'note' }, result.why),
      );
      return nodes;
    }
    const ws = state.p.map((point) => homogeneousWeight(m, point));
    const affineMap = ws.every((w) => w === 1);
    nodes.push(
      h(
        'p',
        { 'data-map-deviation': String(result.distance) },
        `Largest distance between the two images at equal t: ${result.distance < 1e-9 ? result.distance.toExponential(1) : result.distance.toFixed(4)}${result.distance < 1e-9 ? ' — they agree, up to rounding.' : `, at t = ${result.at.toFixed(3)}: they differ.`}`,
      ),
    );
    if (affineMap) {
      nodes.push(
        h(
          'p',
          { class: 'note' },
          'The last row is (0, 0, 1), so w = 1 everywhere: the map is affine, the weights W(N, i, t) sum to 1 and survive it. The solid and dashed images coincide, and so do the two points at t.',
        ),
      );
    } else {
      const n = state.p.length - 1;
      const knots = clampedUniformKnots(n + 1, n);
      const rational = sampleRational(result.mappedControls, ws, knots, n, samplesFor(n));
      const repaired = sampledDeviation(result.mappedCurve, rational).distance;
      nodes.push(
        h(
          'p',
          { class: 'note' },
          `Here w runs from ${Math.min(...ws).toFixed(2)} to ${Math.max(...ws).toFixed(2)} over the control points: the map divides by w, and dividing does not commute with averaging. The ring (map of P(t)) and the dot (curve of the mapped points at t) separate.`,
        ),
        formula(
          `\\text{rational: } \\frac{\\sum_i w_i W(N,i,t)\\,P_i'}{\\sum_i w_i W(N,i,t)}\\ \\text{ with } w_i = ${ws.map((w) => texNumber(w, 2)).join(',\\,')}`,
          true,
        ),
        h(
          'p',
          { 'data-rational-deviation': String(repaired) },
          `Giving each mapped control point its w as a weight (a rational Bézier curve, the simplest NURBS) reproduces the map of the curve: largest distance ${repaired.toExponential(1)}.`,
        ),
      );
    }
    return nodes;
  },
};

function sampleRational(
  points: readonly (readonly number[])[],
  weights: readonly number[],
  knots: readonly number[],
  degree: number,
  count: number,
): number[] {
  const flat: number[] = [];
  for (let k = 0; k <= count; k++)
    flat.push(...nurbsPoint(points, weights, knots, degree, k / count));
  return flat;
}
