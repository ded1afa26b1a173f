/**
 * A figure's size: its box as the ResizeObserver last saw it (read once per
 * change, never while drawing a frame), its canvas sharp at any
 * devicePixelRatio, and a strip's fixed height, taller on the projector.
 */
import type { Projection } from '../render/projection';
import type { Theme } from '../render/theme';

/** Keeps a figure's canvas and view the size of its box. */
export class FigureSize {
  /** The canvas's size in CSS pixels, as last sized. */
  width = 0;
  height = 0;
  /** The figure's box as last observed (CSS pixels), or null before the first observation. */
  private box: { width: number; height: number } | null = null;
  private readonly resizeObserver: ResizeObserver;

  constructor(
    private readonly element: HTMLElement,
    private readonly canvas: HTMLCanvasElement,
    private readonly view: Projection,
    /** The box changed size: the figure must be drawn again. */
    resized: () => void,
  ) {
    this.resizeObserver = new ResizeObserver(([entry]) => {
      // The size is read here, once per change, never while drawing a frame.
      this.box = { width: entry.contentRect.width, height: entry.contentRect.height };
      resized();
    });
    this.resizeObserver.observe(this.element);
  }

  disconnect(): void {
    this.resizeObserver.disconnect();
  }

  /** Sizes the canvas to its box (device pixels); true if the size changed. */
  sizeCanvas(): boolean {
    const rect = this.box ?? this.element.getBoundingClientRect();
    const width = Math.max(1, Math.round(rect.width));
    const height = Math.max(1, Math.round(rect.height));
    const dpr = window.devicePixelRatio || 1;
    const changed =
      this.canvas.width !== Math.round(width * dpr) ||
      this.canvas.height !== Math.round(height * dpr);
    if (changed) {
      this.canvas.width = Math.round(width * dpr);
      this.canvas.height = Math.round(height * dpr);
      this.canvas.style.width = `${width}px`;
      this.canvas.style.height = `${height}px`;
    }
    if (width !== this.width || height !== this.height) {
      this.width = width;
      this.height = height;
      this.view.resize(width, height);
      return true;
    }
    return changed;
  }
}

/** A strip of fixed `height`, taller on the projector as its text and handles are. */
export function stripHeight(element: HTMLElement, height: number, theme: Theme): void {
  const css = `${Math.round(height * (theme.sizes.strip ?? 1))}px`;
  if (element.style.minHeight === css) return;
  element.style.flex = `0 0 ${css}`;
  element.style.minHeight = css;
}
