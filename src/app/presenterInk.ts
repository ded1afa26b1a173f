/**
 * The lecturer's freehand ink over the figures (presenter's I), in CSS pixels
 * of the stage; the page clears it when the step changes.
 */
import { h, setHidden } from './dom';

export class PresenterInk {
  readonly canvas: HTMLCanvasElement;
  private strokes: [number, number][][] = [];
  private current: [number, number][] | null = null;
  private readonly resize: ResizeObserver;
  private readonly listening = new AbortController();

  constructor() {
    this.canvas = h('canvas', { class: 'ink-layer', 'aria-hidden': 'true', 'data-ink': '' });
    const options = { signal: this.listening.signal };
    this.canvas.addEventListener('pointerdown', (e) => this.down(e), options);
    this.canvas.addEventListener('pointermove', (e) => this.move(e), options);
    this.canvas.addEventListener('pointerup', () => (this.current = null), options);
    this.canvas.addEventListener('pointercancel', () => (this.current = null), options);
    this.resize = new ResizeObserver(() => this.redraw());
    this.resize.observe(this.canvas);
    this.showIfUsed();
  }

  /** Ink is on: the layer takes the pointer (else it lets everything through). */
  active(on: boolean): void {
    this.canvas.classList.toggle('inking', on);
    this.showIfUsed();
  }

  /**
   * The layer is there only while ink is on or on the figure: a blank canvas
   * over the stage is copied for the screen on every frame that paints (at
   * 1920×1080 and scale 2, 4.9 million pixels: 4 ms of each drag frame).
   */
  private showIfUsed(): void {
    setHidden(this.canvas, !this.canvas.classList.contains('inking') && this.strokes.length === 0);
  }

  get count(): number {
    return this.strokes.length;
  }

  clear(): void {
    if (this.strokes.length === 0) return;
    this.strokes = [];
    this.current = null;
    this.redraw();
    this.showIfUsed();
  }

  private at(e: PointerEvent): [number, number] {
    const r = this.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  private down(e: PointerEvent): void {
    this.canvas.setPointerCapture?.(e.pointerId);
    this.current = [this.at(e)];
    this.strokes.push(this.current);
    e.preventDefault();
  }

  private move(e: PointerEvent): void {
    if (!this.current) return;
    const p = this.at(e);
    const last = this.current[this.current.length - 1];
    this.current.push(p);
    const c = this.canvas.getContext('2d');
    if (!c) return;
    this.style(c);
    c.beginPath();
    c.moveTo(last[0], last[1]);
    c.lineTo(p[0], p[1]);
    c.stroke();
  }

  private style(c: CanvasRenderingContext2D): void {
    const dpr = window.devicePixelRatio || 1;
    c.setTransform(dpr, 0, 0, dpr, 0, 0);
    c.strokeStyle = '#e3007d';
    c.lineWidth = 5;
    c.lineCap = 'round';
    c.lineJoin = 'round';
  }

  private redraw(): void {
    const dpr = window.devicePixelRatio || 1;
    const width = Math.round(this.canvas.clientWidth * dpr);
    const height = Math.round(this.canvas.clientHeight * dpr);
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
    const c = this.canvas.getContext('2d');
    if (!c) return;
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.style(c);
    for (const stroke of this.strokes) {
      c.beginPath();
      stroke.forEach(([x, y], i) => (i === 0 ? c.moveTo(x, y) : c.lineTo(x, y)));
      c.stroke();
    }
  }

  destroy(): void {
    this.listening.abort();
    this.resize.disconnect();
  }
}
