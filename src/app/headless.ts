/**
 * A lesson's figure drawn without a page: the same drawing calls as the
 * canvas, recorded as SVG. Gallery thumbnails, handouts and the tests that
 * walk every step draw through here, so all three see what the page shows.
 */
import { Painter } from '../render/painter';
import { OrbitCamera } from '../render/orbitCamera';
import type { Projection } from '../render/projection';
import { SvgContext } from '../render/svgContext';
import type { Theme } from '../render/theme';
import { Viewport } from '../render/viewport';
import { drawHandles } from '../render/handles';
import { keyBand } from '../kit/legend';
import { valueBand, valueRowsOver } from '../kit/valueRows';
import type { FigureSpec, Handle } from './lesson';

export interface HeadlessOptions {
  width: number;
  height: number;
  theme: Theme;
  /** A thumbnail: no grid, labels or detail, small plain handles. */
  thumbnail?: boolean;
  /** A space figure's camera as a link writes it (`view.<figure>`): its angles are kept, then fitted. */
  view?: string;
}

export interface HeadlessFigure {
  svg: SvgContext;
  painter: Painter;
  handles: Handle[];
  view: Projection;
}

/** How a figure's units may stretch as it is fitted: freely (a plot), up to its `widen`, or not at all. */
export function fitShape(figure: Pick<FigureSpec<unknown>, 'kind' | 'widen'>): boolean | number {
  return figure.kind === 'plot' ? false : (figure.widen ?? true);
}

/** Room for handles and labels at the edge, as the page fits a figure (never more than a share of a small one). */
export function fitPadding(
  figure: Pick<FigureSpec<unknown>, 'kind' | 'edgeRoom'>,
  theme: Theme,
  width: number,
  height: number,
): number | [number, number] {
  const kind = figure.kind;
  if (kind !== 'plot') {
    const room = theme.sizes.handle * 2 + theme.sizes.label * (figure.edgeRoom ?? 1.6);
    return Math.min(room, 0.12 * Math.min(width, height));
  }
  // A plot's sides hold its y axis' numbers ("0.25" at the type's size), its
  // foot and head the x axis' numbers: each by its own length, so a short,
  // wide strip keeps the room its numbers need beside the axis (#19).
  const small = theme.sizes.small;
  const room = small * 3.2;
  return [Math.min(room, 0.12 * width), Math.min(room, footRoom(small, width, height))];
}

/**
 * A plot's room at its foot and head: 12% of it, and on a plot at least six
 * lines of its numbers tall, never less than the line and a half its x
 * numbers take under it (and its y name over it). A 220 px strip at a 1366 ×
 * 768 projector, 12% of it, pushed the numbers up onto its curves, which then
 * left 0.1 and 0.9 out. A shorter strip (a phone's) keeps its height for its curves.
 */
const footRoom = (small: number, width: number, height: number) => {
  const share = 0.12 * Math.min(width, height);
  return height >= 6 * small ? Math.max(share, 1.5 * small) : share;
};

/**
 * The most a plot of this size gives up above it for its values
 * (FigureSpec.cursorValues): a quarter of its height (a phone's 50 px strip
 * keeps all of it for its curves), or on a plot taller than wide (presenter
 * view's strip beside its curve) what leaves it 0.6 of its width tall.
 */
const valuesRoom = (width: number, height: number) => Math.max(0.25 * height, height - 0.6 * width);

/** The band a figure's heading takes at its top: one line of label type and its margin above. */
export const headlineBand = (theme: Theme): number => theme.sizes.label * 1.9;

/**
 * Fits a figure's view to its subject with `padding` round it, and for a
 * figure with a heading (`headline`) or a key at its top (`keyLines`) a band
 * above for them: the page, handouts and tests fit it the same way.
 */
export function fitFigure<S, M>(
  view: Projection,
  figure: FigureSpec<S, M>,
  model: M,
  theme: Theme,
  padding: number | readonly [number, number],
): void {
  const band =
    view instanceof Viewport
      ? (figure.headline?.(model) ? headlineBand(theme) : 0) +
        keyBand(theme, figure.keyLines?.(model) ?? 0)
      : 0;
  const reach = figure.marksReach?.(model, theme) ?? 0;
  const [padX, padY] = (typeof padding === 'number' ? [padding, padding] : padding).map((pad) =>
    Math.max(pad, reach),
  );
  // The values' room above a plot, in the rows they take at its width, where
  // it leaves the plot most of its height.
  const values = figure.cursorValues?.(model);
  const rows =
    view instanceof Viewport && values ? valueRowsOver(theme, values, view.width, padX) : 0;
  const wanted = valueBand(theme, rows, padY);
  const room = valuesRoom(view.width, view.height);
  const kept = wanted <= room ? wanted : 0;
  if (view instanceof Viewport) view.valueRows = wanted <= room ? rows : 0;
  const top = band + kept;
  // Half the band at each end, then the subject down by half: all of it on top.
  view.fit(figure.bounds(model), [padX, padY + top / 2], fitShape(figure));
  if (top) (view as Viewport).panBy(0, top / 2);
}

/** Draws one figure of the model, fitted to its bounds as the page fits it, with its handles. */
export function drawHeadless<S, M>(
  figure: FigureSpec<S, M>,
  model: M,
  options: HeadlessOptions,
): HeadlessFigure {
  const { width, height, theme, thumbnail = false } = options;
  const view: Projection =
    figure.kind === 'space' ? new OrbitCamera(figure.camera) : new Viewport(width, height);
  view.resize(width, height);
  if (options.view && view instanceof OrbitCamera) view.decode(options.view);
  const padding = thumbnail ? 18 : fitPadding(figure, theme, width, height);
  fitFigure(view, figure, model, theme, padding);
  const svg = new SvgContext();
  const painter = new Painter(svg, view, theme);
  painter.clear();
  const info = { hover: null, thumbnail };
  if (figure.kind === 'geometry' && !thumbnail) painter.grid();
  // Labels are placed once the figure and its handles are down, as on the page.
  painter.holdLabels();
  figure.draw(painter, model, info);
  const handles = figure.handles?.(model) ?? [];
  if (thumbnail) {
    for (const handle of handles)
      painter.handle(handle.position, { color: handle.color, radius: 3.5 });
    painter.placeLabels();
  } else {
    drawHandles(painter, handles);
    figure.drawOver?.(painter, model, info);
    painter.placeLabels();
  }
  return { svg, painter, handles, view };
}
