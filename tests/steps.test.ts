/**
 * What a lecturer sees at every step of every scene of every lesson, drawn
 * headless through the recording context at presenter size (the projector's
 * theme, figures sharing 1900 × 800 px by the lesson's layout, as presenter
 * view lays them out at 1920 × 1080):
 *
 * - no text on a figure under 28 px, and point labels at 36 px or more (the
 *   subscript is what tells P₁,₀ from P₁,₁, so it is held to 28 px too);
 * - no label's letters crossed by a stroke or a disc, drawn before it or
 *   after (the painter's own record of its ink), and no label on another;
 * - every handle of the step inside its figure;
 * - the subject (the strokes of role 'curve') not buried under handles: at
 *   most 35% of it hidden across its whole width (a road through 50
 *   villages was 81–94% hidden, through 500 all of it);
 * - every point's name nearer its own point than any other, on the projector
 *   and on a phone (P₃'s name beside P₄ is read as P₄'s);
 * - numbers to sensible digits on the figures, in the caption and in the
 *   step's formula: no
 *   "1.000000000000", no rounding residue "2.69×10⁻¹⁶", and nothing the page's
 *   own check reads as a broken value ("NaN", "undefined,");
 * - no caption that places a figure ("on the left", "the plot below"): the
 *   figures sit side by side on a projector and one under another on a phone;
 * - every press changes what the room sees besides the caption: a figure or
 *   the step's formula;
 * - the point a step is about (P(t) in the accent colour) never under a
 *   handle: at every step, and at each scene's last step with the parameter at
 *   its ends, where P(0) = P₀.
 */
import { describe, expect, it } from 'vitest';
import type { AnyLesson } from '../src/app/lesson';
import { normalizeState } from '../src/app/lessonState';
import { lessons } from '../src/app/registry';
import { defaultsOf } from '../src/app/urlState';
import { drawHeadless } from '../src/app/headless';
import { filled } from '../src/render/formula';
import { type LabelBox, glyphBox } from '../src/render/labels';
import { makeTheme } from '../src/render/theme';
import { subjectUnderHandles } from '../src/render/buried';
import type { Painter } from '../src/render/painter';
import { presenterSizes, stacked } from '../src/app/figureSizes';
import { layoutFor } from '../src/app/tallLayout';

const theme = makeTheme(false, true);
/** The figures' share of presenter view at 1920 × 1080, under the caption and formula. */
const AREA = { width: 1900, height: 840 };
/** Presenter sizes at 1920 × 1080 (issue #19): any text on a figure, and a point's label. */
const MIN_TEXT = 28;
const MIN_POINT_LABEL = 36;
/** The most of the subject (a curve, a road) its handles may cover: it must still be seen. */
const BURIED = 0.35;
/**
 * The figures' share of a phone held upright (360 × 740): one under another,
 * 344 px wide and about 450 px between them (measured on the page: curvature's
 * three are 158, 106 and 183 px tall, lagrange's two 279 and 175).
 */
const PHONE = { width: 344, height: 450 };
const phoneTheme = makeTheme(false, false);

/**
 * A number no lecturer reads out: more than six decimals ("1.000000000000",
 * "0.9411764706") or a rounding residue in powers of ten ("2.69×10⁻¹⁶", "3.7e-15"). Null
 * when the text has none.
 */
function unreadableNumber(text: string): string | null {
  return /\d\.\d{7,}|×\s?10[⁻-]|\de[-+−]?\d/.exec(text)?.[0] ?? null;
}

