/**
 * Axis numbers read back from the page's own drawing: the figures' SVG export
 * (the same drawing code as the canvases, written as vector text and paths).
 * A number must sit at its tick, on the grid line of that tick, with the
 * numbers of one axis evenly spaced by their values, and a 0 on the axis line
 * itself: so two scales drawn over each other, a scale shifted by a tick or a
 * number left where the zero line is are all seen (#19).
 */
import type { Page } from '@playwright/test';
import { readFileSync } from 'node:fs';

/** A number written on a figure, with the box of its letters as the browser lays out the SVG. */
export interface Text {
  figure: number;
  x: number;
  y: number;
  width: number;
  height: number;
  size: number;
  value: number;
}
interface Segment {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
}

/** Pixels a number may be off its tick (the export rounds to hundredths). */
const SLACK = 1.5;

/**
 * The figures of the page as the SVG button saves them, and the numbers
 * written on them in plain type, not as a subscript (tick numbers),
 * measured where the browser lays the saved drawing out.
 */
export async function exportedDrawing(page: Page): Promise<{ svg: string; numbers: Text[] }> {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.evaluate(() => {
      const button = [...document.querySelectorAll('button')].find(
        (b) => b.textContent?.trim() === 'SVG',
      );
      if (!button) throw new Error('no SVG button');
      button.click();
    }),
  ]);
  const svg = readFileSync(await download.path(), 'utf8');
  const numbers = await page.evaluate((source) => {
    const holder = document.createElement('div');
    holder.style.cssText = 'position:fixed;left:0;top:0;visibility:hidden';
    // The test's own file, parsed as XML: no markup from the page's data.
    const doc = new DOMParser().parseFromString(source, 'image/svg+xml');
    holder.append(document.importNode(doc.documentElement, true));
    document.body.append(holder);
    const out: Text[] = [];
    holder.querySelectorAll('svg > g').forEach((g, figure) => {
      // The box of the text written just before: a subscript starts where its letter ends.
      let before: DOMRect | null = null;
      for (const t of g.querySelectorAll('text')) {
        if (t.getAttribute('fill') === 'none') continue;
        const text = (t.textContent ?? '').replace('−', '-').trim();
        const box = (t as SVGTextElement).getBBox();
        // (set lower, starting where the text before it ends, give or take the fonts' widths).
        const subscript =
          !!before &&
          Math.abs(before.x + before.width - box.x) < 0.4 * box.height &&
          box.y > before.y + 1;
        before = box;
        if (subscript || t.getAttribute('font-weight') !== 'normal') continue;
        if (!/^-?\d+(\.\d+)?$/.test(text)) continue;
        out.push({
          figure,
          x: box.x,
          y: box.y,
          width: box.width,
          height: box.height,
          size: Number(t.getAttribute('font-size')),
          value: Number(text),
        });
      }
    });
    holder.remove();
    return out;
  }, svg);
  return { svg, numbers };
}

function linesOf(group: string): Segment[][] {
  const lines: Segment[][] = [];
  for (const m of group.matchAll(/<path d="([^"]*)" fill="none"/g)) {
    const segments: Segment[] = [];
    let at: [number, number] | null = null;
    for (const c of m[1].matchAll(/([ML])(-?[\d.]+) (-?[\d.]+)/g)) {
      const p: [number, number] = [Number(c[2]), Number(c[3])];
      if (c[1] === 'L' && at) segments.push({ x1: at[0], y1: at[1], x2: p[0], y2: p[1] });
      at = p;
    }
    lines.push(segments);
  }
  return lines;
}

/**
 * Numbers on one row (an x axis: their tops level) or in one column (a y
 * axis: their right edges level), two or more of them.
 */
function axesOf(texts: Text[]): { axis: 'x' | 'y'; numbers: Text[] }[] {
  const rows = new Map<string, Text[]>();
  const columns = new Map<string, Text[]>();
  for (const t of texts) {
    const row = `${Math.round(t.y)}/${t.size}`;
    const column = `${Math.round(t.x + t.width)}/${t.size}`;
    rows.set(row, [...(rows.get(row) ?? []), t]);
    columns.set(column, [...(columns.get(column) ?? []), t]);
  }
  return [
    ...[...rows.values()].map((numbers) => ({ axis: 'x' as const, numbers })),
    ...[...columns.values()].map((numbers) => ({ axis: 'y' as const, numbers })),
  ].filter((g) => g.numbers.length >= 2);
}

