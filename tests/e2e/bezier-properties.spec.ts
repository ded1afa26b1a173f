import type { Page } from '@playwright/test';
import { bezierPoint, elevateDegree, type Point } from '../../src/math';
import { expect, expectHash, snapshot, test, linkState } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="experiment"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());
const pointsOf = (value: string): Point[] => value.split(';').map((q) => q.split(',').map(Number));

test.beforeEach(async ({ page }) => {
  await page.goto('./#/bezier-properties');
  await expect(figure(page)).toBeVisible();
});

/** The step status under the figure: "Step k/count: caption". */
const status = (page: Page) => page.getByText(/^Step \d+\/\d+: /);

test('the clicker walks every experiment from its control points to the whole picture', async ({
  page,
}) => {
  const scenes = page.locator('[data-scene]');
  await expect(scenes).toHaveCount(13);
  await page.keyboard.press('p');
  await page.keyboard.press('Home');
  for (let i = 0; i < 13; i++) {
    const id = await scenes.nth(i).getAttribute('data-scene');
    await expect(scenes.nth(i)).toHaveAttribute('aria-pressed', 'true');
    await expect(status(page)).toHaveText(/^Step 0\/(\d+): The \d+ control points P₀ … P/);
    const count = Number(/^Step 0\/(\d+)/.exec((await status(page).textContent())!)![1]);
    expect(count, id!).toBeGreaterThanOrEqual(4);
    expect(count, id!).toBeLessThanOrEqual(20);
    const first = await pixels(page);
    await page.keyboard.press('PageDown');
    await expect(status(page)).toContainText(`Step 1/${count}: `);
    await page.keyboard.press('End');
    await expect(status(page)).toContainText(`Step ${count}/${count}: `);
    await expect.poll(() => pixels(page)).not.toBe(first);
    await snapshot(page, `bezier-properties-${id}-presenter-last`);
    await page.keyboard.press('PageDown');
  }
  await expect(scenes.last()).toHaveAttribute('aria-pressed', 'true');
});

test('raising the degree keeps the curve within 1e-9 and brings the polygon closer', async ({
  page,
}) => {
  await page.getByRole('button', { name: '5 Raise the degree' }).click();
  await expectHash(page, 'x', (v) => v === 'elevate');
  await expectHash(page, 'k', (v) => v === '0');
  const raise = page.getByRole('button', { name: 'Raise the degree', exact: true });
  const gaps: number[] = [];
  for (let j = 1; j <= 6; j++) {
    await raise.click();
    // Step 1 is the curve; each later step one elevation more.
    await expectHash(page, 'k', (v) => v === String(j + 1));
    await expect(page.locator('.experiment-details')).toHaveAttribute(
      'data-control-points',
      String(4 + j),
    );
    const rows = page
      .getByRole('table', { name: 'Distance from polygon to curve' })
      .locator('tbody tr');
    await expect(rows).toHaveCount(j + 1);
    gaps.push(Number(await rows.last().locator('td').last().innerText()));
  }
  for (let j = 1; j < gaps.length; j++) expect(gaps[j]).toBeLessThan(gaps[j - 1]);
  // The same check on our own: the points in the link, elevated six times, sample the same curve.
  const p = pointsOf((await linkState(page)).p);
  let q: readonly Point[] = p;
  for (let j = 0; j < 6; j++) q = elevateDegree(q);
  expect(q).toHaveLength(10);
  for (let s = 0; s <= 200; s++) {
    const a = bezierPoint(p, s / 200);
    const b = bezierPoint(q, s / 200);
    expect(Math.hypot(a[0] - b[0], a[1] - b[1])).toBeLessThan(1e-9);
  }
  await expect(
    page.getByText(/over 1001 samples: (0|[\d.]+ × 10⁻[⁰¹²³⁴⁵⁶⁷⁸⁹]+) — the same curve/),
  ).toBeVisible();
  // A clicker steps the elevation too, and the count survives a reload of the link.
  await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '8');
  await page.reload();
  await expect(status(page)).toContainText('Degree raised 7 times, to 10');
  await expect(page.locator('.experiment-details')).toHaveAttribute('data-control-points', '11');
});

