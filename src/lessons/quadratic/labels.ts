import { drawLegend } from '../../kit/legend';
import { labelWidth } from '../../render/labelWidth';
import type { Painter } from '../../render/painter';
import type { Member } from './model';

/**
 * Each member's μ1 in a box, at the first of its label spots (ranked in the
 * model: where its curve strays furthest from the polygon P0 P1 P2) that is
 * on screen and does not cover a label already placed; if every spot on
 * screen does, at the best of them. Only the screen is looked at here. Where
 * the boxes together are wider than the figure (a phone), they cannot stand
 * apart beside their curves: they covered the very curves they named, and
 * the members are named in a key in a clear corner instead.
 */
export function placeMemberLabels(
  painter: Painter,
  members: readonly Member[],
  colour: (member: Member) => string,
): void {
  const theme = painter.theme;
  const view = painter.view;
  const size = theme.sizes.label * 0.9;
  const height = size * 1.6;
  const style = { size, bold: true, box: true } as const;
  const widths = members.map((m) => labelWidth(painter, m.text, style));
  const total = widths.reduce((sum, w) => sum + w, 0);
  if (total > view.width * 0.9) {
    drawLegend(
      painter,
      members.map((member) => ({
        text: member.text,
        color: colour(member),
        line: { color: colour(member), width: theme.sizes.line * 1.3 },
      })),
    );
    return;
  }
  const placed: { x: number; y: number; w: number }[] = [];
  members.forEach((member, k) => {
    const spots = member.labelSpots;
    // Its box: the text as measured and the box's padding either side.
    const width = widths[k] + size * 0.7;
    let first = -1;
    let free = -1;
    for (let i = 0; i < spots.length; i++) {
      const [x, y] = view.toScreen(spots[i]);
      const inside =
        x > width / 2 + 4 &&
        x < view.width - width / 2 - 4 &&
        y > height &&
        y < view.height - height;
      if (!inside) continue;
      if (first < 0) first = i;
      const overlaps = placed.some(
        (box) => Math.abs(box.x - x) < (box.w + width) / 2 && Math.abs(box.y - y) < height,
      );
      if (!overlaps) {
        free = i;
        break;
      }
    }
    const chosen = free >= 0 ? free : first;
    if (chosen < 0) return;
    const [x, y] = view.toScreen(spots[chosen]);
    placed.push({ x, y, w: width });
    painter.dot(spots[chosen], colour(member), theme.sizes.point * 0.6);
    painter.label(member.text, spots[chosen], {
      align: 'center',
      box: true,
      color: colour(member),
      size,
      bold: true,
    });
  });
}
