/**
 * Whether a figure's view is fitted to the lesson or is where the user moved
 * it (a pan, a zoom, a turn), and the view's text in the link. A view of the
 * user's is kept, and goes in the link, until a fit is asked for; a fitted one
 * is fitted again when the figure's size changes.
 */
import { OrbitCamera } from '../render/orbitCamera';
import type { Projection } from '../render/projection';
import type { Theme } from '../render/theme';
import type { FigureSize } from './figureSize';
import type { FigureHost } from './figureView';
import { fitFigure, fitPadding } from './headless';
import type { FigureSpec } from './lesson';

/** What the fit needs of the page: the model to fit, the theme, and where to say the view moved. */
export type ViewHost<S, M> = Pick<FigureHost<S, M>, 'model' | 'theme' | 'viewChanged'>;

/** A figure's view, fitted or the user's. */
export class ViewFit<S, M> {
  /** Can the user move this view (and so may the link carry it)? */
  readonly movable: boolean;
  private fitted = false;
  /** The user moved the view: keep it (and put it in the link), unless asked to fit. */
  private userView = false;

  constructor(
    private readonly spec: FigureSpec<S, M>,
    private readonly host: ViewHost<S, M>,
    private readonly view: Projection,
    private readonly size: FigureSize,
    /** The view changed: the figure must be drawn again. */
    private readonly redraw: () => void,
  ) {
    this.movable = spec.kind === 'geometry' || spec.kind === 'space';
  }

  /** Moves the view as the user asked: it is theirs now, and belongs in the link. */
  move(change: () => void): void {
    change();
    this.userView = true;
    this.redraw();
    this.host.viewChanged();
  }

  /** Fits the view to the lesson's bounds (key 0, a preset, first show). */
  fit(): void {
    const changed = this.userView;
    this.userView = false;
    this.fitted = false;
    this.redraw();
    if (changed) this.host.viewChanged();
  }

  /** The figure's size changed: a view that is not the user's is fitted again. */
  resized(): void {
    if (!this.userView) this.fitted = false;
  }

  /** Fits the view to `model` before a frame, when it is due (a plot and a drawing fit every frame). */
  fitIfDue(model: M, theme: Theme): void {
    const alwaysFit = this.spec.kind === 'plot' || this.spec.kind === 'drawing';
    if (!this.fitted || alwaysFit) this.applyFit(model, theme);
  }

  /**
   * The view for the link, when the user has moved it; else null (the link
   * fits). A figure in space turned and then fitted keeps its angles: the
   * link says them, and the fit follows on whatever screen opens it.
   */
  text(): string | null {
    if (!this.movable) return null;
    if (this.userView) return this.view.encode();
    return this.view instanceof OrbitCamera ? this.view.encodeAngles(this.spec.camera) : null;
  }

  /** Takes the view from a link; false if it could not be read (then it fits). */
  apply(text: string | null): boolean {
    if (text === null || !this.movable) {
      // A link without a view opens fitted to the points it brings, as a fresh page does
      // (the view fitted to the last points could leave the new ones off screen).
      this.fit();
      return text === null;
    }
    // Fit first, so a camera read from the link has the distance that fits the scene.
    this.size.sizeCanvas();
    this.applyFit(this.host.model(), this.host.theme());
    // Angles only: turned, then fitted to the scene on this screen.
    if (this.view instanceof OrbitCamera && this.view.decodeAngles(text)) {
      this.userView = false;
      this.fitted = false;
      this.redraw();
      return true;
    }
    const ok = this.view.decode(text);
    this.userView = ok;
    this.fitted = true;
    this.redraw();
    return ok;
  }

  private applyFit(model: M, theme: Theme): void {
    const padding = fitPadding(this.spec, theme, this.view.width, this.view.height);
    fitFigure(this.view, this.spec, model, theme, padding);
    this.fitted = true;
  }
}
