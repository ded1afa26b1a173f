import type { Page } from '@playwright/test';
import { bezierPoint, elevateDegree, type Point } from '../../src/math';
import { expect, expectHash, hashState, snapshot, test } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="experiment"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());
const pointsOf = (value: string): Point[] => value.split(';').map((q) => q.split(',').map(Number));

test.beforeEach(async ({ page }) => {
  await page.goto('./#/bezier-properties');
  await expect(figure(page)).toBeVisible();
});

test('every experiment preset draws, in normal and projector mode', async ({ page }) => {
  const ids = await page
    .locator('[data-preset]')
    .evaluateAll((els) => els.map((e) => (e as HTMLElement).dataset.preset!));
  expect(ids).toHaveLength(12);
  for (const projector of [false, true]) {
    if (projector) await page.keyboard.press('p');
    let previous = '';
    for (const id of ids) {
      await page.locator(`[data-preset="${id}"]`).click();
      await expect.poll(() => pixels(page)).not.toBe(previous);
      previous = await pixels(page);
      await expect(page.locator('.experiment-sentence')).not.toBeEmpty();
      await snapshot(page, `bezier-properties-${id}${projector ? '-projector' : ''}`);
    }
  }
});

test('raising the degree keeps the curve within 1e-9 and brings the polygon closer', async ({
  page,
}) => {
  await page.getByRole('button', { name: '5 Raise the degree' }).click();
  await expectHash(page, 'x', (v) => v === 'elevate');
  const raise = page.getByRole('button', { name: 'Raise the degree', exact: true });
  const gaps: number[] = [];
  for (let k = 1; k <= 6; k++) {
    await raise.click();
    await expectHash(page, 'k', (v) => v === String(k));
    await expect(page.locator('.experiment-details')).toHaveAttribute(
      'data-control-points',
      String(4 + k),
    );
    const deviation = Number(await page.locator('[data-deviation]').getAttribute('data-deviation'));
    expect(deviation).toBeLessThan(1e-9);
    const rows = page
      .getByRole('table', { name: 'Distance from polygon to curve' })
      .locator('tbody tr');
    await expect(rows).toHaveCount(k + 1);
    gaps.push(Number(await rows.last().locator('td').last().innerText()));
  }
  for (let j = 1; j < gaps.length; j++) expect(gaps[j]).toBeLessThan(gaps[j - 1]);
  // The same check on our own: the state in the link, elevated six times, samples the same curve.
  const p = pointsOf(hashState(page).p);
  let q: readonly Point[] = p;
  for (let j = 0; j < Number(hashState(page).k); j++) q = elevateDegree(q);
  expect(q).toHaveLength(10);
  for (let s = 0; s <= 200; s++) {
    const a = bezierPoint(p, s / 200);
    const b = bezierPoint(q, s / 200);
    expect(Math.hypot(a[0] - b[0], a[1] - b[1])).toBeLessThan(1e-9);
  }
  await snapshot(page, 'bezier-properties-elevated-6');
  // A clicker steps the elevation too, and the count survives a reload of the link.
  await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '7');
  await page.reload();
  await expect(page.getByText('Degree 3 → 10')).toBeVisible();
  await expect(page.locator('.experiment-details')).toHaveAttribute('data-control-points', '11');
});

test('moving an inner point of twelve barely moves the curve, and "before" survives the link', async ({
  page,
}) => {
  await page.getByRole('button', { name: '3 No local control' }).click();
  await expect(
    page.getByText(/P5 moved by 2\.000, the curve by at most 23\.6% of that/),
  ).toBeVisible();
  // The link is written shortly after a change: wait for the preset's "before" to be in it.
  await expectHash(page, 'q', (v) => v.split(';').length === 12);
  const before = hashState(page).q;
  const p5 = page.getByRole('button', { name: /^P5 at/ });
  await p5.focus();
  await page.keyboard.press('Shift+ArrowUp');
  await expectHash(page, 'p', (v) => pointsOf(v)[5][1] > pointsOf(before)[5][1] + 2);
  expect(hashState(page).q).toBe(before);
  const text = await page.getByText(/Largest displacement of the curve/).innerText();
  const largest = Number(/curve: ([\d.]+)/.exec(text)![1]);
  const moved = pointsOf(hashState(page).p)[5][1] - pointsOf(before)[5][1];
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

test('an affine map commutes with the curve, a perspective map does not', async ({ page }) => {
  await page.getByRole('button', { name: '7 Affine map' }).click();
  await expect(page.getByText(/they agree, up to rounding/)).toBeVisible();
  for (const map of ['Rotation', 'Scaling']) {
    await page.getByLabel(map).check();
    const d = Number(await page.locator('[data-map-deviation]').getAttribute('data-map-deviation'));
    expect(d).toBeLessThan(1e-9);
  }
  await page.getByRole('button', { name: '7 Perspective map' }).click();
  await expectHash(page, 'm', (v) => v === 'perspective');
  await expect(page.getByText(/they differ/)).toBeVisible();
  const d = Number(await page.locator('[data-map-deviation]').getAttribute('data-map-deviation'));
  expect(d).toBeGreaterThan(0.1);
  const rational = Number(
    await page.locator('[data-rational-deviation]').getAttribute('data-rational-deviation'),
  );
  expect(rational).toBeLessThan(1e-9);
  // A point dragged behind the vanishing line: no image, and a sentence why.
  await page.goto('./#/bezier-properties?x=affine&m=perspective&p=-5,0;1,2;3,2;4,0');
  await expect(page.getByText(/beyond the vanishing line/).first()).toBeVisible();
});

test('inflection and self-intersection presets find them', async ({ page }) => {
  await page.getByRole('button', { name: '8 Inflection' }).click();
  await expect(page.getByText(/^Inflection at t = 0\.5000/)).toBeVisible();
  await expect(page.getByText('No self-intersection on [0, 1].')).toBeVisible();
  await page.getByRole('button', { name: '8 Self-intersection' }).click();
  await expect(
    page.getByText('No inflection on [0, 1]: the curve turns one way only.'),
  ).toBeVisible();
  await expect(page.getByText(/crosses itself: a loop/)).toBeVisible();
  await page.goto('./#/bezier-properties?x=cubic&p=0,0;1,1;2,2;3,3');
  await expect(page.getByText(/All four control points lie on one line/)).toBeVisible();
});

test('a cubic experiment given five points says why it shows the lecture cubic', async ({
  page,
}) => {
  await page.goto('./#/bezier-properties?x=hermite&p=0,0;1,1;2,0;3,1;4,0');
  await expect(
    page.getByRole('status').getByText(/about cubics, which have 4 control points, not 5/),
  ).toBeVisible();
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
  await expect(page.getByText(/largest distance between them over 201 samples/)).toBeVisible();
});

test('subdivision steps split every piece and the polygons close in', async ({ page }) => {
  await page.getByRole('button', { name: '6 Subdivision' }).click();
  await expect(page.getByText('1 split: 2 pieces')).toBeVisible();
  await page.getByRole('button', { name: 'Split every piece' }).click();
  await page.getByRole('button', { name: 'Split every piece' }).click();
  await expect(page.getByText('3 splits: 8 pieces')).toBeVisible();
  const rows = page.getByRole('table', { name: 'Subdivision levels' }).locator('tbody tr');
  const gaps = (await rows.locator('td:last-child').allInnerTexts()).map(Number);
  expect(gaps).toHaveLength(4);
  for (let j = 1; j < gaps.length; j++) expect(gaps[j]).toBeLessThan(gaps[j - 1] / 3);
});
