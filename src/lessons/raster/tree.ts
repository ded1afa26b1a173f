import type { Painter } from '../../render/painter';
import type { Bounds } from '../../render/projection';
import type { RasterModel } from './model';

// The recursion tree of adaptive flattening beside the curve: a piece of
// parameter range [t0, t1] at depth d sits at x = 32·(t0 + t1)/2, y = −LEVEL·d;
// under it, the t axis with the segments' ends found so far.

const WIDTH = 32;
const LEVEL = 4;

const depthOf = (m: RasterModel) => Math.max(...m.tree.map((node) => node.depth));
const axisY = (m: RasterModel) => -LEVEL * (depthOf(m) + 1);

export const treeBounds = (m: RasterModel): Bounds => ({
  minX: -1,
  maxX: WIDTH + 1,
  minY: axisY(m) - 1.5,
  maxY: 1.5,
});

export function drawTree(painter: Painter, m: RasterModel, labels: boolean): void {
  const theme = painter.theme;
  const at = (index: number) => {
    const node = m.tree[index];
    return [(WIDTH * (node.t0 + node.t1)) / 2, -LEVEL * node.depth];
  };
  const y = axisY(m);
  painter.segment([0, y], [WIDTH, y], { color: theme.axis, width: theme.sizes.thin * 1.5 });
  if (labels) {
    for (const [t, text] of [
      [0, 't = 0'],
      [1, 't = 1'],
    ] as const)
      painter.label(text, [WIDTH * t, y], {
        dy: theme.sizes.label * 1.3,
        align: 'center',
        halo: true,
      });
  }
  const visited = m.tree.slice(0, m.piecesShown);
  for (const node of visited) {
    if (node.parent >= 0)
      painter.segment(at(node.parent), at(node.index), {
        color: theme.polygon,
        width: theme.sizes.thin * 1.5,
      });
  }
  for (const node of visited) {
    if (node.split) continue;
    // A kept piece becomes one segment: its ends on the t axis.
    const color = painter.color(0);
    painter.segment([WIDTH * node.t0, y], [WIDTH * node.t1, y], {
      color,
      width: theme.sizes.line * 1.5,
    });
    for (const t of [node.t0, node.t1]) painter.dot([WIDTH * t, y], color, theme.sizes.point * 0.7);
    painter.segment(at(node.index), [WIDTH * ((node.t0 + node.t1) / 2), y], {
      color,
      width: 1,
      dash: [3, 4],
      alpha: 0.5,
    });
  }
  for (const node of visited) {
    const color = node.split ? theme.ink : node.cut ? theme.accent : painter.color(0);
    painter.dot(at(node.index), color, theme.sizes.point * (node.split ? 0.9 : 1.1));
  }
  if (m.shown.is('question')) {
    painter.ring(at(0), theme.sizes.point * 1.6, { color: theme.accent, width: theme.sizes.line });
    return;
  }
  if (m.shown.is('pieces')) {
    const current = m.tree[m.piecesShown - 1];
    painter.ring(at(current.index), theme.sizes.point * 2, {
      color: theme.accent,
      width: theme.sizes.line,
    });
    if (labels) {
      const sign = current.split || current.cut ? '>' : '≤';
      painter.label(
        `${(current.flatness * m.state.zoom).toFixed(2)} ${sign} τ`,
        at(current.index),
        {
          dx: theme.sizes.point * 2.6,
          dy: -theme.sizes.point * 1.5,
          color: theme.accent,
          halo: true,
          bold: true,
        },
      );
    }
  }
}
