/**
 * The frame that keeps a lesson page in step: what the next animation frame
 * must do, and doing it. Work is done by kind of change: a new state redraws
 * the figures and updates the panel; a hover redraws the figures only; a pan,
 * zoom or resize redraws only its own figure; an idle page does nothing.
 */
import { fitToWidth } from '../render/fit';
import { fixBoxes } from '../render/liveBoxes';
import { closeTypesetBudget, openTypesetBudget, typesetWaiting } from '../render/typesetBudget';
import type { FigureView } from './figureView';

/** The name of each frame's measure in the Performance timeline. */
const FRAME = 'spline-lab:frame';
/**
 * Milliseconds of figure drawing after which the panel waits for the next
 * frame (once): the figure answers the hand first, the text follows.
 */
const PANEL_BUDGET_MS = 12;
/** Milliseconds of a frame in which new formulas are typeset; the rest wait for the next frame. */
const TYPESET_BUDGET_MS = 20;

let firstDrawMarked = false;
let framesMeasured = 0;

/** What a frame works on: the page's figures, its state and the text beside them. */
export interface FrameWork<S, M> {
  readonly figures: readonly FigureView<S, M>[];
  state(): S;
  model(state: S): M;
  /** The boxes whose wide formulas are fitted to their width (the panel, the caption). */
  fitted(): readonly HTMLElement[];
  /** Before the figures are drawn for a new state (`moved`: not only a redraw of the same one). */
  prepare(state: S, model: M, moved: boolean): void;
  /** The panel, the caption and the controls, for this state. */
  updatePanel(state: S, model: M): void;
  /** The hovered point changed: the panel marks it too. */
  hovered(): void;
  /** Something beside the frame is still settling (the step line measuring its room). */
  busy(): boolean;
  /** A link waits to be written (debounced): it is written at once when the page settles. */
  linkPending(): boolean;
  writeLink(): void;
}

export class PageFrame<S, M> {
  private frame = 0;
  private drawnState: S | null = null;
  private panelState: S | null = null;
  /** The panel's update was put off to this frame: it is not put off again. */
  private panelDeferred = false;
  private hoverChanged = false;
  private refreshAll = true;
  private readonly dirtyFigures = new Set<FigureView<S, M>>();
  /** The panel changed: fit its wide content at the start of the next frame. */
  private fitPending = false;
  private panelWidthChanged = false;

  constructor(private readonly work: FrameWork<S, M>) {}

