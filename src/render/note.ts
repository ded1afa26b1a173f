/**
 * Words in a box over the figure: the box itself (a note's, a key's), and a
 * note, word-wrapped and put in the first clear corner once the figure and
 * its handles are drawn, or at a given height (notes stacked).
 */
import { say } from './notation';
import type { Box } from './ink';
import { edgePlaces, firstClear, leastHidden } from './boxPlaces';
import { textWidth } from './labelWidth';
import type { Painter } from './painter';
import { subscriptNames } from '../kit/subscripts';

/**
 * A box drawn over the figure for words in it (a note, a key): the
 * background all but opaque, and a border.
 */
export function drawPanelBox(
  painter: Painter,
  box: { x: number; y: number; width: number; height: number },
  border: string,
  borderWidth: number,
): void {
  const c = painter.ctx;
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 0.94;
  c.fillStyle = painter.theme.labelHalo;
  c.fillRect(box.x, box.y, box.width, box.height);
  c.globalAlpha = 1;
  c.strokeStyle = border;
  c.lineWidth = borderWidth;
  c.beginPath();
  c.rect(box.x, box.y, box.width, box.height);
  c.stroke();
  c.restore();
}

/** How a note is drawn: its border's colour, its top (stacked notes), and words for a small figure. */
export interface NoteStyle {
  color?: string;
  /** Given, it sits there at the left. */
  top?: number;
  /** The same said briefly, for a figure too small to hold the whole clear of its handles. */
  brief?: string;
}

/**
 * A note's widths to try, as shares of its figure's: a corner's note, not a
 * banner, then narrower; a banner only when no corner of those is clear (the
 * band a figure keeps free above its curve for a note, #19).
 */
const NOTE_SHARES = [0.6, 0.45, 0.34, 0.26, 0.96];

/**
 * A note's words as the page writes them: the reader's letters, and points
 * named with subscripts (the page's own text turns "P2 = P3" into "P₂ = P₃";
 * the same note on the figure read "P2").
 */
const prose = (text: string) => subscriptNames(say(text));

/**
 * A boxed, word-wrapped message in a corner of the figure; returns the y
 * below it were it at the top left. Given a `top`, it sits there at the left
 * (notes stacked one under another). Otherwise it waits, as labels do, until
 * the figure and its handles are drawn, and takes the first corner (top left,
 * top right, foot left, foot right) where no stroke, point or label runs
 * under it (#19: across the top it covered control points and villages),
 * wrapped as wide as three fifths of the figure or, failing that, narrower
 * and taller (the empty sides of a wide figure); if no corner is clear at any
 * width, the place that hides least.
 */
export function drawNote(painter: Painter, full: string, style: NoteStyle = {}): number {
  const c = painter.ctx;
  const theme = painter.theme;
  const { width: figureWidth, height: figureHeight } = painter.view;
  /** `text` in `size` px wrapped to at most a `share` of the figure's width: its lines and box. */
  const wrapAt = (share: number, size = theme.sizes.label, text = prose(full)) => {
    const words = text.split(/\s+/).filter(Boolean);
    const pad = size * 0.5;
    const maxWidth = Math.max(size * 6, Math.min(figureWidth - 4 * pad, figureWidth * share));
    // Measured through the screen's cache: a note that finds no clear place
    // wraps itself up to 20 ways a frame, each time the same.
    const font = `${size}px ${theme.fontFamily}`;
    const lines: string[] = [];
    for (const word of words) {
      const last = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
      if (lines.length && textWidth(c, font, last) <= maxWidth) lines[lines.length - 1] = last;
      else lines.push(word);
    }
    const width = Math.max(...lines.map((line) => textWidth(c, font, line)), 0);
    return {
      text,
      size,
      pad,
      lines,
      width: width + 2 * pad,
      height: lines.length * size * 1.3 + pad,
    };
  };
  type Wrapped = ReturnType<typeof wrapAt>;
  const widest = wrapAt(NOTE_SHARES[0]);
  const draw = (note: Wrapped, x: number, top: number) => {
    const { text, width, height } = note;
    painter.labels.push({ text, x, y: top, width, height, boxed: true });
    drawPanelBox(
      painter,
      { x, y: top, width: note.width, height: note.height },
      style.color ?? theme.accent,
      Math.max(2, theme.sizes.line),
    );
    c.save();
    c.font = `${note.size}px ${theme.fontFamily}`;
    c.fillStyle = theme.ink;
    c.textAlign = 'left';
    c.textBaseline = 'middle';
    note.lines.forEach((line, i) =>
      c.fillText(line, x + note.pad, top + note.pad / 2 + (i + 0.5) * note.size * 1.3),
    );
    c.restore();
  };
  if (style.top !== undefined) {
    draw(widest, widest.pad, style.top);
    return style.top + widest.height + widest.pad;
  }
  painter.placing(() => {
    // Widest first; a narrower wrap only when no corner of the wider one is
    // clear; then the same in the figure's small size, then the brief words
    // (a phone's small figure), before a handle is hidden.
    const tried: { note: Wrapped; box: Box }[] = [];
    const texts = style.brief ? [prose(full), prose(style.brief)] : [prose(full)];
    for (const text of texts)
      for (const size of new Set([theme.sizes.label, theme.sizes.small]))
        for (const share of NOTE_SHARES) {
          const first = text === texts[0] && size === theme.sizes.label && share === NOTE_SHARES[0];
          const note = first ? widest : wrapAt(share, size, text);
          if (tried.length && note.height > figureHeight - 2 * note.pad) continue;
          const corners = edgePlaces(painter.view, note.width, note.height, note.pad).filter(
            ({ x, y }) => x >= 0 && y >= 0,
          );
          const clear = firstClear(painter, corners);
          if (clear >= 0) return draw(note, corners[clear].x, corners[clear].y);
          tried.push(...corners.map((box) => ({ note, box })));
        }
    // No corner is clear: the place that hides least.
    const best =
      tried[
        leastHidden(
          painter,
          tried.map(({ box }) => box),
        )
      ];
    if (best) draw(best.note, best.box.x, best.box.y);
    else draw(widest, widest.pad, widest.pad);
  });
  return widest.pad + widest.height + widest.pad;
}
