import type { Page } from '@playwright/test';
import {
  expect,
  expectHash,
  snapshot,
  test,
  linkState,
  inLecturesLetter,
  sceneIds,
} from './fixtures';

// This lesson follows the lecture notes, and its tests read its text in their letter, μ.
test.beforeEach(({ page }) => inLecturesLetter(page));

const curve = (page: Page) => page.locator('canvas[data-figure="curve"]');
const plot = (page: Page) => page.locator('canvas[data-figure="blending"]');
const pixels = (page: Page, which: 'curve' | 'blending') =>
  page.locator(`canvas[data-figure="${which}"]`).evaluate((c: HTMLCanvasElement) => c.toDataURL());

const weightRows = (page: Page) =>
  page.getByRole('table', { name: 'Weights at μ', exact: true }).locator('tbody tr');

/** The weights as listed in the table, at full precision, once the table has its `count` rows
 * (the panel is written after the figure, so a read straight after a load can find no rows). */
async function listedWeights(page: Page, count: number): Promise<number[]> {
  await expect(weightRows(page)).toHaveCount(count);
  const values = await weightRows(page).evaluateAll((rows) =>
    rows.map((row) => (row as HTMLElement).dataset.value ?? 'NaN'),
  );
  return values.map(Number);
}

/** The largest gap between the listed weights and `expected`, for a poll until the table caught up. */
const weightGap = async (page: Page, expected: number[]) => {
  const listed = await listedWeights(page, expected.length);
  return Math.max(...listed.map((w, i) => Math.abs(w - expected[i])));
};

// The whole construction of the lecture cubic (step 6 of 6): the weights, P(μ) and the curve.
test.beforeEach(async ({ page }) => {
  await page.goto('./#/blending?step=6');
  await expect(curve(page)).toBeVisible();
  await expect(plot(page)).toBeVisible();
});

test('the lecture cubic at μ = 0.5 lists the weights 1/8, 3/8, 3/8, 1/8', async ({ page }) => {
  await expectHash(page, 'mu', (v) => v === '0.5');
  await expect.poll(() => listedWeights(page, 4)).toEqual([0.125, 0.375, 0.375, 0.125]);
  await expect(page.getByText(/centre-weighted centroid/)).toBeVisible();
  // P(0.5) of (0,0), (1,2), (3,2), (4,0) is (2, 1.5).
  await expect(page.getByText('Worked example: P(0.5) for the cubic')).toBeVisible();
  // The weights' sum in sensible digits, and the parameter is μ throughout (the slides' u is in the key).
  await expect(page.getByText(/Together they fill the bar: ΣW = 1\. /)).toBeVisible();
  await expect(page.getByText(/Collect the powers of μ:/)).toBeVisible();
  await page.getByText('Symbols here and in the notes').click();
  // The key's first row is the kit's: the reader's letter, and each document's.
  await expect(
    page.getByText(/^μ in the lecture notes, u in the slides, t in the practical/),
  ).toBeVisible();
});

test('dragging the plot cursor changes μ, the weights and the curve figure; the weights sum to 1', async ({
  page,
}) => {
  const before = await listedWeights(page, 4);
  const curveBefore = await pixels(page, 'curve');
  const handle = page.getByRole('button', { name: /^μ at/ });
  const box = (await handle.boundingBox())!;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 90, y + 40, { steps: 6 });
  await page.mouse.up();
  await expectHash(page, 'mu', (v) => Number(v) > 0.55);
  const mu = Number((await linkState(page)).mu);
  await expect(page.getByRole('slider', { name: 'μ' })).toHaveValue(String(Number(mu.toFixed(2))));
  // W(3, i, μ) = C(3, i) μ^i (1 − μ)^(3 − i), read back from the page.
  const expected = [1, 3, 3, 1].map((c, i) => c * mu ** i * (1 - mu) ** (3 - i));
  await expect.poll(() => weightGap(page, expected)).toBeLessThan(1e-12);
  const after = await listedWeights(page, 4);
  expect(after).not.toEqual(before);
  expect(Math.abs(after.reduce((a, b) => a + b, 0) - 1)).toBeLessThan(1e-12);
  expect(await pixels(page, 'curve')).not.toBe(curveBefore);

  // The cursor line can be grabbed anywhere along its height, not only at its handle.
  const plotBox = (await plot(page).boundingBox())!;
  const lineX = box.x + box.width / 2 + 90;
  await page.mouse.move(lineX, plotBox.y + plotBox.height * 0.6);
  await page.mouse.down();
  await page.mouse.move(lineX - 200, plotBox.y + plotBox.height * 0.6, { steps: 6 });
  await page.mouse.up();
  await expectHash(page, 'mu', (v) => Number(v) < mu - 0.2);
  const left = Number((await linkState(page)).mu);
  await expect
    .poll(() =>
      weightGap(
        page,
        [1, 3, 3, 1].map((c, i) => c * left ** i * (1 - left) ** (3 - i)),
      ),
    )
    .toBeLessThan(1e-12);
  const weights = await listedWeights(page, 4);
  expect(Math.abs(weights.reduce((a, b) => a + b, 0) - 1)).toBeLessThan(1e-12);
  await snapshot(page, 'blending-dragged');
});

