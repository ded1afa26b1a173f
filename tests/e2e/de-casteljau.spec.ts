import type { Page } from '@playwright/test';
import { expect, expectHash, hashState, snapshot, test } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="construction"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());

test.beforeEach(async ({ page }) => {
  await page.goto('./#/de-casteljau');
  await expect(figure(page)).toBeVisible();
});

test('dragging a control point with the mouse changes the curve and the link', async ({ page }) => {
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
  const before = await pixels(page);
  // P1 is announced with its coordinates; find where it is drawn.
  const p1 = page.getByRole('button', { name: /^P1 at \(1\.00, 2\.00\)/ });
  const box = (await p1.boundingBox())!;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 40, y + 60, { steps: 5 });
  await page.mouse.up();
  await expectHash(page, 'p', (v) => v.split(';')[1] !== '1,2');
  const p = hashState(page).p.split(';');
  expect(p[0]).toBe('0,0');
  expect(Number(p[1].split(',')[0])).toBeGreaterThan(1);
  expect(Number(p[1].split(',')[1])).toBeLessThan(2);
  expect(await pixels(page)).not.toBe(before);
  await snapshot(page, 'de-casteljau-dragged');
  // One drag is one undo step.
  await page.keyboard.press('Control+z');
  await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
});

test('a focused point moves with the arrow keys, with big and fine steps', async ({ page }) => {
  const before = await pixels(page);
  const p2 = page.getByRole('button', { name: /^P2 at/ });
  await p2.focus();
  await page.keyboard.press('ArrowUp');
  await expectHash(page, 'p', (v) => v.split(';')[2] !== '3,2');
  const y1 = Number(hashState(page).p.split(';')[2].split(',')[1]);
  expect(y1).toBeGreaterThan(2);
  await page.keyboard.press('Shift+ArrowRight');
  // Shift moves ten steps along x, and y keeps its value.
  await expectHash(page, 'p', (v) => v.split(';')[2] === `3.5,${y1}`);
  await expect(page.getByRole('button', { name: /^P2 at \(/ })).toBeFocused();
  expect(await pixels(page)).not.toBe(before);
  // The table follows the point (row P0,2 is P2).
  const x = hashState(page).p.split(';')[2].split(',')[0];
  await expect(page.getByRole('row', { name: /^P0,2 / })).toContainText(Number(x).toFixed(4));
});

test('stepping forward and back changes the level shown and the table', async ({ page }) => {
  await page.keyboard.press('Home');
  await expect(page.getByText('Level 0 of 3', { exact: true })).toBeVisible();
  await expectHash(page, 'step', (v) => v === '0');
  await expect(page.getByRole('row', { name: /^P1,0 / })).toContainText('—');
  const level0 = await pixels(page);
  await page.getByRole('button', { name: 'Step forward' }).click();
  await expect(page.getByText('Level 1 of 3', { exact: true })).toBeVisible();
  await expect(page.getByRole('heading', { name: 'Step 1 of 3: level 1' })).toBeVisible();
  // P1,0 = 0.6·P0 + 0.4·P1 = (0.4, 0.8) at t = 0.4.
  await expect(page.getByRole('row', { name: /^P1,0 / })).toContainText('0.4000');
  await expect(page.getByRole('row', { name: /^P1,0 / })).toContainText('0.8000');
  await expect(page.getByRole('row', { name: /^P2,0 / })).toContainText('—');
  expect(await pixels(page)).not.toBe(level0);
  // A presentation clicker sends PageDown / PageUp.
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await expect(page.getByText('Level 3 of 3: P(t)')).toBeVisible();
  // P(0.4) of the lecture cubic = (1.552, 1.44).
  await expect(page.getByRole('row', { name: /^P3,0 / })).toContainText('1.5520');
  await expect(page.getByRole('row', { name: /^P3,0 / })).toContainText('1.4400');
  await expect(page.getByRole('button', { name: 'Step forward' })).toBeDisabled();
  await page.keyboard.press('PageUp');
  await expect(page.getByText('Level 2 of 3', { exact: true })).toBeVisible();
  await expect(page.getByRole('row', { name: /^P3,0 / })).toContainText('—');
  await snapshot(page, 'de-casteljau-level-2');
});

test('the slider and the number field move t', async ({ page }) => {
  const slider = page.getByRole('slider', { name: 't' });
  await slider.focus();
  await page.keyboard.press('ArrowRight');
  await expectHash(page, 't', (v) => v === '0.41');
  await slider.fill('0.75');
  await expectHash(page, 't', (v) => v === '0.75');
  await expect(page.getByRole('row', { name: /^P3,0 / })).toContainText(
    // P(0.75) = 1/64·P0 + 9/64·P1 + 27/64·P2 + 27/64·P3 → x = (9 + 81 + 108)/64
    (198 / 64).toFixed(4),
  );
  const number = page.getByRole('spinbutton', { name: 't value' });
  await number.fill('0.25');
  await number.press('Enter');
  await expectHash(page, 't', (v) => v === '0.25');
  await expect(slider).toHaveValue('0.25');
});

test('subdivision shows the two control polygons at t', async ({ page }) => {
  await page.getByLabel(/Show subdivision at t/).check();
  await expectHash(page, 'split', (v) => v === '1');
  await expect(page.getByText(/Left half \(t from 0 to 0.4\)/)).toBeVisible();
  await expect(page.getByText(/Right half \(t from 0.4 to 1\)/)).toBeVisible();
  await snapshot(page, 'de-casteljau-subdivision');
});

test('reloading the copied link restores the exact state', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.getByRole('button', { name: 'Degree 5' }).click();
  await page.getByRole('slider', { name: 't' }).fill('0.63');
  // The clicker's keys step the construction even while the slider has focus.
  await page.keyboard.press('PageUp');
  await page.keyboard.press('PageUp');
  await page.keyboard.press('PageUp');
  await expect(page.getByText('Level 2 of 5', { exact: true })).toBeVisible();
  await expect(page.getByRole('slider', { name: 't' })).toHaveValue('0.63');
  await page.getByLabel(/Show subdivision at t/).check();
  await page.getByRole('button', { name: 'Copy link' }).click();
  await expect(page.getByText('Link copied.')).toBeVisible();
  const link = await page.evaluate(() => navigator.clipboard.readText());
  expect(link).toBe(page.url());
  const table = await page.getByRole('table', { name: 'Constructed points' }).innerText();

  // A fresh visitor (no local storage) opening the link sees the same thing.
  const other = await context.newPage();
  await other.goto(link);
  await expect(other.getByText('Level 2 of 5', { exact: true })).toBeVisible();
  expect(await other.getByRole('table', { name: 'Constructed points' }).innerText()).toBe(table);
  await expect(other.getByLabel(/Show subdivision at t/)).toBeChecked();
  await expect(other.getByRole('slider', { name: 't' })).toHaveValue('0.63');
  await other.close();
});

