import type { Page } from '@playwright/test';
import { bezierArcLength, bezierCurvature, catmullRomSegments } from '../../src/math';
import { expect, expectHash, settled, snapshot, test, linkState } from './fixtures';

const figure = (page: Page, id: string) => page.locator(`canvas[data-figure="${id}"]`);
/** A row of the panel's table as a number: the cell shows four decimals, the row keeps the whole number. */
const value = async (page: Page, quantity: string) =>
  Number(
    await page
      .getByRole('table', { name: 'Values at t' })
      .locator(`tr[data-quantity="${quantity}"]`)
      .getAttribute('data-value'),
  );
const controlPoints = async (page: Page) =>
  (await linkState(page)).p.split(';').map((p) => p.split(',').map(Number));

test.beforeEach(async ({ page }) => {
  await page.goto('./#/curvature?step=4&t=0.3');
  await expect(figure(page, 'curve')).toBeVisible();
});

test('the osculating circle has radius 1/|κ|, κ as bezierCurvature gives it, after a drag too', async ({
  page,
}) => {
  const check = async () => {
    const t = Number((await linkState(page)).t);
    const kappa = bezierCurvature(await controlPoints(page), t);
    await expect.poll(() => value(page, 'κ')).toBeCloseTo(kappa, 10);
    await expect.poll(() => value(page, 'R = 1/|κ|')).toBeCloseTo(1 / Math.abs(kappa), 10);
  };
  await check();
  // P2 moved from the keyboard, and t moved with the slider's field.
  await page.getByRole('button', { name: /^P2 at/ }).focus();
  await page.keyboard.press('ArrowUp');
  await expectHash(page, 'p', (v) => v.split(';')[2] !== '3,2');
  await page.getByRole('spinbutton', { name: 't value' }).fill('0.7');
  await page.keyboard.press('Enter');
  await expectHash(page, 't', (v) => v === '0.7');
  await check();
  await snapshot(page, 'curvature-osculating-circle');
});

test('on the helix the page shows κ and τ equal to a/(a² + b²) and b/(a² + b²)', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'The Frenet frame of a helix' }).click();
  await expectHash(page, 'part', (v) => v === 'space');
  const check = async () => {
    const { a, b } = await linkState(page);
    const [ra, rb] = [Number(a), Number(b)];
    await expect.poll(() => value(page, 'κ')).toBeCloseTo(ra / (ra * ra + rb * rb), 9);
    await expect.poll(() => value(page, 'τ')).toBeCloseTo(rb / (ra * ra + rb * rb), 9);
  };
  await check();
  await page.getByRole('spinbutton', { name: 'Helix radius a' }).fill('2');
  await page.keyboard.press('Enter');
  await expectHash(page, 'a', (v) => v === '2');
  await check();
});

test('beside the curvature vector K = dT/ds the page says, kindly, that the continuation notes write T′(t)', async ({
  page,
}) => {
  const slip = page.getByRole('note').filter({ hasText: 'The continuation notes' });
  await expect(slip).toContainText('K(T) ≔ T′(t)');
  await expect(slip).toContainText('K(t) = dT/ds');
  // The arc length part has no curvature vector, and no note about it.
  await page.getByRole('button', { name: 'Arc length against parameter' }).click();
  await expect(slip).toBeHidden();
});

test('at a cusp and at an inflection the page says why N is undefined', async ({ page }) => {
  await page.getByRole('button', { name: 'A cusp: speed 0' }).click();
  await page.keyboard.press('End');
  await expect(page.getByRole('status').filter({ hasText: 'Cusp: P′(t) = 0' })).toBeVisible();
  await expect(
    page.getByRole('table', { name: 'Values at t' }).locator('tr[data-quantity="N"]'),
  ).toContainText('undefined');
  await page.getByRole('button', { name: 'An inflection: κ = 0' }).click();
  await page.keyboard.press('End');
  await expect(page.getByRole('status').filter({ hasText: 'Inflection: κ = 0' })).toBeVisible();
});

test('equal steps of arc length: the table’s t(sᵢ) give s = iL/n', async ({ page }) => {
  await page.getByRole('button', { name: 'Arc length against parameter' }).click();
  await expectHash(page, 'part', (v) => v === 'arc');
  const table = page.getByRole('table', { name: 'Arc length table' });
  await expect(table.locator('tbody tr')).toHaveCount(9);
  const p = await controlPoints(page);
  const length = bezierArcLength(p);
  for (const i of [1, 4, 7]) {
    const row = table.locator(`tr[data-quantity="row ${i}"]`);
    const cells = row.locator('td');
    // Column 3 is s(tᵢ) at tᵢ = i/8; column 5 is t(sᵢ) with sᵢ = iL/8: shown to four
    // decimals, the whole numbers kept in the row's data-s and data-equal-t.
    const s = Number(await row.getAttribute('data-s'));
    expect(s).toBeCloseTo(bezierArcLength(p, i / 8), 9);
    expect(Number(await cells.nth(2).textContent())).toBeCloseTo(s, 4);
    const t = Number(await row.getAttribute('data-equal-t'));
    expect(bezierArcLength(p, t)).toBeCloseTo((i * length) / 8, 9);
    expect(Number(await cells.nth(4).textContent())).toBeCloseTo(t, 4);
  }
});

