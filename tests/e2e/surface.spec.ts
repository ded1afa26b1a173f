import type { Page } from '@playwright/test';
import { bezierSurfacePoint } from '../../src/math';
import { expect, expectHash, settled, snapshot, test, linkState } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="patch"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());

/** The control net from the link: `x=` holds 16 points "x,y,z" row by row. */
function netOf(x: string): number[][][] {
  const flat = x.split(';').map((p) => p.split(',').map(Number));
  return [0, 1, 2, 3].map((m) => flat.slice(4 * m, 4 * m + 4));
}
const netFromLink = async (page: Page) => netOf((await linkState(page)).x);

/**
 * A row of the "three ways" table, read from the page: [x, y, z], exact from
 * the row's data-exact, and the written digits (six) checked against it.
 */
async function readPoint(page: Page, name: RegExp): Promise<number[]> {
  const row = page
    .getByRole('table', { name: 'The point P(u, v) three ways' })
    .getByRole('row', { name });
  const exact = ((await row.getAttribute('data-exact')) ?? '').split(',').map(Number);
  const written = (await row.locator('td').allTextContents()).slice(1).map(Number);
  return written.length === 3 && written.every((w, d) => Math.abs(w - exact[d]) <= 5e-7)
    ? exact
    : [NaN, NaN, NaN];
}

/** The point shown agrees with bezierSurfacePoint at the link's u, v and net, to 1e-9, all three ways. */
async function expectPointMatches(page: Page): Promise<void> {
  await expect
    .poll(async () => {
      const state = await linkState(page);
      const expected = bezierSurfacePoint(
        await netFromLink(page),
        Number(state.u),
        Number(state.v),
      );
      const rows = [/^Σ/, /^u, then v/, /^v, then u/];
      const shown = await Promise.all(rows.map((row) => readPoint(page, row)));
      return shown.every((p) => p.every((value, d) => Math.abs(value - expected[d]) <= 1e-9));
    })
    .toBe(true);
}

test.beforeEach(async ({ page }) => {
  await page.goto('./#/surface');
  await expect(figure(page)).toBeVisible();
});

test('u, v and the camera: the point read from the page is P(u, v), three ways, and the weights sum to 1', async ({
  page,
}) => {
  await expectPointMatches(page);
  await page.getByRole('slider', { name: 'u' }).fill('0.73');
  await expectHash(page, 'u', (value) => value === '0.73');
  await expectPointMatches(page);
  await page.getByRole('spinbutton', { name: 'v value' }).fill('0.19');
  await page.getByRole('spinbutton', { name: 'v value' }).press('Enter');
  await expectHash(page, 'v', (value) => value === '0.19');
  await expectPointMatches(page);
  await page.getByRole('slider', { name: 'v' }).fill('0.5');
  await expectHash(page, 'v', (value) => value === '0.5');
  await expectPointMatches(page);
  // The panel's v is written as the parameter's u is: three decimals, in the field and to a screen reader.
  await expect(page.getByRole('spinbutton', { name: 'v value' })).toHaveValue('0.500');
  await expect(page.getByRole('slider', { name: 'v' })).toHaveAttribute(
    'aria-valuetext',
    'v = 0.500',
  );
  await expect(page.getByRole('slider', { name: 'u' })).toHaveAttribute(
    'aria-valuetext',
    'u = 0.730',
  );
  const sum = page.getByRole('status', { name: 'Sum of the 16 weights' });
  await expect(sum).toHaveText('1');
  expect(Math.abs(Number(await sum.getAttribute('data-exact')) - 1)).toBeLessThanOrEqual(1e-12);

  // Orbiting turns the picture, not the point.
  const before = await pixels(page);
  await figure(page).focus();
  await page.keyboard.press(']');
  await page.keyboard.press('}');
  await expectHash(page, 'view.patch', (value) => value !== '');
  expect(await pixels(page)).not.toBe(before);
  await expectPointMatches(page);
  await snapshot(page, 'surface-orbited');
});

test('Shift-dragging a control point moves it along one axis only', async ({ page }) => {
  await page.getByRole('button', { name: 'The patch' }).click();
  const handle = page.getByRole('button', { name: /^P1,1 at/ });
  const box = (await handle.boundingBox())!;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  const before = (await netFromLink(page))[1][1];
  await page.mouse.move(x, y);
  await page.keyboard.down('Shift');
  await page.mouse.down();
  await page.mouse.move(x + 2, y - 30, { steps: 3 });
  await page.mouse.move(x + 4, y - 70, { steps: 4 });
  await page.mouse.up();
  await page.keyboard.up('Shift');
  await expectHash(page, 'x', (v) => netOf(v)[1][1][2] !== before[2]);
  const after = (await netFromLink(page))[1][1];
  // Straight up the screen is the z axis: x and y keep their values exactly.
  expect(after[0]).toBe(before[0]);
  expect(after[1]).toBe(before[1]);
  expect(after[2]).toBeGreaterThan(before[2]);
  // The table follows the link, to the three decimals of the figure's labels
  // (a dragged point has 17 digits), and the other 15 points do too.
  await expect(page.getByRole('textbox', { name: 'P1,1 (x, y, z)' })).toHaveValue(
    after.map((v) => String(Number(v.toFixed(3)))).join(', '),
  );
  await expectPointMatches(page);
});

