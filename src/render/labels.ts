/**
 * What a label is: the style it is asked in, the box it took on screen, the
 * part of that box its letters fill, the frame round a boxed one, and its
 * text split into runs of normal and subscript letters (`P_{1,2}`). The
 * placer (labelPlacer) puts labels where these say; every placed label's box
 * is recorded on the painter, so tests can check that no two overlap.
 */
import type { Box } from './ink';

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
  /**
   * The anchor is a point drawn with this radius (px), and the label goes
   * beside it on whichever side is clear: above right first, then below
   * right, above left, below left, right, left, above, below.
   */
  around?: number;
  /**
   * Other named points on screen (pixels). A label placed `around` its point
   * goes only where it is nearer its own point than any of these, and than
   * any point the figure names (`Painter.namedPoint`) or handle it has drawn,
   * so P₃'s name beside P₄ is never read as P₄'s; failing that it goes
   * farther out on a leader line from its point.
   */
  rivals?: readonly (readonly [number, number])[];
  /** It stays where it is put (an axis number at its tick), or is left out. */
  fixed?: boolean;
  /**
   * It stays where it is put even where that is not clear: its caller chose
   * the place that hides least (a plot's values, boxed over a dashed line
   * rather than over the curve, and never moved across the cursor's line).
   */
  stays?: boolean;
  /**
   * It names the point it was asked at (`Painter.label`, or `around`): moved
   * away, a leader line back to there says whose it is. A heading or a value
   * at a screen position names no point: moved away, it goes without one
   * (raster's heading hung from a leader to nothing).
   */
  names?: boolean;
  /**
   * Where the point it names is on screen (`Painter.label` says): moved from
   * its first place, it tries places all round that point before it goes
   * farther, rather than shifting a label's width at a time away from it.
   */
  of?: readonly [number, number];
  /**
   * It is said elsewhere too (a number the step's formula or table also
   * shows): where no place near it is clear, it is left out rather than boxed
   * over the figure or sent out on a leader (a phone's crowded patch).
   */
  optional?: boolean;
  /**
   * It is part of a box already drawn and registered (a legend's names): it
   * goes exactly where it is put, and the box stands for it among the labels.
   */
  inBox?: boolean;
}

/** Where a label went, in screen pixels. */
export interface LabelBox {
  text: string;
  x: number;
  y: number;
  width: number;
  height: number;
  /** Drawn on a box of its own (a boxed value, a note), which covers what lies under it. */
  boxed?: boolean;
  /** The point it names, for a label placed beside one (`around`), in screen pixels. */
  anchor?: [number, number];
  /** Tied to that point by a leader line. */
  leader?: boolean;
  /** A boxed label's box as drawn, wider and taller than its letters. */
  frame?: Box;
}

/**
 * The part of a label's box its letters fill (capitals to the foot of a
 * subscript), without the line spacing around them: what no stroke may cross.
 */
export function glyphBox(b: LabelBox): Box {
  return { x: b.x, y: b.y + b.height * 0.18, width: b.width, height: b.height * 0.7 };
}

/** The box drawn round a boxed label `total` wide, its text's middle at (left, middleY). */
export function labelFrame(left: number, middleY: number, total: number, size: number): Box {
  const pad = size * 0.35;
  return {
    x: left - pad,
    y: middleY - size * 0.62 - pad * 0.4,
    width: total + 2 * pad,
    height: size * 1.3 + pad * 0.8,
  };
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
