/**
 * The clicker's buttons under the figures: step back, where the script is,
 * step forward. The status keeps the height of a scene's tallest step text,
 * so the figures above keep one size as the steps go by.
 */
import { h, setDisabled, setText } from './dom';

/**
 * Step back / status / step forward: the clicker's buttons. They walk the
 * lesson's script (steps, then the next scene), exactly as PageDown/PageUp.
 */
export class StepControl {
  readonly element: HTMLElement;
  private readonly back: HTMLButtonElement;
  private readonly forward: HTMLButtonElement;
  private readonly status: HTMLElement;
  private shown = '';
  /** The scene and width the status's height is held for (see `reserve`). */
  private reservedFor = '';
  private reserveFrame = 0;

  constructor(advance: (delta: 1 | -1) => void) {
    this.back = h(
      'button',
      { type: 'button', onclick: () => advance(-1), title: 'Step back (PageUp, ←)' },
      '◀ Back',
    );
    this.forward = h(
      'button',
      { type: 'button', onclick: () => advance(1), title: 'Step forward (PageDown, →, space)' },
      'Next ▶',
    );
    this.status = h('span', { class: 'step-status', 'aria-live': 'polite' });
    this.element = h('div', { class: 'steps' }, this.back, this.status, this.forward);
  }

  /** Shows where the script is: `first`/`last` say whether there is anything before/after. */
  update(text: string, first: boolean, last: boolean, nextLabel = 'Next ▶'): void {
    const key = `${text}/${first}/${last}/${nextLabel}`;
    if (key === this.shown) return;
    this.shown = key;
    setDisabled(this.back, first);
    setDisabled(this.forward, last);
    setText(this.status, text);
    setText(this.forward, nextLabel);
  }

  /**
   * Holds the status at the height of the tallest of a scene's step texts
   * (`texts`, asked for once), so the figures above keep one size as the
   * steps go by (#19). A phone lets the status grow to say a step whole; a
   * wider screen clamps it to two lines, which already keeps one height. `key`
   * says which scene and width the texts are for. All texts are measured in
   * one layout, at once if the status is on the page, else on the next frame.
   */
  reserve(key: string, texts: () => readonly string[]): void {
    if (key === this.reservedFor) return;
    this.reservedFor = key;
    cancelAnimationFrame(this.reserveFrame);
    this.reserveFrame = 0;
    // Not on the page yet (a page still mounting on a busy machine): tried
    // again frame by frame, else the scene kept no room and its figures shrank
    // at its first long step (phone.spec, once in a fresh-clone run).
    let tries = 0;
    const measure = () => {
      this.reserveFrame = 0;
      if (this.reservedFor !== key || this.holdTallest(texts) || ++tries > MEASURE_TRIES) return;
      this.reserveFrame = requestAnimationFrame(measure);
    };
    if (this.status.isConnected) measure();
    else this.reserveFrame = requestAnimationFrame(measure);
  }

  /** A scene's room is still to be measured: the page is not settled. */
  get measuring(): boolean {
    return this.reserveFrame !== 0;
  }

  /**
   * `texts` is asked for only where the status can grow: each derives every
   * step's model. False when the status is not on the page yet, so nothing
   * could be measured; true when it is measured, or has nothing to hold (it
   * is clamped, or hidden as in presenter view).
   */
  private holdTallest(texts: () => readonly string[]): boolean {
    const status = this.status;
    status.style.minHeight = '';
    if (!status.isConnected) return false;
    const style = getComputedStyle(status);
    if (style.maxHeight !== 'none' || !status.getClientRects().length) return true;
    const twin = h('div', { class: 'step-status-twin', 'aria-hidden': 'true' });
    Object.assign(twin.style, {
      width: style.width,
      font: style.font,
      letterSpacing: style.letterSpacing,
      textAlign: style.textAlign,
      overflowWrap: style.overflowWrap,
      wordBreak: style.wordBreak,
      hyphens: style.hyphens,
    });
    for (const text of texts()) twin.append(h('div', {}, text));
    status.after(twin);
    const tallest = Math.max(
      0,
      ...[...twin.children].map((line) => line.getBoundingClientRect().height),
    );
    // Out of the page between measurements: no stale copy of a step's words
    // for a reader, a search or a test to find beside the status.
    twin.remove();
    status.style.minHeight = `${Math.ceil(tallest)}px`;
    return true;
  }
}

/** Frames a scene's room waits for its status to be on the page (two seconds at 60 Hz). */
const MEASURE_TRIES = 120;
