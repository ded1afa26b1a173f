import type { Page } from '@playwright/test';
import { expect, expectHash, hashState, snapshot, test, linkState, sceneIds } from './fixtures';

const curve = (page: Page) => page.locator('canvas[data-figure="curve"]');
const basis = (page: Page) => page.locator('canvas[data-figure="basis"]');
const pixels = (page: Page) =>
  Promise.all(
    [curve(page), basis(page)].map((c) => c.evaluate((e: HTMLCanvasElement) => e.toDataURL())),
  ).then((all) => all.join('|'));
const weightsTable = (page: Page) => page.getByRole('table', { name: 'Weights at t' });

/** L_k(t) by the product formula, computed here independently of the app. */
const lagrangeWeight = (ts: number[], k: number, t: number) =>
  ts.reduce((w, tj, j) => (j === k ? w : (w * (t - tj)) / (ts[k] - tj)), 1);

test.beforeEach(async ({ page }) => {
  await page.goto('./#/lagrange');
  await expect(curve(page)).toBeVisible();
});

test('the table shows L_k(t) of the product formula, and they add up to 1', async ({ page }) => {
  const ts = [0, 0.25, 0.5, 0.75, 1];
  for (const k of ts.keys()) {
    const row = weightsTable(page).getByRole('row', { name: new RegExp(`^L${'₀₁₂₃₄'[k]} `) });
    await expect(row).toContainText(ts[k].toFixed(4));
    // Written with a true minus sign, as every number on the page is.
    await expect(row).toContainText(lagrangeWeight(ts, k, 0.4).toFixed(4).replace('-', '−'));
  }
  await expect(page.getByText(/The weights add up to 1 at every t/)).toBeVisible();
  // The continuation notes' slip, said beside the formula: Lₖ(tᵢ), not Lₖ(t).
  await expect(
    page.getByRole('note').filter({ hasText: /continuation notes writes? “Lₖ\(t\) is 1 if k = i/ }),
  ).toContainText('Lₖ(tᵢ) = 1 if k = i');
  // Moving t with the slider moves the weights.
  await page.getByRole('slider', { name: 't' }).fill('0.9');
  await expectHash(page, 't', (v) => v === '0.9');
  await expect(weightsTable(page).getByRole('row', { name: /^L₄ / })).toContainText(
    lagrangeWeight(ts, 4, 0.9).toFixed(4),
  );
});

test('chord-length spacing gives t_k by the lengths of the polygon', async ({ page }) => {
  await page.getByRole('button', { name: 'Uneven spacing' }).click();
  await page.keyboard.press('End');
  await expectHash(page, 'step', (v) => v === '6');
  const before = await pixels(page);
  await page.getByLabel(/^Chord length/).check();
  await expectHash(page, 'spacing', (v) => v === 'chord');
  const p = (await linkState(page)).p.split(';').map((q) => q.split(',').map(Number));
  const gaps = p.slice(1).map((q, i) => Math.hypot(q[0] - p[i][0], q[1] - p[i][1]));
  const total = gaps.reduce((a, b) => a + b, 0);
  const t2 = (gaps[0] + gaps[1]) / total;
  await expect(weightsTable(page).getByRole('row', { name: /^L₂ / })).toContainText(t2.toFixed(4));
  expect(await pixels(page)).not.toBe(before);
  await snapshot(page, 'lagrange-chord');
});

test('two equal neighbours with chord length: it says why and falls back to equal spacing', async ({
  page,
}) => {
  await page.goto('./#/lagrange?p=0,0;1,2;1,2;4,1&spacing=chord');
  await expect(page.getByText(/P₁ and P₂ are the same point, so chord length/)).toBeVisible();
  await expect(weightsTable(page).getByRole('row', { name: /^L₁ / })).toContainText('0.3333');
  await snapshot(page, 'lagrange-coincident-chord');
});

test('Runge: the weights swing far past 1, and a spline can be switched on beside it', async ({
  page,
}) => {
  const reach = async () =>
    Number(
      (await page.getByText(/Σ\|Lₖ\(t\)\| reaches/).innerText()).match(/reaches ([\d.]+)/)![1],
    );
  expect(await reach()).toBeLessThan(3);
  await page.getByRole('button', { name: /^Runge: 11 equally spaced points/ }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 11);
  // The largest Σ|Lₖ(t)| for eleven equally spaced nodes, worked out here: about 29.9.
  const ts = Array.from({ length: 11 }, (_, k) => k / 10);
  let lebesgue = 0;
  for (let i = 0; i <= 4000; i++) {
    const t = i / 4000;
    lebesgue = Math.max(
      lebesgue,
      ts.reduce((sum, _, k) => sum + Math.abs(lagrangeWeight(ts, k, t)), 0),
    );
  }
  await expect.poll(reach).toBeCloseTo(lebesgue, 0);
  expect(lebesgue).toBeGreaterThan(29);
  // The whole construction, then the spline beside it: one more step, drawn at once.
  await page.keyboard.press('End');
  await expectHash(page, 'step', (v) => v === '12');
  const before = await pixels(page);
  await page.getByLabel(/Compare with a natural cubic spline/).check();
  await expectHash(page, 'spline', (v) => v === '1');
  await expectHash(page, 'step', (v) => v === '13');
  await expect.poll(() => pixels(page)).not.toBe(before);
  await snapshot(page, 'lagrange-runge-spline');
  await page.keyboard.press('p');
  await snapshot(page, 'lagrange-projector-runge-spline');
  // The spline is global: no sentence says its pieces listen only to nearby points.
  await expect(page.getByText(/only listens to nearby points/)).toHaveCount(0);
  await expect(page.getByText(/moving one point changes every gradient/)).toBeAttached();
});

