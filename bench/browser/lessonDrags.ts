// The drags of one lesson: a movable point, each slider, and a preset's point.
import type { Browser, Page } from '@playwright/test';
import {
  circlePath,
  sweepPath,
  tracedDrag,
  type DragLimits,
  type DragResult,
  type SliderBox,
} from './drag';
import { figureDrawn, freshContext, nextFrames } from './page';

/** One line of the drag table: a measurement, or a note saying why there is none. */
export interface DragRow {
  readonly lesson: string;
  readonly control: string;
  readonly result?: DragResult;
  readonly note?: string;
  /** The reference page's p95 (ms), measured just before this lesson's drags. */
  readonly referenceP95?: number;
}

/** A preset to set up before dragging, and which of its points to take. */
export interface PresetDrag {
  readonly lesson: string;
  readonly button: string;
  /** Printed after the point's name, e.g. "village". */
  readonly pointKind: string;
}

interface HandleBox {
  readonly index: number;
  readonly id: string;
  readonly name: string;
  readonly centre: readonly [number, number];
  readonly canvasCentre: readonly [number, number];
  readonly onCanvas: boolean;
}

const HANDLE = '.handle-proxy';
const SLIDER = 'input[type=range]';

/** A movable point and every slider of the lesson, at its opening state. */
export async function dragLesson(
  browser: Browser,
  base: string,
  slug: string,
  limits: DragLimits,
): Promise<DragRow[]> {
  return withLesson(browser, base, slug, async (page) => {
    const rows: DragRow[] = [await dragPoint(browser, page, slug, 'first', limits)];
    const count = await page.locator(SLIDER).count();
    for (let index = 0; index < count; index++)
      rows.push(await dragSlider(browser, page, slug, index, limits));
    return rows;
  });
}

/** A point in the middle of the preset's points (a village of 500, say). */
export async function dragPreset(
  browser: Browser,
  base: string,
  preset: PresetDrag,
  limits: DragLimits,
): Promise<DragRow[]> {
  return withLesson(browser, base, preset.lesson, async (page) => {
    const button = page.getByRole('button', { name: preset.button, exact: true });
    if ((await button.count()) === 0)
      return [{ lesson: preset.lesson, control: preset.button, note: 'preset button not found' }];
    await button.first().click();
    await settle(page);
    const row = await dragPoint(browser, page, preset.lesson, 'middle', limits, preset.pointKind);
    return [{ ...row, control: `${preset.button}: ${row.control}` }];
  });
}

/** Opens `#/<slug>` in a fresh context, waits for its figure, runs `measure`, closes. */
async function withLesson(
  browser: Browser,
  base: string,
  slug: string,
  measure: (page: Page) => Promise<DragRow[]>,
): Promise<DragRow[]> {
  const context = await freshContext(browser);
  try {
    const page = await context.newPage();
    await page.goto(`${base}#/${slug}`);
    if (!(await figureDrawn(page)))
      return [{ lesson: slug, control: '—', note: 'no figure drawn within 15 s' }];
    await settle(page);
    return await measure(page);
  } finally {
    await context.close();
  }
}

/** Lets fonts, formulas and the first draws finish before anything is measured. */
async function settle(page: Page): Promise<void> {
  await page.waitForLoadState('networkidle');
  await page.evaluate(() => document.fonts.ready.then(() => undefined));
  for (let i = 0; i < 5; i++) await nextFrames(page);
}

async function dragPoint(
  browser: Browser,
  page: Page,
  slug: string,
  which: 'first' | 'middle',
  limits: DragLimits,
  kind = 'point',
): Promise<DragRow> {
  const handle = pickHandle(await handleBoxes(page), which);
  if (!handle) return { lesson: slug, control: kind, note: `no movable ${kind} on a canvas` };
  const result = await tracedDrag(
    browser,
    page,
    circlePath(handle.centre, handle.canvasCentre, limits.frames),
    { selector: HANDLE, index: handle.index, property: 'handle' },
    limits,
  );
  return { lesson: slug, control: `${kind} ${handle.name}`, result };
}

async function dragSlider(
  browser: Browser,
  page: Page,
  slug: string,
  index: number,
  limits: DragLimits,
): Promise<DragRow> {
  const slider = page.locator(SLIDER).nth(index);
  const name = (await slider.getAttribute('aria-label')) ?? `#${index + 1}`;
  if (!(await slider.isVisible()) || !(await slider.isEnabled()))
    return { lesson: slug, control: `slider ${name}`, note: 'slider hidden or disabled' };
  await slider.scrollIntoViewIfNeeded();
  await nextFrames(page);
  const box = await sliderBox(page, index);
  const result = await tracedDrag(
    browser,
    page,
    sweepPath(box),
    { selector: SLIDER, index, property: 'value' },
    limits,
  );
  return { lesson: slug, control: `slider ${name}`, result };
}

/** Every keyboard stand-in for a point: where it is, and the centre of its canvas. */
function handleBoxes(page: Page): Promise<HandleBox[]> {
  return page.$$eval(HANDLE, (elements) =>
    elements.map((element, index) => {
      const box = element.getBoundingClientRect();
      const canvas = element.closest('.figure')?.querySelector('canvas');
      const area = canvas?.getBoundingClientRect() ?? new DOMRect(0, 0, innerWidth, innerHeight);
      const [x, y] = [box.left + box.width / 2, box.top + box.height / 2];
      const label = element.getAttribute('aria-label') ?? '';
      return {
        index,
        id: (element as HTMLElement).dataset.handle ?? '',
        name: label.split(' at ')[0] || `#${index + 1}`,
        centre: [x, y] as [number, number],
        canvasCentre: [area.left + area.width / 2, area.top + area.height / 2] as [number, number],
        onCanvas:
          box.width > 0 &&
          x >= Math.max(0, area.left) &&
          x <= Math.min(innerWidth, area.right) &&
          y >= Math.max(0, area.top) &&
          y <= Math.min(innerHeight, area.bottom),
      };
    }),
  );
}

/**
 * The first or the middle one of the lesson's numbered points on screen
 * (`p0`, `p1`, …: control points, villages), else of any handle on screen. A
 * lesson's other handles (a point on the road, a tangent) may be held to a
 * line and barely follow a circle.
 */
function pickHandle(boxes: readonly HandleBox[], which: 'first' | 'middle'): HandleBox | null {
  const visible = boxes.filter((b) => b.onCanvas);
  const numbered = visible.filter((b) => /^p\d+$/.test(b.id));
  const pool = numbered.length > 0 ? numbered : visible;
  return pool[which === 'first' ? 0 : Math.floor(pool.length / 2)] ?? null;
}

function sliderBox(page: Page, index: number): Promise<SliderBox> {
  return page.$$eval(
    SLIDER,
    (elements, at) => {
      const input = elements[at] as HTMLInputElement;
      const box = input.getBoundingClientRect();
      const min = Number(input.min || 0);
      const max = Number(input.max || 100);
      // No step attribute means 1; "any" means continuous.
      const step = input.step === 'any' ? 0 : Number(input.step || 1);
      const range = max - min || 1;
      return {
        left: box.left,
        width: box.width,
        middleY: box.top + box.height / 2,
        fraction: (Number(input.value) - min) / range,
        stepFraction: Number.isFinite(step) && step > 0 ? step / range : 0,
      };
    },
    index,
  );
}
