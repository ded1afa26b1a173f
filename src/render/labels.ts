/**
 * Placing text on a figure: lecture labels with subscripts, labels that keep
 * clear of nearby handles, values beside a plot cursor pushed apart, and
 * boxed notes. Every placed label's box is recorded on the painter, so tests
 * can check that no two overlap.
 */
import { say } from './notation';
import type { Painter } from './painter';

export interface LabelStyle {
  color?: string;
  size?: number;
  /** Offset in pixels from the anchor (screen axes, y down). */
  dx?: number;
  dy?: number;
  align?: CanvasTextAlign;
  baseline?: CanvasTextBaseline;
  bold?: boolean;
  /** Draw a light halo behind the text so it reads over lines. */
  halo?: boolean;
  /** Draw a boxed label (background box with border). */
  box?: boolean;
}

/** Where a label went, in screen pixels. */
export interface LabelBox {
  text: string;
  x: number;
  y: number;
  width: number;
  height: number;
}

/** Splits `P_{1,2}x_3` into runs of normal and subscript text. */
export function splitSubscripts(text: string): { text: string; sub: boolean }[] {
  const runs: { text: string; sub: boolean }[] = [];
  let i = 0;
  let plain = '';
  while (i < text.length) {
    if (text[i] === '_' && i + 1 < text.length) {
      if (plain) runs.push({ text: plain, sub: false });
      plain = '';
      if (text[i + 1] === '{') {
        const end = text.indexOf('}', i + 2);
        const stop = end < 0 ? text.length : end;
        runs.push({ text: text.slice(i + 2, stop), sub: true });
        i = stop + 1;
      } else {
        runs.push({ text: text[i + 1], sub: true });
        i += 2;
      }
    } else {
      plain += text[i];
      i += 1;
    }
  }
  if (plain) runs.push({ text: plain, sub: false });
  return runs;
}

/** Do a placed label and a box overlap by more than a pixel each way? */
function overlaps(b: LabelBox, x: number, y: number, width: number, height: number): boolean {
  const w = Math.min(b.x + b.width, x + width) - Math.max(b.x, x);
  const h = Math.min(b.y + b.height, y + height) - Math.max(b.y, y);
  return w > 1 && h > 1;
}

/** A label at screen coordinates, kept whole inside the figure and clear of the labels placed before it. */
export function drawScreenLabel(
  painter: Painter,
  text: string,
  x: number,
  y: number,
  style: LabelStyle = {},
): { width: number } {
  const c = painter.ctx;
  const theme = painter.theme;
  const view = painter.view;
  const size = style.size ?? theme.sizes.label;
  text = say(text);
  const runs = splitSubscripts(text);
  const weight = style.bold ? 'bold ' : '';
  const mainFont = `${weight}${size}px ${theme.fontFamily}`;
  const subFont = `${weight}${Math.round(size * 0.72)}px ${theme.fontFamily}`;
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 1;
  const widths = runs.map((run) => {
    c.font = run.sub ? subFont : mainFont;
    return c.measureText(run.text).width;
  });
  const total = widths.reduce((a, b) => a + b, 0);
  const align = style.align ?? 'left';
  let left =
    align === 'center' ? x - total / 2 : align === 'right' || align === 'end' ? x - total : x;
  const baseline = style.baseline ?? 'middle';
  let middleY = baseline === 'top' ? y + size / 2 : baseline === 'bottom' ? y - size / 2 : y;
  // Keep the whole label inside the figure rather than cut at its edge.
  const margin = 2 + (style.box ? size * 0.35 : 0);
  const inside = (l: number, m: number): [number, number] => [
    Math.max(margin, Math.min(l, view.width - total - margin)),
    Math.max(size * 0.7 + margin, Math.min(m, view.height - size * 0.7 - margin)),
  ];
  [left, middleY] = inside(left, middleY);
  // A label never lands on one already placed this frame: it moves to the
  // nearest free spot around its place (above, below, beside), and if all of
  // them are taken it is left out rather than drawn unreadably on another.
  const height = size * 1.3;
  const free = (l: number, m: number) =>
    !painter.labels.some((b) => overlaps(b, l, m - size * 0.65, total, height));
  if (!free(left, middleY)) {
    const gap = size * 0.3;
    const spot = [
      [0, -height],
      [0, height],
      [total + gap, 0],
      [-(total + gap), 0],
      [total + gap, -height],
      [-(total + gap), -height],
      [total + gap, height],
      [-(total + gap), height],
      [0, -2 * height],
      [0, 2 * height],
    ]
      .map(([dx, dy]) => inside(left + dx, middleY + dy))
      .find(([l, m]) => free(l, m));
    if (!spot) {
      c.restore();
      return { width: 0 };
    }
    [left, middleY] = spot;
  }
  painter.labels.push({ text, x: left, y: middleY - size * 0.65, width: total, height });
  if (style.box) {
    const pad = size * 0.35;
    const box: [number, number, number, number] = [
      left - pad,
      middleY - size * 0.62 - pad * 0.4,
      total + 2 * pad,
      size * 1.3 + pad * 0.8,
    ];
    c.fillStyle = theme.labelHalo;
    c.globalAlpha = 0.92;
    c.fillRect(...box);
    c.globalAlpha = 1;
    c.strokeStyle = style.color ?? theme.ink;
    c.lineWidth = Math.max(1, theme.sizes.thin);
    c.beginPath();
    c.rect(...box);
    c.stroke();
  }
  c.textAlign = 'left';
  c.textBaseline = 'middle';
  runs.forEach((run, i) => {
    c.font = run.sub ? subFont : mainFont;
    const textY = run.sub ? middleY + size * 0.3 : middleY;
    if (style.halo && !style.box) {
      // A halo that follows the glyphs, as map labels have: it keeps the text
      // readable over lines without blanking out a rectangle of the figure.
      c.strokeStyle = theme.labelHalo;
      c.lineWidth = Math.max(2.5, size * 0.22);
      c.lineJoin = 'round';
      c.globalAlpha = 0.9;
      c.strokeText(run.text, left, textY);
      c.globalAlpha = 1;
    }
    c.fillStyle = style.color ?? theme.ink;
    c.fillText(run.text, left, textY);
    left += widths[i];
  });
  c.restore();
  return { width: total };
}

