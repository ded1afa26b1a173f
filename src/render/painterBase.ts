/**
 * What every primitive of the painter draws with and keeps: the surface, the
 * projection and the theme, what the presenter lets the figure show, the
 * rectangle drawing is cut to, and what a frame records as it is drawn (its
 * ink, its labels, the points it names), which its labels are placed against.
 * The painter (painter.ts) builds its vocabulary on it.
 */
import { Ink } from './ink';
import type { ClipRect } from './clip';
import { paletteColor } from './figureColours';
import { figureClip, onFigure } from './figureRect';
import type { LabelBox } from './labels';
import type { P } from './painter';
import type { Projection } from './projection';
import { SHOW_ALL, type Shown, labelHidden, strokeHidden } from './shown';
import { ScreenPoints } from './strokes';
import { type StrokeStyle, applyStroke } from './strokeStyle';
import type { DrawingSurface } from './surface';
import type { Theme } from './theme';

/** The surface, projection, theme and records of a painter, and what its primitives ask of them. */
export class PainterBase {
  /** Every label placed this frame, in screen pixels (for overlap checks). */
  readonly labels: LabelBox[] = [];
  /** Every stroke and disc drawn this frame, in screen pixels: where labels must not sit. */
  readonly ink = new Ink();
  /**
   * Points named on the figure that are not handles (screen pixels): the
   * moving point, a constructed point with a name (B₂). A handle's name must
   * be nearer its own point than any of them (P₃'s beside B₂ reads as B₂'s).
   */
  readonly named: [number, number][] = [];
  /** Accent points a handle drawn after them covers (screen pixels): what the tests look for. */
  readonly underHandles: [number, number][] = [];
  readonly clip: ClipRect;
  /** The buffer world points are projected into (see project). */
  protected readonly screen = new ScreenPoints();

  constructor(
    readonly ctx: DrawingSurface,
    readonly view: Projection,
    readonly theme: Theme,
    /** What may be drawn: all of it, unless the presenter hid something. */
    readonly show: Readonly<Shown> = SHOW_ALL,
    /** The screen rectangle drawn into: the view and a margin, or an inset's box (render/inset). */
    clip?: ClipRect,
  ) {
    this.clip = clip ?? figureClip(view);
  }

  get sizes() {
    return this.theme.sizes;
  }

  color(i: number): string {
    return paletteColor(this.theme, i);
  }

  /** Is a world point on screen (within `margin` pixels of the figure)? */
  visible(p: P, margin = 0): boolean {
    const [x, y] = this.view.toScreen(p);
    return onFigure(this.view, x, y, margin);
  }

  applyStroke(style: StrokeStyle, fallbackWidth: number, fallbackColor: string): void {
    applyStroke(this.ctx, this.theme, style, fallbackWidth, fallbackColor);
  }

  clear(): void {
    const c = this.ctx;
    c.save();
    c.globalAlpha = 1;
    c.fillStyle = this.theme.background;
    c.fillRect(0, 0, this.view.width, this.view.height);
    c.restore();
  }

  /** World points as interleaved screen x, y, in a buffer the next projection reuses. */
  project(points: readonly P[]): Float64Array {
    return this.screen.project(this.view, points);
  }

  /** The presenter hid what this style draws. */
  hidden(style: StrokeStyle): boolean {
    return strokeHidden(this.show, style);
  }

  /** The presenter hid this label (all labels, or those with values). */
  labelHidden(text: string): boolean {
    return labelHidden(this.show, text);
  }
}
