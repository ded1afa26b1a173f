// `npm run bench`: Spline Lab's maths against its dev-only peers, side by side
// in one process. Prints figures only; nothing here is asserted.
import { Bezier } from 'bezier-js';
import { curveBasis, curveNatural } from 'd3-shape';
import {
  bezierPoint,
  cubicSplineC2,
  naturalCubicBezierBatch,
  naturalCubicDerivatives,
  naturalCubicDerivativesBatch,
  sampleUniformBSpline,
  sampleBezier,
  uniformBSplineBezierBatch,
  type Point,
} from '../src/math/index';
import { clock, measure, type Timing } from './measure';

interface Row {
  readonly task: string;
  readonly ours: Timing;
  readonly peerName: string;
  readonly peer: Timing | undefined;
}

/** A drawing context that records nothing: both sides pay only for computing. */
function silentContext(): CanvasRenderingContext2D {
  let count = 0;
  const bump = () => void count++;
  return {
    moveTo: bump,
    lineTo: bump,
    bezierCurveTo: bump,
    closePath: bump,
  } as unknown as CanvasRenderingContext2D;
}

/**
 * A drawing context that stores every bezierCurveTo into preallocated
 * Float64Arrays, so the peer materialises the same output ours returns.
 */
function recordingContext(segments: number): CanvasRenderingContext2D {
  const stored = new Float64Array(6 * (segments + 8));
  let offset = 0;
  return {
    moveTo: () => undefined,
    lineTo: () => undefined,
    closePath: () => undefined,
    bezierCurveTo: (x1: number, y1: number, x2: number, y2: number, x: number, y: number) => {
      stored[offset] = x1;
      stored[offset + 1] = y1;
      stored[offset + 2] = x2;
      stored[offset + 3] = y2;
      stored[offset + 4] = x;
      stored[offset + 5] = y;
      offset += 6;
    },
  } as unknown as CanvasRenderingContext2D;
}

/** n points along a wiggly path, as parallel typed arrays and as [x, y] pairs. */
function wiggle(n: number): { xs: Float64Array; ys: Float64Array } {
  const xs = new Float64Array(n);
  const ys = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    xs[i] = i + 0.3 * Math.sin(i * 0.7);
    ys[i] = 100 * Math.sin(i * 0.01) + 5 * Math.cos(i * 1.3);
  }
  return { xs, ys };
}

function naturalSpline(n: number): Row {
  const { xs, ys } = wiggle(n);
  // Output buffers are reused, as a lesson redrawing every frame would.
  const out = naturalCubicBezierBatch([xs, ys]);
  const ours = measure(
    () => undefined,
    () => naturalCubicBezierBatch([xs, ys], out),
  );
  return {
    task: `natural cubic spline, ${label(n)} points → control points`,
    ours,
    peerName: 'd3-shape curveNatural',
    peer: d3Natural(xs, ys, silentContext),
  };
}

/**
 * d3's natural spline through the points: d3 collects points in point() and
 * solves in lineEnd(); it is fed untimed and lineEnd alone is timed (solve both
 * coordinates + emit every bezierCurveTo to `context`).
 */
function d3Natural(
  xs: Float64Array,
  ys: Float64Array,
  context: () => CanvasRenderingContext2D,
): Timing {
  return measure(
    () => {
      const curve = curveNatural(context());
      curve.lineStart();
      for (let i = 0; i < xs.length; i++) curve.point(xs[i], ys[i]);
      return curve;
    },
    (curve) => curve.lineEnd(),
  );
}

/**
 * The contract's own spline functions on plain arrays (what a lesson or another
 * tool calls), each returning fresh arrays, against the same d3 solve.
 */
