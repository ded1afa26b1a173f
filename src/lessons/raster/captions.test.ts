import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { drawState } from '../../kit/scriptChecks';
import { type Point, chordDeviation, flatteningTree } from '../../math';
import lesson from './lesson';
import type { RasterModel } from './model';
import { type RasterState, schema } from './state';

// The compare scene's captions, walked step by step through the lesson's
// script, against segment counts worked here from their definitions: the
// fewest uniform segments by trying n = 1, 2, 3, … in turn, the flatness
// bound from the control points' second differences. Each count is also the
// one the figure draws (its heading counts the polyline drawn).

const defaults = defaultsOf(schema);
const derive = (s: RasterState) => lesson.derive(s) as RasterModel;
const steps = lesson.steps!;
const compare = (change: Partial<RasterState>) => {
  const scene = lesson.scenes!.find((s) => s.id === 'compare')!;
  return { ...scene.apply(defaults), ...change };
};

/** t = k/n, k = 0 … n, written out here rather than taken from the lesson. */
const uniform = (n: number) => Array.from({ length: n + 1 }, (_, k) => k / n);
/** The largest distance from the curve to the chord of its piece, for polyline vertices at `ts`. */
const gapOf = (points: readonly Point[], ts: number[]) => chordDeviation(points, ts).distance;

/** Adaptive flattening to `tolerance` (units): its leaves' parameters, straight from the maths. */
function adaptive(points: readonly Point[], tolerance: number): number[] {
  const leaves = flatteningTree(points, tolerance).filter((node) => !node.split);
  return [0, ...leaves.map((node) => node.t1)];
}

/** The fewest uniform segments whose polyline strays at most `gap`: n = 1, 2, … tried in turn. */
function fewestWithin(points: readonly Point[], gap: number): number {
  let n = 1;
  while (gapOf(points, uniform(n)) > gap) n++;
  return n;
}

/** ⌈√(d(d−1)·max‖P(i+2) − 2P(i+1) + P(i)‖ / (8τ))⌉: the segments the flatness bound plans for. */
function planned(points: readonly Point[], tolerance: number): number {
  const d = points.length - 1;
  let largest = 0;
  for (let i = 0; i + 2 <= d; i++) {
    const [a, b, c] = [points[i], points[i + 1], points[i + 2]];
    largest = Math.max(largest, Math.hypot(c[0] - 2 * b[0] + a[0], c[1] - 2 * b[1] + a[1]));
  }
  return Math.max(1, Math.ceil(Math.sqrt((d * (d - 1) * largest) / (8 * tolerance))));
}

/** The first whole number in a text ("… 14 segments …" → 14) after `after`. */
const countIn = (text: string, after: RegExp) => Number(after.exec(text)![1]);

const SETTINGS: Partial<RasterState>[] = [
  {},
  { tolerance: 0.2 },
  { tolerance: 1.5 },
  { zoom: 2 },
  { uniformSegments: 9, tolerance: 0.3, zoom: 0.5 },
  {
    points: [
      [1, 1],
      [8, 20],
      [20, 2],
      [30, 18],
    ],
  },
];