  /** A frame is asked for (once, however often this is called before it). */
  request(): void {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.drawNow();
    });
  }

  /** This figure alone needs drawing (its view or size changed). */
  invalidate(figure: FigureView<S, M>): void {
    this.dirtyFigures.add(figure);
    this.request();
  }

  /** The hovered point changed: every figure and the panel's mark. */
  hoverMoved(): void {
    this.hoverChanged = true;
    this.request();
  }

  /** Every figure is drawn afresh (a presenter tool, an exercise's marks). */
  redrawAll(): void {
    this.refreshAll = true;
    this.request();
  }

  /** Every figure and the panel afresh (display settings changed every size). */
  refresh(): void {
    this.refreshAll = true;
    this.panelState = null;
    this.request();
  }

  /** The panel and caption are written again for the same state (a question asked). */
  panelAgain(): void {
    this.panelState = null;
    this.request();
  }

  /** Wide formulas are fitted again at the start of the next frame (fonts came, a box showed). */
  fitSoon(): void {
    this.fitPending = true;
    this.request();
  }

  /** The panel's width changed: its formulas are fitted to the new one. */
  panelResized(): void {
    this.panelWidthChanged = true;
    this.request();
  }

  /** Draws everything now, as for a new state (before an export). */
  drawAllNow(): void {
    this.refreshAll = true;
    this.drawNow();
  }

  /**
   * Does what the changes since the last frame need. Each frame's work is
   * measured as `spline-lab:frame` (derive + draw + panel), for the
   * benchmark and the tests.
   */
  drawNow(): void {
    const work = this.work;
    const start = performance.now();
    // Fit what the last frame changed first: its layout is clean now (the
    // browser laid it out to draw it), so reading widths forces no layout.
    if (this.fitPending) {
      this.fitPending = false;
      for (const box of work.fitted()) fitToWidth(box);
      // Then the live numbers whose size changed: one layout for all of them.
      for (const box of work.fitted()) fixBoxes(box);
    }
    const typesetting = performance.now();
    // Formulas that waited for this frame, then this frame's own (see typesetBudget.ts).
    if (openTypesetBudget(TYPESET_BUDGET_MS) > 0) this.fitSoon();
    const state = work.state();
    const deriving = performance.now();
    const model = work.model(state);
    const drawing = performance.now();
    const stateChanged = state !== this.drawnState || this.refreshAll;
    if (stateChanged) work.prepare(state, model, state !== this.drawnState);
    const all = stateChanged || this.hoverChanged;
    for (const figure of work.figures) {
      if (figure.element.hidden) continue;
      if (!all && !this.dirtyFigures.has(figure)) continue;
      const from = performance.now();
      figure.draw(model, this.refreshAll);
      performance.measure(`${FRAME}:figure:${figure.spec.id}`, { start: from });
    }
    this.dirtyFigures.clear();
    const panelStart = performance.now();
    // On the first frame the figure goes first: the panel (a page of formulas
    // to typeset) follows in the next frame, so the figure shows sooner. So it
    // does when the figures took long (a new scene): one long task would hold
    // the pointer and keys up, two shorter ones do not.
    const wanted = (stateChanged || state !== this.panelState) && this.drawnState !== null;
    const deferred = wanted && !this.panelDeferred && performance.now() - start > PANEL_BUDGET_MS;
    this.panelDeferred = deferred;
    const panelDue = wanted && !deferred;
    if (panelDue) {
      this.panelState = state;
      work.updatePanel(state, model);
    }
    if (this.hoverChanged) work.hovered();
    if (panelDue || this.panelWidthChanged) this.fitSoon();
    if (!panelDue && this.panelState !== state) this.request();
    if (typesetWaiting()) this.fitSoon();
    closeTypesetBudget();
    this.drawnState = state;
    this.hoverChanged = false;
    this.refreshAll = false;
    this.panelWidthChanged = false;
    if (!firstDrawMarked) {
      firstDrawMarked = true;
      performance.mark('spline-lab:first-draw');
    }
    // The frame ends here: the measuring below is the tests' and the
    // benchmark's, not the app's (a fresh machine once saw 56 ms go inside these
    // calls, its parts summing to 7 ms).
    const end = performance.now();
    if (++framesMeasured % 1000 === 0) performance.clearMeasures();
    // The frame, and its parts: fitting, waiting formulas, the model, the figures, the panel.
    performance.measure(`${FRAME}:fit`, { start, end: typesetting });
    performance.measure(`${FRAME}:typeset`, { start: typesetting, end: deriving });
    performance.measure(`${FRAME}:derive`, { start: deriving, end: drawing });
    performance.measure(`${FRAME}:figures`, { start: drawing, end: panelStart });
    performance.measure(`${FRAME}:panel`, { start: panelStart, end });
    performance.measure(FRAME, { start, end });
  }

  /**
   * Resolves when the page is settled: the state is final, its frame drawn, the
   * panel updated and the link written. Tests wait on this instead of sleeping.
   */
  async settled(): Promise<void> {
    const frame = () => new Promise<void>((resolve) => requestAnimationFrame(() => resolve()));
    await frame();
    for (let i = 0; i < 600; i++) {
      const state = this.work.state();
      const drawing =
        this.frame !== 0 ||
        this.fitPending ||
        typesetWaiting() ||
        // Formula fonts still on their way: the caption and the figure beside it change size when they come.
        document.fonts?.status === 'loading' ||
        this.work.busy() ||
        this.panelState !== state ||
        this.drawnState !== state;
      // The state is final: the link it would write in a moment is written now
      // (a test waiting out the debounce waited 100 ms for nothing).
      if (!drawing && this.work.linkPending()) this.work.writeLink();
      if (!drawing) return;
      await frame();
    }
  }

  stop(): void {
    cancelAnimationFrame(this.frame);
  }
}