test('the cursor moves with the keyboard, and the weights of every degree sum to 1', async ({
  page,
}) => {
  await page.getByRole('button', { name: /^μ at/ }).focus();
  await page.keyboard.press('ArrowRight');
  await expectHash(page, 'mu', (v) => Number(v) > 0.5);
  await page.keyboard.press('ArrowUp');
  // Up and down do not move μ: the cursor only slides along the μ axis.
  const mu = (await linkState(page)).mu;
  await page.keyboard.press('ArrowLeft');
  await expectHash(page, 'mu', (v) => Number(v) < Number(mu));
  const add = page.getByRole('button', { name: 'N + 1: add a control point' });
  const check = async (n: number) => {
    await expect(page.getByRole('heading', { name: new RegExp(`\\(N = ${n}\\)`) })).toBeVisible();
    const weights = await listedWeights(page, n + 1);
    expect(weights.every((w) => w >= 0)).toBe(true);
    expect(Math.abs(weights.reduce((a, b) => a + b, 0) - 1)).toBeLessThan(1e-12);
  };
  await add.click();
  await check(4);
  // Twelve points (N = 11) from a link, then the last one the lesson allows.
  const twelve = Array.from({ length: 12 }, (_, i) => `${i},${i % 2}`).join(';');
  await page.goto(`./#/blending?p=${twelve}&mu=0.37&step=14`);
  await check(11);
  await add.click();
  await check(12);
  await expect(page.getByRole('button', { name: 'N + 1: add a control point' })).toBeDisabled();
});

test('hovering a weight row highlights its control point in both figures', async ({ page }) => {
  const curveBefore = await pixels(page, 'curve');
  const plotBefore = await pixels(page, 'blending');
  const row = page
    .getByRole('table', { name: 'Weights at μ', exact: true })
    .getByRole('row', { name: /^P₂/ });
  await row.hover();
  await expect(row).toHaveClass(/current/);
  await expect.poll(() => pixels(page, 'curve')).not.toBe(curveBefore);
  expect(await pixels(page, 'blending')).not.toBe(plotBefore);
});

test('comparing with Lagrange shows negative weights and a curve leaving the hull', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Compare: Lagrange' }).click();
  await expectHash(page, 'b', (v) => v === 'lagrange');
  await expect(
    page.getByText(/Not non-negative: the lowest value on \[0, 1\] is −\d/),
  ).toBeVisible();
  await expect(page.getByText(/leaves the convex hull/)).toBeVisible();
  await page.getByLabel('Uniform cubic B-spline').check();
  await expectHash(page, 'b', (v) => v === 'bspline');
  await expect(page.getByText('No value on [0, 1] is negative.')).toBeVisible();
  await page.getByLabel('Hermite H0…H3').check();
  await expect(page.getByText(/Not non-negative/)).toBeVisible();
});

test('the Compare scenes start from the Bézier picture, and the mirror steps through the symmetry', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Compare: Hermite' }).click();
  const status = page.locator('.step-status');
  await expect(status).toHaveText(
    'Step 0/7: The control points P₀ … P₃, their Bézier curve and Bernstein weights, to compare with',
  );
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText("Step 1/7: Hermite's data, first the end points: P₀ and P₃");
  await page.goto('./#/blending?step=0');
  await page.getByLabel('Bernstein mirrored: μ → 1 − μ').check();
  await expectHash(page, 'b', (v) => v === 'mirror');
  await page.keyboard.press('End');
  await expect(status).toHaveText(/^Step 4\/4: So P\(1 − μ\) weights the points in reverse order/);
});

