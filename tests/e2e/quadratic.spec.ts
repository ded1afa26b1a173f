import type { Page } from '@playwright/test';
import {
  expect,
  expectHash,
  snapshot,
  test,
  linkState,
  inLecturesLetter,
  readNumber,
} from './fixtures';

// This lesson follows the lecture notes, and its tests read its text in their letter, μ.
test.beforeEach(({ page }) => inLecturesLetter(page));

const figure = (page: Page) => page.locator('canvas[data-figure="quadratic"]');
const pixels = (page: Page) => figure(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());

/** The points of the link, as numbers. */
const points = async (page: Page) =>
  (await linkState(page)).p.split(';').map((q) => q.split(',').map(Number));

/** a0, a1, a2 as the page prints them in the "all digits" table. */
async function coefficients(page: Page): Promise<number[][]> {
  const table = page.getByRole('table', { name: 'Coefficients, all digits' });
  const rows = [];
  for (const name of ['a0', 'a1', 'a2']) {
    const cells = await table
      .getByRole('row', { name: new RegExp(`^${name} `) })
      .locator('td')
      .allInnerTexts();
    rows.push([readNumber(cells[1]), readNumber(cells[2])]);
  }
  return rows;
}

/** Opens the details table, sets μ1 with the slider and checks P(μ1) = P1 from the printed numbers. */
async function expectThroughP1(page: Page, mu: number) {
  const slider = page.getByRole('slider', { name: 'μ₁' });
  await slider.fill(String(mu));
  await expectHash(page, 'mu', (v) => v === String(mu));
  const p1 = (await points(page))[1];
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

const heading = (page: Page, k: number) =>
  page.getByRole('heading', { name: new RegExp(`^Step ${k} of 5: `) });

test('the μ1 slider and a moved point change the curve, and P(μ1) stays P1', async ({ page }) => {
  await page.keyboard.press('End');
  await expect(heading(page, 5)).toBeVisible();
  await page.getByText('All digits of the coefficients').click();
  const first = await expectThroughP1(page, 0.3);
  const before = await pixels(page);
  const second = await expectThroughP1(page, 0.72);
  expect(second[2]).not.toEqual(first[2]);
  // a0 = P0 whatever μ1 is; a1 + a2 = P2 − P0.
  expect(second[0]).toEqual((await points(page))[0]);
  const [p0, , p2] = await points(page);
  for (const d of [0, 1]) expect(second[1][d] + second[2][d]).toBeCloseTo(p2[d] - p0[d], 9);
  expect(await pixels(page)).not.toBe(before);
  await expect(page.getByText(/Check:/).first()).toBeVisible();
  await snapshot(page, 'quadratic-rules-mu-0.72');
  // A point moved with the keyboard: the curve still passes through it.
  await page.getByRole('button', { name: /^P1 at/ }).focus();
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('Shift+ArrowRight');
  await expectHash(page, 'p', (v) => v.split(';')[1] !== '2,3');
  await expectThroughP1(page, 0.45);
});

test('the clicker builds the construction from the points up, then opens the next scene', async ({
  page,
}) => {
  await page.keyboard.press('Home');
  await expect(heading(page, 0)).toHaveText(
    'Step 0 of 5: Three points P₀, P₁, P₂: we want a smooth curve through them',
  );
  const frames = [await pixels(page)];
  const captions = [
    'First idea: the parabola y(x)',
    'Instead, a parametric quadratic P(μ)',
    'Dots at equal steps of μ',
    'One set of points, four curves',
    'Choosing μ₁ from the points',
  ];
  for (const [k, caption] of captions.entries()) {
    await page.keyboard.press('PageDown');
    await expect(heading(page, k + 1)).toContainText(caption);
    await expect.poll(() => pixels(page)).not.toBe(frames[frames.length - 1]);
    frames.push(await pixels(page));
  }
  expect(new Set(frames).size).toBe(6);
  // Past the last step: the next scene, at its first step.
  await page.keyboard.press('PageDown');
  await expectHash(page, 'p', (v) => v === '1,0;1,2.5;3.5,1.5');
  await expect(heading(page, 0)).toBeVisible();
  await page.keyboard.press('PageDown');
  await expect(page.getByText(/There is none: P₀ and P₁ share x = 1/)).toBeVisible();
  await expect(heading(page, 1)).toContainText('there is none, P₀ and P₁ share x = 1');
  await snapshot(page, 'quadratic-same-x');
  // The parametric curve has no such trouble: the next step draws it through all three.
  await page.getByText('All digits of the coefficients').click();
  await page.keyboard.press('PageDown');
  await expectThroughP1(page, 0.5);
  await expect(
    page.getByRole('link', { name: /one polynomial through n \+ 1 points/ }),
  ).toHaveAttribute('href', '#/lagrange');
});

test('links with three equal x, one spot, or points going backwards say so', async ({ page }) => {
  await page.goto('./#/quadratic?p=2,0;2,1;2,3&step=1');
  await expect(page.getByText(/There is none: all three points share x = 2/)).toBeVisible();
  await page.goto('./#/quadratic?p=1,1;1,1;1,1&step=1');
  await expect(page.getByText(/all three points are at one spot, \(1, 1\)/).first()).toBeVisible();
  await page.getByRole('button', { name: 'Going backwards' }).click();
  await page.keyboard.press('PageDown');
  await expect(
    page.getByText(/meets the points in the wrong order: x1 = 4 is not between/),
  ).toBeVisible();
  await snapshot(page, 'quadratic-backwards');
});

test('the rules put μ1 where the formulas say', async ({ page }) => {
  await page.getByRole('button', { name: 'Uneven spacing' }).click();
  await expectHash(page, 'p', (v) => v === '0,0;0.6,1;5,1.5');
  await page.keyboard.press('End');
  await expect(heading(page, 5)).toBeVisible();
  // d0 = |(0.6, 1)|, d1 = |(4.4, 0.5)|, from the scene's points.
  const d0 = Math.hypot(0.6, 1);
  const d1 = Math.hypot(4.4, 0.5);
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
  const mu = centripetal;
  for (const d of [0, 1])
    expect(Math.abs(a2[d] * mu * mu + a1[d] * mu + a0[d] - [0.6, 1][d])).toBeLessThan(1e-9);
  await page.keyboard.press('p');
  await snapshot(page, 'quadratic-presenter-rules');
});
