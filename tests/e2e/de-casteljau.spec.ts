import type { Page } from '@playwright/test';
import { expect, expectHash, snapshot, test, linkState } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="construction"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());
/** The step status under the figure: "Step k/count: caption". */
const status = (page: Page) => page.getByText(/^Step \d+\/\d+: /);
const row = (page: Page, name: string) =>
  page
    .getByRole('table', { name: 'Constructed points' })
    .getByRole('row', { name: new RegExp(`^${name} `) });

test.beforeEach(async ({ page }) => {
  await page.goto('./#/de-casteljau');
  await expect(figure(page)).toBeVisible();
});

test('a point is dragged, added and removed, and undo brings each back', async ({ page }) => {
  // The whole construction (the lesson opens at step 0, #19).
  await page.goto('./#/de-casteljau?step=5');
  await expect(figure(page)).toBeVisible();
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
  const before = await pixels(page);
  const box = (await page.getByRole('button', { name: /^P1 at \(1\.00, 2\.00\)/ }).boundingBox())!;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 40, y + 60, { steps: 5 });
  await page.mouse.up();
  await expectHash(page, 'p', (v) => v.split(';')[1] !== '1,2');
  const [p0, p1] = (await linkState(page)).p.split(';');
  expect(p0).toBe('0,0');
  expect(Number(p1.split(',')[0])).toBeGreaterThan(1);
  expect(Number(p1.split(',')[1])).toBeLessThan(2);
  expect(await pixels(page)).not.toBe(before);
  // One drag is one undo step.
  await page.keyboard.press('Control+z');
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');

  await page.getByRole('button', { name: 'Add a control point' }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 5);
  // Shown to its end, the construction stays at its end: degree 4 has 6 steps.
  await expectHash(page, 'step', (v) => v === '6');
  await page.getByRole('button', { name: /^P4 at/ }).focus();
  await page.keyboard.press('Delete');
  await expectHash(page, 'p', (v) => v.split(';').length === 4);
  await page.keyboard.press('Control+z');
  await expectHash(page, 'p', (v) => v.split(';').length === 5);
});

test('the clicker builds the construction from the points up, then opens the next scene', async ({
  page,
}) => {
  await page.keyboard.press('Home');
  await expect(status(page)).toHaveText(
    'Step 0/5: The 4 control points P₀ … P₃, and nothing else yet',
  );
  await expect(row(page, 'P₁,₀')).toContainText('—');
  const points = await pixels(page);
  await page.keyboard.press('PageDown');
  await expect(status(page)).toHaveText(
    'Step 1/5: Join them in order: the control polygon, level 0',
  );
  expect(await pixels(page)).not.toBe(points);
  await page.keyboard.press('PageDown');
  await expect(status(page)).toContainText('Step 2/5: Level 1:');
  // P1,0 = 0.4·P0 + 0.6·P1 = (0.6, 1.2) at t = 0.6 (Figure 5's).
  await expect(row(page, 'P₁,₀')).toContainText('0.6000');
  await expect(row(page, 'P₁,₀')).toContainText('1.2000');
  await expect(row(page, 'P₂,₀')).toContainText('—');
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await expect(status(page)).toContainText('Step 4/5: Level 3: one point is left');
  // P(0.6) = 0.064·P0 + 0.288·P1 + 0.432·P2 + 0.216·P3 = (2.448, 1.44).
  await expect(row(page, 'P₃,₀')).toContainText('2.4480');
  await expect(row(page, 'P₃,₀')).toContainText('1.4400');
  await page.keyboard.press('PageDown');
  await expect(status(page)).toContainText('traces the Bézier curve');
  await snapshot(page, 'de-casteljau-traced');
  // Past the last step: the next scene, at its first step.
  await page.keyboard.press('PageDown');
  await expectHash(page, 'p', (v) => v === '0,0;2,3;4,0');
  await expect(status(page)).toHaveText(
    'Step 0/4: The 3 control points P₀ … P₂, and nothing else yet',
  );
  await page.keyboard.press('PageUp');
  await expect(status(page)).toContainText('Step 5/5');
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
});