test('moving an inner point of twelve barely moves the curve, and "before" survives the link', async ({
  page,
}) => {
  await page.getByRole('button', { name: '3 No local control' }).click();
  await expect(
    page.getByText(/P₅ moved by 2\.000, the curve by at most 23\.6% of that/),
  ).toBeVisible();
  // The link is written shortly after a change: wait for the preset's "before" to be in it.
  await expectHash(page, 'q', (v) => v.split(';').length === 12);
  const before = (await linkState(page)).q;
  const p5 = page.getByRole('button', { name: /^P5 at/ });
  await p5.focus();
  await page.keyboard.press('Shift+ArrowUp');
  await expectHash(page, 'p', (v) => pointsOf(v)[5][1] > pointsOf(before)[5][1] + 2);
  expect((await linkState(page)).q).toBe(before);
  const text = await page.getByText(/Largest displacement of the curve/).innerText();
  const largest = Number(/curve: ([\d.]+)/.exec(text)![1]);
  const moved = pointsOf((await linkState(page)).p)[5][1] - pointsOf(before)[5][1];
  // W(11, 5, 5/11) ≈ 0.236: the curve moves less than a quarter of the point.
  expect(largest / moved).toBeGreaterThan(0.23);
  expect(largest / moved).toBeLessThan(0.24);
  const link = page.url();
  const other = await page.context().newPage();
  await other.goto(link);
  await expect(other.getByText(text)).toBeVisible();
  await other.close();
  await page.getByRole('button', { name: 'Make this the "before" curve' }).click();
  await expect(page.getByText(/The dashed "before" curve is the current one/)).toBeVisible();
});

test('the curve stays in the convex hull while a point is dragged', async ({ page }) => {
  await page.getByRole('button', { name: '2 Convex hull' }).click();
  await expect(page.getByText('All 401 sampled curve points lie in the hull.')).toBeVisible();
  const p3 = page.getByRole('button', { name: /^P3 at/ });
  const box = (await p3.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + 200, box.y - 150, { steps: 5 });
  await page.mouse.up();
  await expectHash(page, 'p', (v) => pointsOf(v)[3][1] > 2);
  await expect(page.getByText('All 401 sampled curve points lie in the hull.')).toBeVisible();
  // Collinear points: the hull is a segment, and the lesson says so.
  await page.goto('./#/bezier-properties?x=hull&p=0,0;1,1;2,2;3,3');
  await expect(page.getByText(/the hull is a segment/)).toBeVisible();
});

test('maps, inflections, loops and the Hermite form are found and explained', async ({ page }) => {
  await page.getByRole('button', { name: '7 Affine map' }).click();
  await expect(page.getByText(/they agree, up to rounding/)).toBeVisible();
  await page.getByRole('button', { name: '7 Perspective map' }).click();
  await expectHash(page, 'm', (v) => v === 'perspective');
  await expect(page.getByText(/they differ/)).toBeVisible();
  // A point behind the vanishing line: no image, and a sentence why.
  await page.goto('./#/bezier-properties?x=affine&m=perspective&p=-5,0;1,2;3,2;4,0');
  await expect(page.getByText(/beyond the vanishing line/).first()).toBeVisible();

  // (0,0), (1.5,3), (2.5,−1), (4,2) is point-symmetric about (2, 1): its inflection is at t = ½.
  await page.getByRole('button', { name: '8 Inflection' }).click();
  await expect(page.getByText(/^Inflection at t = 0\.5000/)).toBeVisible();
  await page.getByRole('button', { name: '8 Self-intersection' }).click();
  await expect(page.getByText(/crosses itself: a loop/)).toBeVisible();
  await page.goto('./#/bezier-properties?x=cubic&p=0,0;1,1;2,2;3,3');
  await expect(page.getByText(/All four control points lie on one line/)).toBeVisible();

  await page.goto('./#/bezier-properties?x=hermite&p=0,0;1,1;2,0;3,1;4,0');
  await expect(
    page.getByRole('status').getByText(/about cubics, which have 4 control points, not 5/),
  ).toBeVisible();
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
  await expect(page.getByText(/largest distance between them over 201 samples/)).toBeVisible();
});

test('subdivision steps split every piece and the polygons close in', async ({ page }) => {
  await page.getByRole('button', { name: '6 Subdivision' }).click();
  await expect(status(page)).toContainText('Step 0/6');
  await page.getByRole('button', { name: 'Split every piece' }).click();
  await expect(status(page)).toContainText('1 split at t: 2 pieces');
  await page.getByRole('button', { name: 'Split every piece' }).click();
  await page.getByRole('button', { name: 'Split every piece' }).click();
  await expect(status(page)).toContainText('3 splits at t: 8 pieces');
  const rows = page.getByRole('table', { name: 'Subdivision levels' }).locator('tbody tr');
  await expect(rows).toHaveCount(4);
  const gaps = (await rows.locator('td:last-child').allInnerTexts()).map(Number);
  for (let j = 1; j < gaps.length; j++) expect(gaps[j]).toBeLessThan(gaps[j - 1] / 3);
});