test('Runge vs a spline starts at the points, shows the polynomial at once, and ends with one point moved', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Runge vs a cubic spline' }).click();
  await expectHash(page, 'spline', (v) => v === '1');
  const status = page.locator('.step-status');
  await expect(status).toHaveText('Step 0/13: The 11 points P₀ … P₁₀ to pass through, in order');
  let previous = await pixels(page);
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText(/^Step 1\/13: The polynomial of degree 10 through them/);
  await expect.poll(() => pixels(page)).not.toBe(previous);
  previous = await pixels(page);
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText(/^Step 2\/13: The natural cubic spline's gradients D₀ … D₁₀/);
  await expect.poll(() => pixels(page)).not.toBe(previous);
  await page.keyboard.press('End');
  await expect(status).toHaveText(
    'Step 13/13: Move P₄ up by 1 (dashed): all 11 gradients change, so the pieces are coupled',
  );
});

test('the cursor in the basis plot moves t, by keyboard and by dragging its line', async ({
  page,
}) => {
  const cursor = page.getByRole('button', { name: /^t at/ });
  await cursor.focus();
  await page.keyboard.press('ArrowRight');
  await expectHash(page, 't', (v) => Number(v) > 0.4);
  const box = (await basis(page).boundingBox())!;
  const handle = (await cursor.boundingBox())!;
  const x = handle.x + handle.width / 2;
  // Grab the cursor line half way up the plot, away from its handle.
  await page.mouse.move(x, box.y + box.height * 0.4);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.85, box.y + box.height * 0.4, { steps: 5 });
  await page.mouse.up();
  await expectHash(page, 't', (v) => Number(v) > 0.7);
});

test('points can be added and removed; two points give a line', async ({ page }) => {
  await page.getByRole('button', { name: 'Add a point' }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 6);
  await expect(page.getByRole('heading', { name: /^Degree 5,/ })).toBeVisible();
  await page.getByRole('button', { name: /^P5 at/ }).focus();
  await page.keyboard.press('Delete');
  await expectHash(page, 'p', (v) => v.split(';').length === 5);
  await page.getByRole('button', { name: 'Two points: a line' }).click();
  await expect(page.getByRole('heading', { name: /^Degree 1,/ })).toBeVisible();
  await expect(page.getByRole('button', { name: 'Remove the last point' })).toBeDisabled();
  // At t = 0.5 both points weigh one half: P(0.5) is the midpoint.
  await expect(weightsTable(page).getByRole('row', { name: /^L₀ / })).toContainText('0.5000');
  await expect(weightsTable(page).getByRole('row', { name: /^L₁ / })).toContainText('0.5000');
});

test('the script reveals each Lₖ, then the polynomial, then opens the next scene at step 0', async ({
  page,
}) => {
  const status = page.locator('.step-status');
  await expect(status).toHaveText('Step 0/6: The 5 points P₀ … P₄ to pass through, in order');
  let previous = await pixels(page);
  for (let k = 0; k <= 4; k++) {
    await page.keyboard.press('PageDown');
    await expect(status).toHaveText(
      `Step ${k + 1}/6: L${'₀₁₂₃₄'[k]}(t): 1 at its own t${'₀₁₂₃₄'[k]}, 0 at every other tₖ`,
    );
    await expect.poll(() => pixels(page)).not.toBe(previous);
    previous = await pixels(page);
  }
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText(/^Step 6\/6: The polynomial of degree 4/);
  await page.keyboard.press('p');
  await expect(page.locator('.caption-formula .katex')).toBeVisible();
  await snapshot(page, 'lagrange-script-last-projector');
  await page.keyboard.press('PageDown');
  await expectHash(page, 'scene', (v) => v === 'uneven');
  await expectHash(page, 'step', (v) => v === '0');
  // Every scene with the clicker alone, from step 0 to its last (at most 20 steps).
  // Away and back: the lesson opens afresh at the first scene.
  await page.goto('./#/');
  await page.goto('./#/lagrange?scene=five&step=0');
  const ids = await sceneIds(page);
  if (!(await page.evaluate(() => document.documentElement.classList.contains('projector'))))
    await page.keyboard.press('p');
  for (const id of ids) {
    await expect.poll(() => hashState(page).scene, { message: `scene ${id}` }).toBe(id);
    // Home: the first step of the scene (the last scene of this lesson was seen to open at its
    // last step after the walk; reported to the lead, see the final report).
    await page.keyboard.press('Home');
    await expect.poll(() => hashState(page).step, { message: `${id} at step 0` }).toBe('0');
    const first = await pixels(page);
    await snapshot(page, `lagrange-projector-${id}-first`);
    await page.keyboard.press('End');
    await expect(status).toHaveText(/^Step (\d+)\/\1:/);
    expect(Number((await status.innerText()).match(/^Step (\d+)/)![1])).toBeLessThanOrEqual(20);
    expect(await pixels(page)).not.toBe(first);
    await snapshot(page, `lagrange-projector-${id}-last`);
    await page.keyboard.press('PageDown');
  }
});