test('the slider and the number field move t', async ({ page }) => {
  await page.goto('./#/de-casteljau?step=5');
  await expect(figure(page)).toBeVisible();
  const slider = page.getByRole('slider', { name: 't' });
  await slider.focus();
  await page.keyboard.press('ArrowRight');
  await expectHash(page, 't', (v) => v === '0.61');
  await slider.fill('0.75');
  await expectHash(page, 't', (v) => v === '0.75');
  // P(0.75) = 1/64·P0 + 9/64·P1 + 27/64·P2 + 27/64·P3 → x = (9 + 81 + 108)/64
  await expect(row(page, 'P₃,₀')).toContainText((198 / 64).toFixed(4));
  const number = page.getByRole('spinbutton', { name: 't value' });
  await number.fill('0.25');
  await number.press('Enter');
  await expectHash(page, 't', (v) => v === '0.25');
  await expect(slider).toHaveValue('0.25');
});

test('subdivision lists both halves legibly, even for many points', async ({ page }) => {
  await page.getByLabel(/Show subdivision at t/).check();
  await expectHash(page, 'split', (v) => v === '1');
  const halves = page.getByRole('table', { name: 'Control points of the two halves' });
  // At t = 0.6: P1,0 = (0.6, 1.2), P1,1 = 0.4·(1, 2) + 0.6·(3, 2) = (2.2, 2), and
  // P2,0 = 0.4·(0.6, 1.2) + 0.6·(2.2, 2) = (1.56, 1.68), the left half's third point.
  await expect(halves.getByRole('row', { name: /^Left P₂,₀ / })).toContainText('1.5600');
  await expect(halves.getByRole('row', { name: /^Left P₂,₀ / })).toContainText('1.6800');
  // Its right half ends at P3: (4, 0), named P0,3.
  await expect(halves.getByRole('row', { name: /^Right P₀,₃ / })).toContainText('4.0000');
  for (let i = 0; i < 6; i++)
    await page.getByRole('button', { name: 'Add a control point' }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 10);
  await expect(halves.getByRole('row')).toHaveCount(1 + 2 * 10);
  const size = await halves
    .getByRole('row', { name: /^Right P₀,₉ / })
    .evaluate((r) => parseFloat(getComputedStyle(r).fontSize));
  expect(size).toBeGreaterThanOrEqual(12);
  await snapshot(page, 'de-casteljau-subdivision');
});

test('a copied link opens the same scene, step and subdivision', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.getByRole('button', { name: 'Degree 5' }).click();
  await page.getByRole('slider', { name: 't' }).fill('0.63');
  // The clicker's keys step the construction even while the slider has focus.
  for (let i = 0; i < 4; i++) await page.keyboard.press('PageDown');
  await expect(status(page)).toContainText('Step 4/7: Level 3:');
  await expect(page.getByRole('slider', { name: 't' })).toHaveValue('0.63');
  await page.getByLabel(/Show subdivision at t/).check();
  await page.getByRole('button', { name: 'Copy link' }).click();
  await expect(page.getByText('Link copied.')).toBeVisible();
  const link = await page.evaluate(() => navigator.clipboard.readText());
  expect(link).toBe(page.url());
  const table = await page.getByRole('table', { name: 'Constructed points' }).innerText();
  const other = await context.newPage();
  await other.goto(link);
  await expect(status(other)).toContainText('Step 4/7: Level 3:');
  expect(await other.getByRole('table', { name: 'Constructed points' }).innerText()).toBe(table);
  await expect(other.getByLabel(/Show subdivision at t/)).toBeChecked();
  await other.close();
});

test('hostile and degenerate links are explained, never obeyed', async ({ page, watch }) => {
  const hostile = [
    'p=<script>alert(1)</script>&t=0.5',
    'p=NaN,1;2,3&t=NaN',
    `p=${Array.from({ length: 100000 }, (_, i) => `${i},0`).join(';')}`,
    'p=%E0%A4%A&&&==;;,,&step=-3&split=maybe&zzz=1',
  ];
  for (const query of hostile) {
    await page.goto(`./#/de-casteljau?${query}`);
    await expect(
      page
        .getByRole('status')
        .getByText(/Ignored from the link/)
        .first(),
    ).toBeVisible();
    await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
    expect(await page.locator('script:not([src])').count()).toBe(0);
  }
  expect(watch.errors).toEqual([]);
  // Three points on one spot: drawn, and said in words.
  await page.goto('./#/de-casteljau?p=1,1;1,1;1,1&step=3');
  await expect(
    page.getByRole('note').getByText(/All control points are on one spot/),
  ).toBeVisible();
  await page.goto('./#/de-casteljau?p=0,0;1,1;3,3&step=3');
  await expect(page.getByRole('note').getByText(/lie on one line/)).toBeVisible();
});
