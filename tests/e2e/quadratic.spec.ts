import type { Page } from '@playwright/test';
import { expect, expectHash, hashState, snapshot, test } from './fixtures';

const figure = (page: Page) => page.locator('canvas[data-figure="quadratic"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());

/** The points of the link, as numbers. */
const points = (page: Page) =>
  hashState(page)
    .p.split(';')
    .map((q) => q.split(',').map(Number));

/** a0, a1, a2 as the page prints them in the "all digits" table. */
async function coefficients(page: Page): Promise<number[][]> {
  const table = page.getByRole('table', { name: 'Coefficients, all digits' });
  const rows = [];
  for (const name of ['a0', 'a1', 'a2']) {
    const cells = await table
      .getByRole('row', { name: new RegExp(`^${name} `) })
      .locator('td')
      .allInnerTexts();
    rows.push([Number(cells[1]), Number(cells[2])]);
  }
  return rows;
}

/** Opens the details table, sets μ1 with the slider and checks P(μ1) = P1 from the printed numbers. */
async function expectThroughP1(page: Page, mu: number) {
  const slider = page.getByRole('slider', { name: 'μ₁' });
  await slider.fill(String(mu));
  await expectHash(page, 'mu', (v) => v === String(mu));
  const p1 = points(page)[1];
  // The table is redrawn on the next frame: its last row names the new μ1.
  const table = page.getByRole('table', { name: 'Coefficients, all digits' });
  await expect(table.getByRole('row', { name: new RegExp(`^P\\(${mu}\\) `) })).toBeVisible();
  const [a0, a1, a2] = await coefficients(page);
  for (const d of [0, 1]) {
    // P(μ1) = a2 μ1² + a1 μ1 + a0, computed here from the printed coefficients.
    expect(Math.abs(a2[d] * mu * mu + a1[d] * mu + a0[d] - p1[d])).toBeLessThan(1e-9);
  }
  return [a0, a1, a2];
}

test.beforeEach(async ({ page }) => {
  await page.goto('./#/quadratic');
  await expect(figure(page)).toBeVisible();
});

test('moving the μ1 slider changes the curve and the coefficients, and P(μ1) stays P1', async ({
  page,
}) => {
  await page.keyboard.press('End');
  await expect(page.getByRole('heading', { name: /^Step 3 of 3/ })).toBeVisible();
  await page.getByText('All digits of the coefficients').click();
  const first = await expectThroughP1(page, 0.3);
  const before = await pixels(page);
  const second = await expectThroughP1(page, 0.72);
  expect(second[2]).not.toEqual(first[2]);
  // a0 = P0 whatever μ1 is; a1 + a2 = P2 − P0.
  expect(second[0]).toEqual(points(page)[0]);
  const [p0, , p2] = points(page);
  for (const d of [0, 1]) expect(second[1][d] + second[2][d]).toBeCloseTo(p2[d] - p0[d], 9);
  expect(await pixels(page)).not.toBe(before);
  // The typeset check line says the same thing.
  await expect(page.getByText(/Check:/).first()).toBeVisible();
  await snapshot(page, 'quadratic-rules-mu-0.72');
});

test('a point moved with the keyboard keeps the curve through it', async ({ page }) => {
  await page.keyboard.press('PageDown');
  await page.getByText('All digits of the coefficients').click();
  const p1 = page.getByRole('button', { name: /^P1 at/ });
  await p1.focus();
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('Shift+ArrowRight');
  await expectHash(page, 'p', (v) => v.split(';')[1] !== '1,2');
  await expectThroughP1(page, 0.45);
});

test('two equal x: the parabola lesson says there is no y(x), on the figure and the panel', async ({
  page,
}) => {
  const before = await pixels(page);
  await page.getByRole('button', { name: 'Two equal x' }).click();
  await expectHash(page, 'p', (v) => v === '1,0;1,2.5;3.5,1.5');
  await expect(page.getByText(/There is none: P0 and P1 share x = 1/)).toBeVisible();
  expect(await pixels(page)).not.toBe(before);
  await snapshot(page, 'quadratic-same-x');
  // The parametric curve has no such trouble: step forward and it is drawn through all three.
  await page.getByText('All digits of the coefficients').click();
  await page.getByRole('button', { name: 'Step forward' }).click();
  await expectThroughP1(page, 0.5);
});

test('a link with three equal x, or points going backwards, says so', async ({ page }) => {
  await page.goto('./#/quadratic?p=2,0;2,1;2,3&step=0');
  await expect(page.getByText(/There is none: all three points share x = 2/)).toBeVisible();
  await page.goto('./#/quadratic?p=1,1;1,1;1,1&step=0');
  await expect(page.getByText(/all three points are at one spot, \(1, 1\)/).first()).toBeVisible();
  await page.getByRole('button', { name: 'Going backwards' }).click();
  await expect(
    page.getByText(/meets the points in the wrong order: x1 = 4 is not between/),
  ).toBeVisible();
  await snapshot(page, 'quadratic-backwards');
});

test('the rules put μ1 where the formulas say', async ({ page }) => {
  await expectHash(page, 'p', (v) => v !== '');
  const defaults = hashState(page).p;
  await page.getByRole('button', { name: 'Uneven spacing' }).click();
  await expect(page.getByRole('heading', { name: /^Step 3 of 3/ })).toBeVisible();
  // The link is written just after the change: read the preset's points, not the old ones.
  await expectHash(page, 'p', (v) => v !== defaults);
  const [p0, p1, p2] = points(page);
  const d0 = Math.hypot(p1[0] - p0[0], p1[1] - p0[1]);
  const d1 = Math.hypot(p2[0] - p1[0], p2[1] - p1[1]);
  const rules = page.getByRole('table', { name: 'Rules for μ1' });
  await expect(rules.getByRole('row', { name: /^Chord length/ })).toContainText(
    (d0 / (d0 + d1)).toFixed(4),
  );
  const centripetal = Math.sqrt(d0) / (Math.sqrt(d0) + Math.sqrt(d1));
  await expect(rules.getByRole('row', { name: /^Centripetal/ })).toContainText(
    centripetal.toFixed(4),
  );
  const before = await pixels(page);
  await page.getByRole('button', { name: 'Use centripetal' }).click();
  await expectHash(page, 'mu', (v) => Math.abs(Number(v) - centripetal) < 1e-9);
  await expect(page.getByRole('button', { name: 'Use centripetal' })).toBeDisabled();
  await expect(page.getByRole('spinbutton', { name: 'μ₁ value' })).toHaveValue(
    centripetal.toFixed(3),
  );
  expect(await pixels(page)).not.toBe(before);
  await page.getByText('All digits of the coefficients').click();
  const [a0, a1, a2] = await coefficients(page);
  const mu = Number(hashState(page).mu);
  for (const d of [0, 1])
    expect(Math.abs(a2[d] * mu * mu + a1[d] * mu + a0[d] - p1[d])).toBeLessThan(1e-9);
});

test('every preset draws, in normal and projector mode', async ({ page }) => {
  const presets = page.getByRole('group', { name: 'Presets' }).getByRole('button');
  const count = await presets.count();
  expect(count).toBe(5);
  let previous = await pixels(page);
  for (let i = 0; i < count; i++) {
    const preset = presets.nth(i);
    const id = await preset.getAttribute('data-preset');
    await preset.click();
    await expect.poll(() => pixels(page)).not.toBe(previous);
    previous = await pixels(page);
    await snapshot(page, `quadratic-preset-${id}`);
  }
  await page.keyboard.press('p');
  await expect(page.locator('.projector')).toHaveCount(1);
  await snapshot(page, 'quadratic-projector-uneven');
  await page.getByRole('button', { name: 'Figure 2: the family' }).click();
  await snapshot(page, 'quadratic-projector-family');
});

test('steps walk from the parabola to the rules, with a clicker', async ({ page }) => {
  const frames = [await pixels(page)];
  for (const k of [1, 2, 3]) {
    await page.keyboard.press('PageDown');
    await expect(page.getByRole('heading', { name: new RegExp(`^Step ${k} of 3`) })).toBeVisible();
    frames.push(await pixels(page));
  }
  expect(new Set(frames).size).toBe(4);
  await expect(
    page.getByRole('link', { name: /one polynomial through n \+ 1 points/ }),
  ).toHaveAttribute('href', '#/lagrange');
});