/** A boxed, word-wrapped message across the top of the figure; returns the y below it. */
export function drawNote(
  painter: Painter,
  text: string,
  style: { color?: string; top?: number } = {},
): number {
  const c = painter.ctx;
  const theme = painter.theme;
  const size = theme.sizes.label;
  const pad = size * 0.5;
  const maxWidth = Math.max(size * 6, painter.view.width - 4 * pad);
  c.save();
  c.font = `${size}px ${theme.fontFamily}`;
  const lines: string[] = [];
  text = say(text);
  for (const word of text.split(/\s+/).filter(Boolean)) {
    const last = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
    if (lines.length && c.measureText(last).width <= maxWidth) lines[lines.length - 1] = last;
    else lines.push(word);
  }
  const width = Math.max(...lines.map((line) => c.measureText(line).width), 0);
  const lineHeight = size * 1.3;
  const height = lines.length * lineHeight + pad;
  // At the top of the figure, or at its foot if labels already sit up there.
  const clash = (y: number) =>
    painter.labels.filter((b) => overlaps(b, pad, y, width + 2 * pad, height)).length;
  const foot = painter.view.height - height - pad;
  const top = style.top ?? (clash(pad) > 0 && foot > pad && clash(foot) < clash(pad) ? foot : pad);
  painter.labels.push({ text, x: pad, y: top, width: width + 2 * pad, height });
  c.setLineDash([]);
  c.globalAlpha = 0.94;
  c.fillStyle = theme.labelHalo;
  c.fillRect(pad, top, width + 2 * pad, height);
  c.globalAlpha = 1;
  c.strokeStyle = style.color ?? theme.accent;
  c.lineWidth = Math.max(2, theme.sizes.line);
  c.beginPath();
  c.rect(pad, top, width + 2 * pad, height);
  c.stroke();
  c.fillStyle = theme.ink;
  c.textAlign = 'left';
  c.textBaseline = 'middle';
  lines.forEach((line, i) => c.fillText(line, 2 * pad, top + pad / 2 + (i + 0.5) * lineHeight));
  c.restore();
  return top + height + pad;
}

/**
 * Labels beside a plot cursor at x = `at` (world), one per value (e.g. the
 * weights `L_2 = 0.81`), each at its value's height but pushed apart so none
 * covers another.
 */
export function drawCursorLabels(
  painter: Painter,
  at: number,
  entries: readonly { y: number; text: string; color: string }[],
): void {
  const view = painter.view;
  const sizes = painter.theme.sizes;
  const size = sizes.small;
  const gap = size * 1.3;
  const [x] = view.toScreen([at, 0]);
  const placed = entries
    .map((entry) => ({ ...entry, sy: view.toScreen([at, entry.y])[1] }))
    .sort((a, b) => a.sy - b.sy);
  // Top down, push each label below the one above it; then bottom up, keep
  // them above the axis numbers and the cursor's handle, pushing up in turn.
  const top = size;
  const bottom = view.height - size * 3.2;
  for (let i = 0; i < placed.length; i++) {
    placed[i].sy = Math.max(placed[i].sy, i ? placed[i - 1].sy + gap : top);
  }
  for (let i = placed.length - 1; i >= 0; i--) {
    placed[i].sy = Math.min(placed[i].sy, i < placed.length - 1 ? placed[i + 1].sy - gap : bottom);
  }
  // Near the right edge, write them on the left of the cursor.
  const left = x > view.width * 0.75;
  for (const label of placed) {
    // Clear of the cursor's handle, which may sit on the cursor line.
    const offset = sizes.handle + 6;
    drawScreenLabel(painter, label.text, left ? x - offset : x + offset, label.sy, {
      color: label.color,
      halo: true,
      size,
      align: left ? 'right' : 'left',
    });
  }
}

/**
 * A label beside the screen point `at` on whichever of four sides
 * (above/below, right/left) lies farthest from the `avoid` points (world).
 */
export function drawLabelClear(
  painter: Painter,
  text: string,
  at: readonly [number, number],
  avoid: readonly (readonly number[])[],
  style: LabelStyle = {},
): void {
  const [x, y] = at;
  const size = style.size ?? painter.theme.sizes.label;
  const width = size * 0.6 * text.length;
  const gap = size * 0.7;
  const candidates: [number, number, CanvasTextAlign][] = [
    [gap, -size, 'left'],
    [gap, size, 'left'],
    [-gap, -size, 'right'],
    [-gap, size, 'right'],
  ];
  const obstacles = avoid.map((q) => painter.view.toScreen(q));
  let best = candidates[0];
  let bestClearance = -Infinity;
  for (const candidate of candidates) {
    const [dx, dy, align] = candidate;
    const cx = x + dx + (align === 'left' ? width / 2 : -width / 2);
    const cy = y + dy;
    let clearance = Infinity;
    for (const [ox, oy] of obstacles) clearance = Math.min(clearance, Math.hypot(ox - cx, oy - cy));
    if (clearance > bestClearance + 1e-9) {
      bestClearance = clearance;
      best = candidate;
    }
  }
  drawScreenLabel(painter, text, x + best[0], y + best[1], { ...style, align: best[2] });
}
