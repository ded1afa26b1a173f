/**
 * Under a figure's canvas: its background and a geometry figure's grid, drawn
 * again only when the size, the view or the theme changes. A drag frame then
 * rasterises what moved, and not a fill and a grid over the whole figure that
 * did not. It is vector drawing, not a second canvas: Chromium hands the
 * compositor a copy of every canvas layer on every frame, changed or not (a
 * static canvas under a drawn one: 3 → 6 ms a frame), while the page's own
 * drawing is rastered again only when it changes.
 */
import { sameValues } from '../kit/memoOn';
import { Painter, SHOW_ALL } from '../render/painter';
import type { Projection } from '../render/projection';
import type { DrawingSurface } from '../render/surface';
import { SvgContext } from '../render/svgContext';
import type { Theme } from '../render/theme';
import type { FigureKind } from './lesson';

const SVG_NS = 'http://www.w3.org/2000/svg';

/** What lies under a figure's drawing: its background, and a geometry figure's grid. */
export function paintBackdrop(
  surface: DrawingSurface,
  view: Projection,
  kind: FigureKind,
  theme: Theme,
): void {
  const painter = new Painter(surface, view, theme, SHOW_ALL);
  painter.clear();
  if (kind === 'geometry') painter.grid();
}

/** The backdrop's SVG element, and what it was last drawn for. */
export class FigureBackdrop {
  readonly element: SVGSVGElement;
  /** The size, theme and view the backdrop was drawn for. */
  private drawnFrom: readonly unknown[] = [];

  constructor(
    private readonly view: Projection,
    private readonly kind: FigureKind,
  ) {
    this.element = document.createElementNS(SVG_NS, 'svg');
    this.element.setAttribute('class', 'figure-backdrop');
    this.element.setAttribute('aria-hidden', 'true');
  }

  /** Draws the background and the grid for a figure of `size`, if the size, the view or the theme changed. */
  draw(size: { readonly width: number; readonly height: number }, theme: Theme): void {
    const { width, height } = size;
    const grid = this.kind === 'geometry';
    // A grid moves with the view: where two of its points land says where it all does.
    const view = grid ? [...this.view.toScreen([0, 0]), ...this.view.toScreen([1, 1])] : [];
    const from = [width, height, theme, ...view];
    if (sameValues(from, this.drawnFrom)) return;
    this.drawnFrom = from;
    const svg = new SvgContext();
    paintBackdrop(svg, this.view, this.kind, theme);
    // Markup the SvgContext wrote from the view's numbers and the theme's colours (escaped).
    const drawn = new DOMParser().parseFromString(svg.toSvg(width, height), 'image/svg+xml');
    for (const [name, value] of [
      ['width', width],
      ['height', height],
    ] as const)
      this.element.setAttribute(name, String(value));
    this.element.setAttribute('viewBox', `0 0 ${width} ${height}`);
    this.element.replaceChildren(
      ...[...drawn.documentElement.childNodes].map((node) => document.importNode(node, true)),
    );
  }
}
