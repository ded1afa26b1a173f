import { script, step } from '../../kit/script';
import type { UniformModel } from './model';
import { blend, n3, pt, segmentLabel, segmentName } from './notation';
import type { BSplineState } from './state';
import { pieceAt, pieceTex, uniformPieces } from './uniformPieces';

/** What the steps of the uniform cubic (open or closed) reveal, by name. */
export type UniformReveal = 'points' | 'polygon' | 'segment' | 'segments' | 'joints';

const closed = (state: BSplineState) => state.part === 'closed';

/** B0(t) … B3(t) of the continuation notes written out, with their values at the local t: two rows of an aligned block. */
export function basesTex(t: number): string {
  const [b0, b1, b2, b3] = uniformPieces(3).map(
    (piece, k) => `B_${k}(t) &= ${pieceTex(piece)} = ${n3(pieceAt(piece, t))}`,
  );
  return `${b0} & ${b1} \\\\ ${b2} & ${b3}`;
}

/**
 * The uniform cubic, open or closed: the points, the polygon, the
 * segment under the cursor alone, all segments, their joints.
 */
export const uniformScript = script<BSplineState, UniformModel, UniformReveal>(
  step(
    'points',
    ({ state }) =>
      `The m + 1 = ${state.points.length} control points P0 … P${state.points.length - 1}`,
  ),
  step('polygon', ({ state }) => {
    const n = state.points.length;
    return closed(state)
      ? `Closed: after P${n - 1} come P0, P1, P2 again (P${n} = P0, P${n + 1} = P1, P${n + 2} = P2)`
      : 'The control polygon: the curve will follow it, but pass through none of its points';
  }),
  step(
    'segment',
    ({ model: m }) =>
      `Segment ${segmentName(m.segment)} blends ${m.segments[m.segment].points.map((j) => `P${j}`).join(', ')} with the four bases B0(t) … B3(t)`,
    ({ model: m }) =>
      `\\begin{aligned}${basesTex(m.local)} \\\\ ${segmentLabel(m.segment)}(${n3(m.local)}) &= ${blend(m.basis, (j) => `P_{${m.owner[j]}}`)} = ${pt(m.point)}\\end{aligned}`,
  ),
  step(
    'segments',
    ({ state, model: m }) =>
      closed(state)
        ? `All m + 1 = ${m.segments.length} segments, one colour each, with the same matrix everywhere: a closed C² curve`
        : `All m − 2 = ${m.segments.length} segments, one colour each: they join with C² continuity`,
    ({ state }) => {
      const points = state.points.length;
      return closed(state)
        ? `m + 1 = ${points}\\text{ points} \\;\\to\\; m + 1 = ${points}\\text{ segments}`
        : `m + 1 = ${points}\\text{ points} \\;\\to\\; m - 2 = ${points - 3}\\text{ segments}`;
    },
  ),
  step(
    'joints',
    'Each joint is (P(i−1) + 4Pi + P(i+1))/6; P(s) runs along the whole curve as t moves',
    ({ model: m }) => {
      const i = m.segment;
      const [a, b, c] = [0, 1, 2].map((k) => `P_{${m.owner[i + k]}}`);
      return `${segmentLabel(i)}(0) = \\tfrac16(${a} + 4${b} + ${c}) = ${pt(m.beziers[i][0])}`;
    },
  ),
);