test('the last state is restored from local storage when the link has none', async ({
  page,
  context,
}) => {
  await page.getByRole('button', { name: 'Quadratic' }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 3);
  // A later visit on this device, by a bare link, in a page of its own.
  const later = await context.newPage();
  await later.goto('./#/de-casteljau');
  await expectHash(later, 'p', (v) => v === '0,0;2,3;4,0');
  // The same bare link typed over the open lesson keeps what is on screen.
  await page.goto('./#/');
  await page.goto('./#/de-casteljau');
  await expectHash(page, 'p', (v) => v === '0,0;2,3;4,0');
  await later.close();
});

const hostile = [
  ['script tags', 'p=<script>alert(1)</script>&t=0.5'],
  ['NaN', 'p=NaN,1;2,3&t=NaN'],
  ['huge numbers', 'p=1e99,0;1,1;2,2&t=1e99'],
  ['too many points', `p=${Array.from({ length: 100000 }, (_, i) => `${i},0`).join(';')}`],
  ['garbage', 'p=%E0%A4%A&&&==;;,,&step=-3&split=maybe&zzz=1'],
] as const;

for (const [name, query] of hostile) {
  test(`a hostile link (${name}) shows a notice and the defaults`, async ({ page, watch }) => {
    await page.goto(`./#/de-casteljau?${query}`);
    await expect(
      page
        .getByRole('status')
        .getByText(/Ignored from the link/)
        .first(),
    ).toBeVisible();
    await expectHash(page, 'p', (v) => v === '0,0;1,2;3,2;4,0');
    await expect(page.getByRole('row', { name: /^P0,1 / })).toContainText('1.0000');
    expect(await page.locator('script:not([src])').count()).toBe(0);
    expect(watch.errors).toEqual([]);
  });
}

test('valid parts of a damaged link are kept', async ({ page }) => {
  await page.goto('./#/de-casteljau?p=0,0;2,2;4,0&t=oops&step=1');
  await expect(page.getByRole('status').getByText(/t: "oops" is not a number/)).toBeVisible();
  await expectHash(page, 'p', (v) => v === '0,0;2,2;4,0');
  await expect(page.getByText('Level 1 of 2', { exact: true })).toBeVisible();
});

test('points can be added and removed, and undo brings them back', async ({ page }) => {
  await page.getByRole('button', { name: 'Add a control point' }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 5);
  const p4 = page.getByRole('button', { name: /^P4 at/ });
  await p4.focus();
  await page.keyboard.press('Delete');
  await expectHash(page, 'p', (v) => v.split(';').length === 4);
  // Double-click on empty space adds a point there.
  const box = (await figure(page).boundingBox())!;
  await page.mouse.dblclick(box.x + box.width / 2, box.y + box.height - 30);
  await expectHash(page, 'p', (v) => v.split(';').length === 5);
  await page.keyboard.press('Control+z');
  await expectHash(page, 'p', (v) => v.split(';').length === 4);
  await page.keyboard.press('Control+Shift+z');
  await expectHash(page, 'p', (v) => v.split(';').length === 5);
});

test('normal and projector screenshots', async ({ page }) => {
  await page.keyboard.press('Home');
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await snapshot(page, 'de-casteljau-normal');
  await page.keyboard.press('p');
  await snapshot(page, 'de-casteljau-projector-step2');
});