test('every scene in presenter view, stepped by the clicker; the space view from two angles', async ({
  page,
}) => {
  await page.keyboard.press('p');
  const scenes = ['plane', 'inflection', 'cusp', 'helix', 'twisted', 'arc'];
  for (const [i, id] of scenes.entries()) {
    if (i > 0) {
      // After a scene's last step the clicker opens the next scene at its first step.
      await page.keyboard.press('PageDown');
      await expectHash(page, 'scene', (v) => v === id);
      await expectHash(page, 'step', (v) => v === '0');
    }
    await page.keyboard.press('End');
    await expectHash(page, 'step', (v) => Number(v) >= 5);
    await snapshot(page, `curvature-presenter-${id}`);
    if (id === 'twisted') {
      const before = (await linkState(page))['view.space'] ?? '';
      await page.keyboard.press(']');
      await page.keyboard.press('}');
      await expectHash(page, 'view.space', (v) => v !== '' && v !== before);
      await snapshot(page, 'curvature-presenter-twisted-turned');
    }
  }
});

test('a de Casteljau curve opens here through its link: the same control points, and κ at the cursor as bezierCurvature gives it', async ({
  page,
}) => {
  // A quartic: the link carries any degree.
  const p = [
    [0, 0],
    [1, 3],
    [3, 3.5],
    [5, 1],
    [6, 2.5],
  ];
  await page.goto(`./#/de-casteljau?p=${p.map((q) => q.join(',')).join(';')}&t=0.35`);
  await settled(page);
  await page.getByRole('link', { name: 'Curvature of this curve →' }).click();
  await expect(page).toHaveURL(/#\/curvature\?/);
  await settled(page);
  expect((await linkState(page)).src).toBe('bezier');
  expect(await controlPoints(page)).toEqual(p);
  // Each handle names its place, two decimals: "P3 at (5.00, 1.00)".
  for (const [i, q] of p.entries())
    await expect(
      page.getByRole('button', { name: `P${i} at (${q[0].toFixed(2)}, ${q[1].toFixed(2)})` }),
    ).toBeVisible();
  await expect.poll(() => value(page, 't')).toBe(0.35);
  await expect.poll(() => value(page, 'κ')).toBeCloseTo(bezierCurvature(p, 0.35), 10);
  // Moving the cursor keeps the page on the curve of the link.
  await page.getByRole('spinbutton', { name: 't value' }).fill('0.8');
  await page.keyboard.press('Enter');
  await expectHash(page, 't', (v) => v === '0.8');
  await expect.poll(() => value(page, 'κ')).toBeCloseTo(bezierCurvature(p, 0.8), 10);
});

test('a point dragged with the mouse, then the link: the curvature lesson opens on the points as they were let go', async ({
  page,
}) => {
  await page.goto('./#/de-casteljau');
  await settled(page);
  const before = (await linkState(page)).p;
  const handle = page.getByRole('button', { name: /^P2 at/ });
  const box = (await handle.boundingBox())!;
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x - 120, y + 70, { steps: 8 });
  await page.mouse.up();
  // The link carries the points the de Casteljau page's own link holds after the drag.
  await expectHash(page, 'p', (v) => v !== before);
  const dragged = (await linkState(page)).p;
  await page.getByRole('link', { name: 'Curvature of this curve →' }).click();
  await expect(page).toHaveURL(/#\/curvature\?/);
  await settled(page);
  expect((await linkState(page)).p).toBe(dragged);
});

test('a Catmull-Rom spline: κ on the piece under the cursor, and its joins named C¹', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'A Catmull-Rom spline: κ jumps at its C¹ joins' }).click();
  await expectHash(page, 'src', (v) => v === 'catmull-rom');
  const p = await controlPoints(page);
  const segments = catmullRomSegments(p, 0);
  const t = Number((await linkState(page)).t);
  // Global s = pieces·t: piece i = ⌊s⌋, local u = s − i.
  const s = segments.length * t;
  const i = Math.min(Math.floor(s), segments.length - 1);
  await expect.poll(() => value(page, 'κ')).toBeCloseTo(bezierCurvature(segments[i], s - i), 10);
  await expect(page.getByText(`${segments.length} pieces, joined at the dots`)).toBeVisible();
  await page.keyboard.press('End');
  await expectHash(page, 'step', (v) => Number(v) >= 5);
  await snapshot(page, 'curvature-catmull-rom-joins');
});