test('a link with a bad comparison or too many points keeps the rest and says why', async ({
  page,
}) => {
  await page.goto('./#/blending?p=0,0;1,1;2,0&mu=0.25&b=fourier');
  await expect(page.getByRole('status').getByText(/b: "fourier" is not one of/)).toBeVisible();
  await expectHash(page, 'p', (v) => v === '0,0;1,1;2,0');
  await expect(page.getByRole('heading', { name: 'Weights at μ = 0.25 (N = 2)' })).toBeVisible();
  // Coincident control points are legal: the curve is a point, the weights still sum to 1.
  await page.goto('./#/blending?p=1,1;1,1;1,1;1,1&mu=0.3');
  await expect(page.getByRole('heading', { name: 'Weights at μ = 0.3 (N = 3)' })).toBeVisible();
  const weights = await listedWeights(page, 4);
  expect(Math.abs(weights.reduce((a, b) => a + b, 0) - 1)).toBeLessThan(1e-12);
});

test('the script steps from the points through each weight to the curve, then opens the next scene', async ({
  page,
}) => {
  await page.goto('./#/blending?step=0');
  const status = page.locator('.step-status');
  await expect(status).toHaveText('Step 0/6: The control points P₀ … P₃ and their polygon');
  let previous = await pixels(page, 'blending');
  const captions = [
    'The weight of P₀: W(3, 0, μ), largest at μ = 0',
    'The weight of P₁: W(3, 1, μ), largest at μ = 1/3',
    'The weight of P₂: W(3, 2, μ), largest at μ = 2/3',
    'The weight of P₃: W(3, 3, μ), largest at μ = 1',
  ];
  for (const [k, caption] of captions.entries()) {
    await page.keyboard.press('PageDown');
    await expect(status).toHaveText(`Step ${k + 1}/6: ${caption}`);
    // Each weight adds its curve to the plot.
    await expect.poll(() => pixels(page, 'blending')).not.toBe(previous);
    previous = await pixels(page, 'blending');
  }
  const curve = await pixels(page, 'curve');
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText(/^Step 6\/6: As μ runs from 0 to 1/);
  await expect.poll(() => pixels(page, 'curve')).not.toBe(curve);
  // Presenter view draws the caption and its formula over the figure.
  await page.keyboard.press('p');
  await expect(page.locator('.caption-step')).toHaveText(/As μ runs from 0 to 1/);
  await expect(page.locator('.caption-formula .katex')).toBeVisible();
  await snapshot(page, 'blending-script-last-projector');
  await page.keyboard.press('PageDown');
  await expectHash(page, 'scene', (v) => v === 'linear');
  await expectHash(page, 'step', (v) => v === '0');
  await expect(page.locator('.caption-step')).toHaveText(
    'The control points P₀ … P₁ and their polygon',
  );
});

test('every scene opens at step 0 and ends with everything drawn, walked with the clicker in presenter view', async ({
  page,
}) => {
  const ids = await sceneIds(page);
  expect(ids.length).toBeGreaterThanOrEqual(7);
  await page.goto('./#/blending?step=0');
  await page.keyboard.press('p');
  const status = page.locator('.step-status');
  const caption = page.locator('.caption-step');
  for (const id of ids) {
    await expectHash(page, 'scene', (v) => v === id);
    await expectHash(page, 'step', (v) => v === '0');
    await expect(caption).toHaveText(/^The control points/);
    const first = await pixels(page, 'blending');
    await snapshot(page, `blending-projector-${id}-first`);
    await page.keyboard.press('End');
    // N + 1 weights, P(μ), the curve, and the comparison if there is one: at most 20 steps.
    // Interpolating or approximating has its own five: points, one curve, its distances,
    // the other, its distances.
    const n = (await linkState(page)).p.split(';').length - 1;
    const compared = ['hermite', 'bspline', 'lagrange'].includes(id) ? 1 : 0;
    const last = id === 'interpolating' ? 4 : n + 3 + compared;
    await expectHash(page, 'step', (v) => v === String(last));
    await expect(status).toHaveText(/^Step (\d+)\/\1:/);
    expect(await pixels(page, 'blending')).not.toBe(first);
    await snapshot(page, `blending-projector-${id}-last`);
    await page.keyboard.press('PageDown');
  }
});