function naturalSplineContract(n: number): Row[] {
  const { xs, ys } = wiggle(n);
  const points: Point[] = Array.from(xs, (x, i) => [x, ys[i]]);
  const xValues = Array.from(xs);
  const yValues = Array.from(ys);
  const segments = measure(
    () => undefined,
    () => cubicSplineC2(points),
  );
  const derivatives = measure(
    () => undefined,
    () => [naturalCubicDerivatives(xValues), naturalCubicDerivatives(yValues)],
  );
  const silent = d3Natural(xs, ys, silentContext);
  const recorded = d3Natural(xs, ys, () => recordingContext(n));
  const task = `cubicSplineC2, ${label(n)} 2D points → Point[][]`;
  return [
    { task, ours: segments, peerName: 'd3-shape curveNatural', peer: silent },
    { task, ours: segments, peerName: 'd3-shape curveNatural, recording context', peer: recorded },
    {
      task: `naturalCubicDerivatives of x and of y, ${label(n)} values each`,
      ours: derivatives,
      peerName: 'd3-shape curveNatural',
      peer: silent,
    },
  ];
}

function bezierEvaluations(n: number): Row[] {
  const points: Point[] = [
    [0, 0],
    [30, 90],
    [70, -40],
    [100, 10],
  ];
  const peer = bezierJsCompute(points, n);
  const buffer = new Float64Array(2 * n);
  const batch = measure(
    () => undefined,
    () => sampleBezier(points, n - 1, buffer),
  );
  return [
    {
      task: `cubic Bézier, ${label(n)} evaluations (bezierPoint per call)`,
      ours: bezierPointCalls(points, n),
      peerName: 'bezier-js compute',
      peer,
    },
    {
      task: `cubic Bézier, ${label(n)} evaluations (sampleBezier batch)`,
      ours: batch,
      peerName: 'bezier-js compute',
      peer,
    },
  ];
}

/** The same through the contract on a 3D cubic (bezier-js takes {x, y, z}). */
function bezierEvaluations3D(n: number): Row {
  const points: Point[] = [
    [0, 0, 0],
    [30, 90, 20],
    [70, -40, 60],
    [100, 10, -30],
  ];
  return {
    task: `3D cubic Bézier, ${label(n)} evaluations (bezierPoint per call)`,
    ours: bezierPointCalls(points, n),
    peerName: 'bezier-js compute',
    peer: bezierJsCompute(points, n),
  };
}

/** n calls of bezierPoint at t = 0 … 1, each result read. */
function bezierPointCalls(points: readonly Point[], n: number): Timing {
  return measure(
    () => undefined,
    () => {
      let sum = 0;
      for (let i = 0; i < n; i++) sum += bezierPoint(points, i / (n - 1))[0];
      return sum;
    },
  );
}

/** n calls of bezier-js compute at t = 0 … 1, each result read. */
function bezierJsCompute(points: readonly Point[], n: number): Timing {
  const curve = new Bezier(points.map(([x, y, z]) => (z === undefined ? { x, y } : { x, y, z })));
  return measure(
    () => undefined,
    () => {
      let sum = 0;
      for (let i = 0; i < n; i++) sum += curve.compute(i / (n - 1)).x;
      return sum;
    },
  );
}

function uniformBSpline(n: number): Row[] {
  const { xs, ys } = wiggle(n);
  const out = uniformBSplineBezierBatch([xs, ys]);
  const ours = measure(
    () => undefined,
    () => uniformBSplineBezierBatch([xs, ys], out),
  );
  // curveBasis emits one bezierCurveTo per point as the points arrive.
  const feed = (curve: ReturnType<typeof curveBasis>) => {
    curve.lineStart();
    for (let i = 0; i < n; i++) curve.point(xs[i], ys[i]);
    curve.lineEnd();
    return curve;
  };
  const silent = measure(() => curveBasis(silentContext()), feed);
  const recorded = measure(() => curveBasis(recordingContext(n)), feed);
  const task = `uniform cubic B-spline, ${label(n)} points → Bézier segments`;
  const samples = sampleUniformBSpline([xs, ys], 8);
  const sampled = measure(
    () => undefined,
    () => sampleUniformBSpline([xs, ys], 8, samples),
  );
  return [
    {
      task: `uniform cubic B-spline, ${label(n)} points sampled 8 per segment`,
      ours: sampled,
      peerName: '(no peer: sampleUniformBSpline)',
      peer: undefined,
    },
    { task, ours, peerName: 'd3-shape curveBasis, no-op context', peer: silent },
    { task, ours, peerName: 'd3-shape curveBasis, recording context', peer: recorded },
  ];
}