/** What is wrong with the axis numbers of one exported drawing (none: an empty list). */
export function tickProblems({ svg, numbers }: { svg: string; numbers: Text[] }): string[] {
  const problems: string[] = [];
  const groups = svg.split(/<g transform="translate\(/).slice(1);
  groups.forEach((group, g) => {
    const lines = linesOf(group);
    const segments = lines.flat();
    // The axis lines: a path of one horizontal and one vertical stroke.
    const axisPaths = lines.filter(
      (l) =>
        l.length === 2 &&
        Math.abs(l[0].y1 - l[0].y2) < 0.01 &&
        Math.abs(l[1].x1 - l[1].x2) < 0.01 &&
        Math.abs(l[0].x1 - l[0].x2) > 0 &&
        Math.abs(l[1].y1 - l[1].y2) > 0,
    );
    // A plot's numbers: a column left of its vertical axis, a row under its foot.
    // (Numbers elsewhere, a raster's pixel indices or a table's cells, are not ticks.)
    const ofPlot = numbers.filter(
      (t) =>
        t.figure === g &&
        axisPaths.some((l) => {
          const x = l[1].x1;
          const foot = Math.max(l[1].y1, l[1].y2);
          return (
            Math.abs(t.x + t.width - x) < 2 * t.size ||
            (t.y >= foot - SLACK && t.y - foot < 2 * t.size)
          );
        }),
    );
    for (const { axis, numbers: axisNumbers } of axesOf(ofPlot)) {
      // Where a number says its tick is: under an x tick, centred; beside a y tick, level.
      const at = (t: Text) => (axis === 'x' ? t.x + t.width / 2 : t.y + t.height / 2);
      const name = (t: Text) => `figure ${g + 1}, ${axis} axis “${t.value}”`;
      // The letters' box is the font's, not the ink's: a quarter of the type size.
      const slack = (t: Text) => Math.max(SLACK, t.size * 0.25);
      const sorted = [...axisNumbers].sort((a, b) => a.value - b.value);
      const first = sorted[0];
      const last = sorted[sorted.length - 1];
      if (last.value === first.value) {
        problems.push(`${name(first)} twice on one axis`);
        continue;
      }
      // Evenly spaced by value: on one straight line through the first and last.
      const perUnit = (at(last) - at(first)) / (last.value - first.value);
      for (const t of sorted) {
        const expected = at(first) + (t.value - first.value) * perUnit;
        if (Math.abs(at(t) - expected) > slack(t))
          problems.push(
            `${name(t)} at ${at(t).toFixed(1)} px, its scale puts it at ${expected.toFixed(1)}`,
          );
      }
      for (const t of axisNumbers) {
        // Its grid line: across the plot, ending next to the number.
        const onTick = segments.some((s) =>
          axis === 'x'
            ? Math.abs(s.x1 - at(t)) <= slack(t) &&
              Math.abs(s.x2 - at(t)) <= slack(t) &&
              Math.max(s.y1, s.y2) <= t.y + SLACK &&
              Math.max(s.y1, s.y2) >= t.y - 2 * t.size
            : Math.abs(s.y1 - at(t)) <= slack(t) &&
              Math.abs(s.y2 - at(t)) <= slack(t) &&
              Math.min(s.x1, s.x2) >= t.x + t.width - SLACK &&
              Math.min(s.x1, s.x2) <= t.x + t.width + 2 * t.size,
        );
        if (!onTick) problems.push(`${name(t)} is at no tick`);
        // A 0 beside the y axis is where the horizontal axis line is drawn.
        if (axis === 'y' && t.value === 0) {
          const beside = axisPaths.filter(
            (l) => Math.abs(Math.min(l[0].x1, l[0].x2) - (t.x + t.width)) < 2 * t.size,
          );
          if (beside.length && !beside.some((l) => Math.abs(l[0].y1 - at(t)) <= slack(t)))
            problems.push(`${name(t)} is not on the axis line`);
        }
      }
    }
  });
  return problems;
}