/** A value gone wrong, as quality.spec reads the page: NaN, Infinity, "= undefined", "undefined,". */
const BROKEN = /\bNaN\b|Infinity|[=(,]\s*undefined\b(?!\s*\()|\bundefined\s*[,)=]/;

/** Distance from (x, y) to the nearest point of a label's box. */
const toBox = (x: number, y: number, b: LabelBox) =>
  Math.hypot(Math.max(b.x - x, 0, x - b.x - b.width), Math.max(b.y - y, 0, y - b.y - b.height));

/**
 * A point's name nearer another point than its own is read as the other's
 * (P₃ beside P₄): every label placed beside a point, unless a leader line ties
 * it to its point, is nearest its own.
 */
function namedElsewhere(
  labels: readonly LabelBox[],
  points: readonly [number, number][],
): string[] {
  const found: string[] = [];
  for (const label of labels) {
    if (!label.anchor || label.leader) continue;
    const [ax, ay] = label.anchor;
    const own = toBox(ax, ay, label);
    const nearer = points.find(
      ([x, y]) => (x !== ax || y !== ay) && toBox(x, y, label) < own - 0.5,
    );
    if (nearer)
      found.push(
        `“${label.text}” is nearer the point at (${nearer.map((v) => v.toFixed(0)).join(', ')}) than its own`,
      );
  }
  return found;
}

/** Words that place a figure on the screen, which changes with the screen's shape. */
const PLACE_ON_SCREEN =
  /\bon the (left|right)\b|\b(figure|plot|strip|curve|functions?)s? (below|above|beside)\b/i;

interface Drawn {
  svg: string;
  problems: string[];
}

/** Every figure the state's scene shows, drawn as the projector shows it, with what is wrong in it. */
function drawStep(
  lesson: AnyLesson,
  state: unknown,
  layout: AnyLesson['layout'],
  area = AREA,
): Drawn {
  const model = lesson.derive(state);
  const figures = figuresOf(lesson, state);
  const sizes = presenterSizes(layout, figures, area, theme.sizes.strip ?? 1);
  const problems: string[] = [];
  let svg = '';
  for (const figure of figures) {
    // Each figure as the projector lays it out, a strip as tall as it draws it.
    const size = sizes.get(figure.id)!;
    const [width, height] = [Math.round(size.width), Math.round(size.height)];
    const {
      svg: context,
      painter,
      handles,
      view,
    } = drawHeadless(figure, model, {
      width,
      height,
      theme,
    });
    const drawing = context.toSvg(width, height);
    svg += drawing;
    const at = `${figure.id}:`;
    for (const [, size, text] of drawing.matchAll(
      /<text[^>]*font-size="([\d.]+)"[^>]*>([^<]*)</g,
    )) {
      if (Number(size) < MIN_TEXT - 0.5) problems.push(`${at} “${text}” at ${size} px`);
      const digits = unreadableNumber(text);
      if (digits) problems.push(`${at} “${text}” writes ${digits}`);
      // What the page's own check reads as a broken number (quality.spec): say "undefined and".
      if (BROKEN.test(text)) problems.push(`${at} “${text}” reads as a broken number`);
      // A derivative's prime is ′, not a typewriter apostrophe (P′(t), not P'(t)).
      if (/[\p{L})]'(?!\p{L})/u.test(text.replace(/&#39;|&apos;/g, "'")))
        problems.push(`${at} “${text}” writes a prime as an apostrophe`);
      // A value not shown yet is asked for in words, not left as a bare “?”.
      if (/(^|:\s*)\?$/.test(text)) problems.push(`${at} “${text}” ends in a bare “?”`);
    }
    const labels = painter.labels;
    // Whole on its figure: a sentence wider than a narrow figure takes lines, a legend's names too.
    for (const b of labels)
      if (b.x < -0.5 || b.y < -0.5 || b.x + b.width > width + 0.5 || b.y + b.height > height + 0.5)
        problems.push(
          `${at} “${b.text}” runs off the figure (${b.x.toFixed(0)}, ${b.y.toFixed(0)}, ${b.width.toFixed(0)} × ${b.height.toFixed(0)} in ${width} × ${height})`,
        );
    const onScreen = handles.map((h) => view.toScreen(h.position));
    for (const through of crossedLabels(painter, onScreen)) problems.push(`${at} ${through}`);
    if (figure.kind === 'geometry')
      for (const on of labelsOnGridAxes(painter, view)) problems.push(`${at} ${on}`);
    for (let i = 0; i < labels.length; i++)
      for (let j = i + 1; j < labels.length; j++) {
        const [a, b] = [labels[i], labels[j]];
        const w = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
        const h = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
        if (w > 1 && h > 1) problems.push(`${at} “${a.text}” on “${b.text}”`);
      }
    problems.push(
      ...namedElsewhere(painter.labels, [...onScreen, ...painter.named]).map((p) => at + ' ' + p),
    );
    const buried = subjectUnderHandles(painter.ink);
    if (buried > BURIED)
      problems.push(
        `${at} the curve lies under handles for ${(buried * 100).toFixed(0)}% of its length`,
      );
    for (const [x, y] of painter.underHandles)
      problems.push(`${at} a handle hides the point at (${x.toFixed(0)}, ${y.toFixed(0)})`);
    for (const handle of handles) {
      const [x, y] = view.toScreen(handle.position);
      if (!(x >= 0 && y >= 0 && x <= width && y <= height))
        problems.push(`${at} handle ${handle.id} outside, at (${x.toFixed(0)}, ${y.toFixed(0)})`);
    }
  }
  return { svg, problems };
}

/**
 * Labels a stroke or a point runs through, and boxed labels and notes that
 * hide a handle (a box is drawn over what it covers: lines may run under it,
 * but a point a person drags must stay in reach).
 */
function crossedLabels(painter: Painter, handles: readonly [number, number][]): string[] {
  // A handle is the figure's own list of them, drawn at the theme's size: not
  // the painter's record, so a placer blind to handles cannot blind this too.
  const r = painter.theme.sizes.handle;
  return painter.labels.flatMap((label) => {
    if (label.boxed) {
      const hidden = handles.find(([x, y]) => toBox(x, y, label) < r);
      return hidden
        ? [`“${label.text}” hides the handle at (${hidden.map((v) => v.toFixed(0)).join(', ')})`]
        : [];
    }
    const through = painter.ink.crossing(glyphBox(label));
    return through ? [`${through} through “${label.text}”`] : [];
  });
}

/**
 * Unboxed labels the grid's x- or y-axis runs through. The grid is drawn
 * under the canvas, apart from the figure's ink: its axes are found here from
 * where the view puts the origin, not from the painter's record.
 */
function labelsOnGridAxes(painter: Painter, view: { toScreen(p: number[]): number[] }): string[] {
  const [ox, oy] = view.toScreen([0, 0]);
  return painter.labels.flatMap((label) => {
    if (label.boxed) return [];
    const g = glyphBox(label);
    const on: string[] = [];
    if (ox > g.x && ox < g.x + g.width) on.push('the y-axis');
    if (oy > g.y && oy < g.y + g.height) on.push('the x-axis');
    return on.map((axis) => `${axis} through “${label.text}”`);
  });
}

function figuresOf(lesson: AnyLesson, state: unknown) {
  const shownIds = lesson.figuresShown?.(state) ?? null;
  return lesson.figures.filter((f) => !shownIds || shownIds.includes(f.id));
}

/**
 * The step on a phone (360 px wide: each figure the page's width, one under
 * another, in the screen's theme): whose names are beside whose points, and
 * which labels a stroke runs through (a label clear on the projector may not
 * be on a figure of another shape).
 */
function namesOnPhone(lesson: AnyLesson, state: unknown): string[] {
  const model = lesson.derive(state);
  const figures = figuresOf(lesson, state);
  const ids = figures.map((f) => f.id);
  const sizes = presenterSizes(stacked(lesson.layout, ids), figures, PHONE, 1);
  return figures.flatMap((figure) => {
    const size = sizes.get(figure.id)!;
    const { painter, handles, view } = drawHeadless(figure, model, {
      width: Math.round(size.width),
      height: Math.round(size.height),
      theme: phoneTheme,
    });
    const onScreen = handles.map((h) => view.toScreen(h.position));
    return [
      ...crossedLabels(painter, onScreen),
      ...namedElsewhere(painter.labels, [...onScreen, ...painter.named]),
    ].map((p) => `phone ${figure.id}: ${p}`);
  });
}

/**
 * Each scene of the lesson as it opens (step 0), with its last step and its
 * figures' arrangement in `area`: presenter view arranges them once, as the
 * scene opens (tallLayout.ts).
 */
function* openedScenes(lesson: AnyLesson, area: { width: number; height: number }) {
  const steps = lesson.steps!;
  const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
  for (const scene of lesson.scenes ?? []) {
    const opened = normalizeState(lesson, { ...scene.apply(defaults), [steps.key]: 0 }).state;
    const layout = layoutFor(lesson, figuresOf(lesson, opened), lesson.derive(opened), area, theme);
    yield { scene, opened, count: steps.count(opened), layout };
  }
}

describe('presenter sizes', () => {
  it('a point’s label is 36 px and its subscript 28 px on the projector', () => {
    expect(theme.sizes.label).toBeGreaterThanOrEqual(MIN_POINT_LABEL);
    expect(theme.sizes.small).toBeGreaterThanOrEqual(MIN_TEXT);
  });
});

describe('every step of every scene, as the room sees it', () => {
  for (const meta of lessons) {
    it(`${meta.slug}: legible, clear of strokes, handles inside, points named as drawn, and every press shows something new`, async () => {
      const lesson = await meta.load();
      const steps = lesson.steps!;
      const found: string[] = [];
      for (const { scene, opened, count, layout } of openedScenes(lesson, AREA)) {
        let before: string | null = null;
        for (let k = 0; k <= count; k++) {
          const state = normalizeState(lesson, { ...opened, [steps.key]: k }).state;
          const { svg, problems } = drawStep(lesson, state, layout);
          for (const problem of [...problems, ...namesOnPhone(lesson, state)])
            found.push(`${scene.id} step ${k}: ${problem}`);
          // The caption names points as the figure labels them: P₁, not P1; y₃, not y3.
          const caption = steps.describe(state, k);
          const plain = caption.match(
            /(?<![A-Za-z])(?:[PDBQLH]\d|[xy]\d\b|[PDBQLHNux]\([ijkmnr](?:[+−]\d+)?(?:,\s?\w+)?\)|[PDBQLH][ijkmn]\b)/,
          );
          if (plain) found.push(`${scene.id} step ${k}: the caption writes “${plain[0]}”`);
          // Figures sit side by side on a wide screen and one under another on a
          // phone: a caption that says "on the left" or "the plot below" is wrong on one.
          const place = caption.match(PLACE_ON_SCREEN);
          if (place) found.push(`${scene.id} step ${k}: the caption says “${place[0]}”`);
          // A caption is plain words and Unicode: a TeX subscript's underscore is read out as one.
          const texInCaption = caption.match(/\w_\{?\w+\}?|\\[a-z]+/);
          if (texInCaption)
            found.push(`${scene.id} step ${k}: the caption writes “${texInCaption[0]}”`);
          const digits = unreadableNumber(caption);
          if (digits) found.push(`${scene.id} step ${k}: the caption writes ${digits}`);
          const formula = steps.formula?.(lesson.derive(state), state);
          const tex = typeof formula === 'string' ? formula : formula ? filled(formula) : '';
          const texDigits = unreadableNumber(tex.replace(/\\times\s*10\^\{?[-−]/g, '×10⁻'));
          if (texDigits) found.push(`${scene.id} step ${k}: the formula writes ${texDigits}`);
          // What the room sees besides the caption: the figures and the step's formula.
          const seen = `${svg}\n${steps.formula?.(lesson.derive(state), state) ?? ''}`;
          if (before !== null && seen === before)
            found.push(
              `${scene.id} step ${k}: the figures and formula are the same as step ${k - 1}’s`,
            );
          before = seen;
        }
        // At the parameter's ends the moving point is an end point, under its handle.
        const parameter = lesson.parameter;
        if (parameter)
          for (const end of [parameter.min, parameter.max]) {
            const state = normalizeState(lesson, {
              ...opened,
              [steps.key]: count,
              [parameter.key]: end,
            }).state;
            for (const problem of drawStep(lesson, state, layout).problems.filter((p) =>
              p.includes('a handle hides'),
            ))
              found.push(`${scene.id} last step, ${parameter.label} = ${end}: ${problem}`);
          }
      }
      expect(found).toEqual([]);
    }, 120_000);
  }
});

/**
 * Presenter view's figure area on a lecturer's laptop (1366 × 768), its type
 * as large as on a projector: the figures are smaller, so a sentence or a
 * legend that fits at 1920 × 1080 may not. (Crowding there is not held to
 * the projector's rules here. That no key hides a handle is read from the
 * page instead, in laptop.spec: this model's text widths are estimates, and
 * it saw keys over handles the page does not draw there, and missed one it
 * does.)
 */
const LAPTOP = { width: 1346, height: 560 };

describe('every step of every scene, projected from a laptop', () => {
  for (const meta of lessons) {
    it(`${meta.slug}: every label whole on its figure and every handle on it`, async () => {
      const lesson = await meta.load();
      const steps = lesson.steps!;
      const found: string[] = [];
      for (const { scene, opened, count, layout } of openedScenes(lesson, LAPTOP)) {
        for (let k = 0; k <= count; k++) {
          const state = normalizeState(lesson, { ...opened, [steps.key]: k }).state;
          for (const problem of drawStep(lesson, state, layout, LAPTOP).problems)
            if (/runs off the figure|outside, at/.test(problem))
              found.push(`${scene.id} step ${k}: ${problem}`);
        }
      }
      expect([...new Set(found)]).toEqual([]);
    });
  }
});
