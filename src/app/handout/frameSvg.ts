/**
 * One frame's figures as one SVG document: each shown figure drawn headless
 * (the canvas's own drawing calls) into its box of the lesson's layout, cut
 * to that box, with a grid's headings.
 */
import { escapeXml } from '../../render/svgContext';
import type { Theme } from '../../render/theme';
import { drawHeadless } from '../headless';
import type { AnyLesson } from '../lesson';
import { layoutFrame } from './frameLayout';

const r = (v: number) => Math.round(v * 10) / 10;

export function frameSvg(
  lesson: AnyLesson,
  state: unknown,
  figureIds: readonly string[],
  width: number,
  height: number,
  theme: Theme,
  views: Readonly<Record<string, string>>,
): string {
  const model = lesson.derive(state);
  const placed = layoutFrame(lesson.layout, lesson.figures, new Set(figureIds), {
    x: 0,
    y: 0,
    w: width,
    h: height,
  });
  const parts: string[] = [];
  for (const { id, box } of placed.figures) {
    const figure = lesson.figures.find((f) => f.id === id);
    if (!figure) continue;
    const w = Math.max(1, Math.floor(box.w));
    const h = Math.max(1, Math.floor(box.h));
    const { svg } = drawHeadless(figure, model, { width: w, height: h, theme, view: views[id] });
    parts.push(
      `<svg x="${r(box.x)}" y="${r(box.y)}" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}" overflow="hidden"><title>${escapeXml(figure.title)}</title>${svg.elements.join('')}</svg>`,
    );
  }
  for (const { text, box } of placed.headings)
    parts.push(
      `<text x="${r(box.x + box.w / 2)}" y="${r(box.y + box.h / 2)}" text-anchor="middle" dominant-baseline="central" font-size="${theme.sizes.small}" font-family="${escapeXml(theme.fontFamily)}" fill="${theme.ink}">${escapeXml(text)}</text>`,
    );
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${r(width)}" height="${r(height)}" viewBox="0 0 ${r(width)} ${r(height)}"><rect width="100%" height="100%" fill="${theme.background}"/>${parts.join('')}</svg>`;
}