describe('the compare scene counts the segments its figure draws, as the definitions give them', () => {
  for (const change of SETTINGS) {
    it(`at ${JSON.stringify(change)}`, () => {
      const base = compare(change);
      const { points } = base;
      const tolerance = base.tolerance / base.zoom;
      const adaptiveTs = adaptive(points, tolerance);
      const seen: string[] = [];
      for (let k = 0; k <= steps.count(base); k++) {
        const s = { ...base, step: k };
        const caption = steps.describe(s, k);
        const name = derive(s).shown.name;
        seen.push(name);
        const texts = drawState(lesson, s).texts;
        const left = texts.find((text) => text.startsWith('Uniform'))!;
        const right = texts.find((text) => text.startsWith('Adaptive'))!;
        const where = `step ${k} (${name}): ${caption} | ${left}`;
        if (name === 'uniform') {
          const n = Math.round(base.uniformSegments);
          expect(countIn(caption, /Uniform, (\d+) segments?/), where).toBe(n);
          expect(countIn(left, /(\d+) segments?/), where).toBe(n);
        }
        if (name === 'adaptive') {
          const n = adaptiveTs.length - 1;
          expect(countIn(caption, /: (\d+) segments?/), where).toBe(n);
          expect(countIn(right, /: (\d+) segments?/), where).toBe(n);
        }
        if (name === 'sameGap') {
          const n = fewestWithin(points, gapOf(points, adaptiveTs));
          expect(countIn(caption, /needs (\d+) segments?/), where).toBe(n);
          expect(countIn(left, /Uniform: (\d+) segments?/), where).toBe(n);
        }
        if (name === 'bound') {
          const n = planned(points, tolerance);
          expect(countIn(caption, /bend: (\d+) segments?/), where).toBe(n);
          expect(countIn(left, /Uniform, planned: (\d+) segments?/), where).toBe(n);
          // The bound keeps its promise: the polyline drawn strays at most τ, as the caption says.
          const gap = gapOf(points, uniform(n)) * base.zoom;
          expect(gap, where).toBeLessThanOrEqual(base.tolerance);
          expect(caption, where).toContain(`they stray ${gap.toFixed(2)} px`);
        }
      }
      expect(seen).toEqual(['twice', 'uniform', 'adaptive', 'sameGap', 'bound']);
    });
  }
});

describe('numbers on screen', () => {
  it('are written to fixed digits, never as a power of ten, in every caption, formula and figure', () => {
    for (const scene of lesson.scenes!) {
      const s = scene.apply(defaults);
      for (let k = 0; k <= steps.count(s); k++) {
        const at = { ...s, step: k };
        const texts = [
          steps.describe(at, k),
          steps.formula!(derive(at), at) ?? '',
          ...drawState(lesson, at).texts,
        ];
        for (const text of texts)
          expect(text, `${scene.id} step ${k}`).not.toMatch(/\d\.\d{5,}|\d[eE][-+]?\d|times 10/);
      }
    }
  });
});

describe('the compare scene’s heading', () => {
  it('stands in a clear corner of the figure, off the grid’s axes and its frame, unboxed on the projector, at every step and size', async () => {
    const { drawHeadless } = await import('../../app/headless');
    const { makeTheme } = await import('../../render/theme');
    const { glyphBox } = await import('../../render/labels');
    const figure = lesson.figures.find((f) => f.id === 'curve')!;
    const base = compare({});
    // Presenter view's left figure, a laptop's, and a phone's (measured on the page).
    const sizes: [number, number, boolean][] = [
      [1050, 900, true],
      [640, 520, false],
      [344, 230, false],
    ];
    let checked = 0;
    for (let k = 0; k <= steps.count(base); k++)
      for (const [width, height, presenter] of sizes) {
        const state = { ...base, step: k };
        const theme = makeTheme(false, presenter);
        const { painter, view } = drawHeadless(figure, derive(state), { width, height, theme });
        const heading = painter.labels.filter((l) => l.text.startsWith('Uniform'));
        const where = `step ${k} at ${width} × ${height}`;
        checked += heading.length;
        const [ox, oy] = view.toScreen([0, 0]);
        for (const line of heading) {
          // On the projector it is found a clear corner; on a phone's short
          // figure there may be none, and a box hides the lines under it.
          if (presenter) expect(line.boxed ?? false, `${where}: “${line.text}” boxed`).toBe(false);
          if (line.boxed) continue;
          const g = glyphBox(line);
          // The axes found from where the view puts the origin, not from the painter.
          const onY = ox > g.x && ox < g.x + g.width;
          const onX = oy > g.y && oy < g.y + g.height;
          expect(onY, `${where}: y-axis through “${line.text}”`).toBe(false);
          expect(onX, `${where}: x-axis through “${line.text}”`).toBe(false);
          // Not pressed against the figure's frame: half its type size clear of each side.
          const room = line.height / 1.3 / 2;
          expect(line.x, `${where}: “${line.text}” at the left edge`).toBeGreaterThanOrEqual(room);
          expect(
            line.x + line.width,
            `${where}: “${line.text}” at the right edge`,
          ).toBeLessThanOrEqual(width - room);
        }
      }
    // Steps 1 to 4 head the figure; at the first it asks its question in the caption.
    expect(checked).toBeGreaterThanOrEqual(4 * sizes.length);
  });
});