/** Reads every value of `from` and writes it to `to`: the least a solve must do. */
function readAndWrite(from: Float64Array, to: Float64Array): Float64Array {
  for (let i = 0; i < from.length; i++) to[i] = from[i];
  return to;
}

/** The natural solve of one coordinate against reading and writing its arrays once. */
function bandwidth(n: number): { solve: Timing; copy: Timing; memcpy: Timing } {
  const { ys } = wiggle(n);
  const out = new Float64Array(n);
  const copy = measure(
    () => undefined,
    () => readAndWrite(ys, out),
  );
  const solve = measure(
    () => undefined,
    () => naturalCubicDerivativesBatch(ys, out),
  );
  const memcpy = measure(
    () => undefined,
    () => out.set(ys),
  );
  return { solve, copy, memcpy };
}

/**
 * What cubicSplineC2's result costs by itself: m segments of four fresh
 * [x, y] arrays, written from numbers that are already solved. No maths and no
 * checks; the contract's Point[][] cannot be returned faster than this.
 */
function segmentArrays(n: number): Timing {
  const { xs, ys } = wiggle(n);
  const { firstControl, secondControl } = naturalCubicBezierBatch([xs, ys]);
  const [bx, by, cx, cy] = [...firstControl, ...secondControl];
  const m = n - 1;
  return measure(
    () => undefined,
    () => {
      const segments = new Array<Point[]>(m);
      for (let i = 0; i < m; i++) {
        segments[i] = [
          [xs[i], ys[i]],
          [bx[i], by[i]],
          [cx[i], cy[i]],
          [xs[i + 1], ys[i + 1]],
        ];
      }
      return segments;
    },
  );
}

function label(n: number): string {
  return n >= 1e6
    ? `10^${Math.round(Math.log10(n))}`
    : n >= 1e5
      ? `10^${Math.round(Math.log10(n))}`
      : String(n);
}

function format(ms: number): string {
  return ms >= 100 ? ms.toFixed(0) : ms >= 10 ? ms.toFixed(1) : ms.toFixed(2);
}

function printTable(rows: readonly Row[]): void {
  const header = ['task', 'ours (ms)', 'peer', 'peer (ms)', 'ratio peer/ours'];
  const lines = rows.map((row) => [
    row.task,
    format(row.ours.median),
    row.peerName,
    row.peer ? format(row.peer.median) : '—',
    row.peer ? `${(row.peer.median / row.ours.median).toFixed(1)}×` : '—',
  ]);
  const widths = header.map((title, c) =>
    Math.max(title.length, ...lines.map((line) => line[c].length)),
  );
  const print = (cells: string[]) =>
    console.log(`| ${cells.map((cell, c) => cell.padEnd(widths[c])).join(' | ')} |`);
  print(header);
  console.log(`|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`);
  lines.forEach(print);
}

const rows: Row[] = [
  naturalSpline(1e5),
  naturalSpline(1e6),
  ...naturalSplineContract(1e5),
  ...bezierEvaluations(1e6),
  bezierEvaluations3D(1e6),
  ...uniformBSpline(1e5),
];
console.log(
  `Spline Lab maths benchmark — node ${process.version}, ${clock}, median of 9 runs after 3 warm-ups${(globalThis as { gc?: unknown }).gc ? ', GC between runs' : ''}\n`,
);
printTable(rows);
const { solve, copy, memcpy } = bandwidth(1e6);
const allocation = segmentArrays(1e5);
console.log(
  [
    '',
    `natural spline solve, 10^6 values → gradients: ${format(solve.median)} ms`,
    `reading and writing the same arrays once (JS loop): ${format(copy.median)} ms → solve/baseline ${(solve.median / copy.median).toFixed(1)}× (target ≤ 3×)`,
    `(TypedArray.set memcpy, the hardware floor: ${format(memcpy.median)} ms → ${(solve.median / memcpy.median).toFixed(1)}×)`,
    '',
    `cubicSplineC2's result alone, 10^5 2D points: 10^5 segments of 4 fresh [x, y] arrays from solved numbers: ${format(allocation.median)} ms`,
  ].join('\n'),
);