test('a point typed into the 4 × 4 table moves the patch', async ({ page }) => {
  const before = await pixels(page);
  const cell = page.getByRole('textbox', { name: 'P2,1 (x, y, z)' });
  await cell.fill('2, 1, -1.25');
  await cell.press('Enter');
  await expectHash(page, 'x', (v) => netOf(v)[2][1].join(',') === '2,1,-1.25');
  await expect(
    page.getByRole('button', { name: /^P2,1 at \(2\.00, 1\.00, -1\.25\)/ }),
  ).toBeAttached();
  expect(await pixels(page)).not.toBe(before);
  await expectPointMatches(page);
  // Not three numbers: the cell is put back and nothing changes.
  const frame = await figure(page).boundingBox();
  await cell.fill('2, oops');
  await cell.press('Enter');
  await expect(cell).toHaveValue('2, 1, -1.25');
  await expect(
    page.getByRole('status').filter({ hasText: /^P₂,₁: type three numbers/ }),
  ).toBeVisible();
  // Said under the table, not in the page's notices, which would push the
  // figures down: the figure keeps its size, so the link shows the same picture.
  await expect(page.locator('.notice')).toHaveCount(0);
  expect(await figure(page).boundingBox()).toEqual(frame);
});

test('the clicker walks every scene from its first step to its last, in presenter view', async ({
  page,
}) => {
  const scenes = await page.getByRole('group', { name: 'Scenes' }).getByRole('button').count();
  expect(scenes).toBe(13);
  await page.keyboard.press('p');
  for (let i = 1; i <= scenes; i++) {
    await expect(page.getByText(new RegExp(`scene ${i}/${scenes}, step 0/`))).toBeVisible();
    await page.keyboard.press('End');
    await expect(page.getByText(new RegExp(`scene ${i}/${scenes}, step [1-9]/`))).toBeVisible();
    await snapshot(page, `surface-scene-${i}`);
    await page.keyboard.press('PageDown');
  }
  // After the last scene, the clicker stays on its last step.
  await expect(page.getByText(new RegExp(`scene ${scenes}/${scenes}`))).toBeVisible();
});

test('each net worth seeing opens with its own idea; a net edited away from it walks the patch’s steps', async ({
  page,
}) => {
  const caption = page.locator('.step-status');
  await page.getByRole('button', { name: 'Flat', exact: true }).click();
  await expect(caption).toContainText(
    'A flat net: all 16 points in the plane z = 0, evenly spaced',
  );
  await page.keyboard.press('End');
  await expect(caption).toContainText('Its tangents are the same everywhere, so is its normal');
  await page.getByRole('button', { name: 'Bump', exact: true }).click();
  await expect(caption).toContainText('A bump: the twelve border points at height 0');
  await page.keyboard.press('End');
  await expectHash(page, 'k', (v) => v === '5');
  // Lift a border point: no longer the bump, a patch like any other, at the same step.
  await page.getByRole('button', { name: /^P0,1 at/ }).focus();
  await page.keyboard.press('Control+ArrowUp');
  await expectHash(page, 'x', (v) => netOf(v)[0][1][2] > 0);
  await expect(caption).toContainText('The patch, and the point P(0.5, 0.5) on it');
});

test('beside the scene that builds the curve in u, the slides’ “for 0 ≤ v ≤ 1”, said kindly', async ({
  page,
}) => {
  const slip = page.getByRole('note').filter({ hasText: 'for 0 ≤ v ≤ 1' });
  await expect(slip).toBeHidden();
  await page.getByRole('button', { name: 'Choose v, then u' }).click();
  await expect(slip).toBeVisible();
  await expect(slip).toContainText('runs in u, for 0 ≤ u ≤ 1');
  await page.getByRole('button', { name: 'Matrix form' }).click();
  await expect(slip).toBeHidden();
});

test('two patches: moving a point next to the edge breaks C¹', async ({ page }) => {
  await page.getByRole('button', { name: 'Two patches, C¹' }).click();
  await page.keyboard.press('End');
  await expect(page.getByText(/collinear and equally long: C¹/).first()).toBeVisible();
  const handle = page.getByRole('button', { name: /^Q1,1 at/ });
  await handle.focus();
  await page.keyboard.press('Control+ArrowUp');
  await expect(page.getByText(/not collinear: C⁰ only/).first()).toBeVisible();
  await snapshot(page, 'surface-join-broken');
});

test('presenter view at 1920 × 1080: the patch has a frame its box fits, and the heat map a square one', async ({
  page,
}) => {
  await page.setViewportSize({ width: 1920, height: 1080 });
  await page.keyboard.press('p');
  await settled(page);
  const box = async (id: string) =>
    (await page.locator(`canvas[data-figure="${id}"]`).boundingBox())!;
  const patch = await box('patch');
  const weights = await box('weights');
  // The leaning hill's net seen from the starting camera is 4.1 wide and 4.43 tall
  // (its box's corners projected), so it takes the frame's height: a frame
  // twice as wide as tall (the 2.4 : 1 row gave 2.0 here) leaves most of it empty.
  expect(patch.width / patch.height).toBeLessThan(1.8);
  expect(weights.width / weights.height).toBeGreaterThan(0.9);
  expect(patch.width).toBeGreaterThan(weights.width);
});
