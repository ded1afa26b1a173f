import { SvgContext } from '../render/svgContext';
import type { Theme } from '../render/theme';
import type { DrawInfo } from './lesson';
import type { FigureView } from './figureView';

/** Every figure of the lesson laid out as on screen, redrawn as vector SVG. */
export function figuresToSvg<S, M>(
  figures: readonly FigureView<S, M>[],
  model: M,
  theme: Theme,
  info: DrawInfo,
): string {
  const boxes = figures.map((f) => f.element.getBoundingClientRect());
  const left = Math.min(...boxes.map((b) => b.left));
  const top = Math.min(...boxes.map((b) => b.top));
  const width = Math.max(...boxes.map((b) => b.right)) - left;
  const height = Math.max(...boxes.map((b) => b.bottom)) - top;
  const groups = figures.map((figure, i) => {
    const svg = new SvgContext();
    figure.render(svg, model, theme, info);
    const x = Math.round(boxes[i].left - left);
    const y = Math.round(boxes[i].top - top);
    return `<g transform="translate(${x} ${y})">${svg.elements.join('')}</g>`;
  });
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${Math.round(width)}" height="${Math.round(height)}" viewBox="0 0 ${Math.round(width)} ${Math.round(height)}"><rect width="100%" height="100%" fill="${theme.background}"/>${groups.join('')}</svg>`;
}

/** The canvases composed into one PNG at device resolution. */
export function figuresToPng<S, M>(
  figures: readonly FigureView<S, M>[],
  theme: Theme,
): Promise<Blob> {
  const boxes = figures.map((f) => f.element.getBoundingClientRect());
  const left = Math.min(...boxes.map((b) => b.left));
  const top = Math.min(...boxes.map((b) => b.top));
  const dpr = window.devicePixelRatio || 1;
  const canvas = document.createElement('canvas');
  canvas.width = Math.round((Math.max(...boxes.map((b) => b.right)) - left) * dpr);
  canvas.height = Math.round((Math.max(...boxes.map((b) => b.bottom)) - top) * dpr);
  const ctx = canvas.getContext('2d');
  if (!ctx) return Promise.reject(new Error('No 2D canvas available'));
  ctx.fillStyle = theme.background;
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  figures.forEach((figure, i) => {
    const [x, y] = [(boxes[i].left - left) * dpr, (boxes[i].top - top) * dpr];
    // The canvas holds the drawing; its background and grid lie under it.
    ctx.setTransform(dpr, 0, 0, dpr, Math.round(x), Math.round(y));
    figure.paintBackdrop(ctx, theme);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(figure.canvas, Math.round(x), Math.round(y));
  });
  return new Promise((resolve, reject) =>
    canvas.toBlob(
      (blob) => (blob ? resolve(blob) : reject(new Error('PNG encoding failed'))),
      'image/png',
    ),
  );
}

export function download(blob: Blob, filename: string): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
