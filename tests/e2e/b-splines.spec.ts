import type { Page } from '@playwright/test';
import { bsplineBasis } from '../../src/math';
import { expect, expectHash, snapshot, test, linkState } from './fixtures';

const numbers = (page: Page) => page.getByRole('table', { name: 'Numbers of the curve' });
/** The value cell of a row of the Numbers table. */
const value = (page: Page, name: RegExp) =>
  numbers(page).getByRole('row', { name }).locator('td').nth(1);
const point = (text: string) => text.replace(/[()]/g, '').split(',').map(Number);
const list = (raw: string) => raw.split(';').map((q) => q.split(',').map(Number));
/**
 * A tiny number as the page writes it for a person, read back by hand: "0",
 * "8.9 × 10⁻¹⁶" (never "8.9e-16"), or a plain decimal. NaN for anything else.
 */
function written(text: string): number {
  const small = /^(\d\.\d) × 10⁻([⁰¹²³⁴⁵⁶⁷⁸⁹]+)$/.exec(text);
  if (!small) return /^−?\d+(\.\d+)?$/.test(text) ? Number(text.replace('−', '-')) : NaN;
  const power = [...small[2]].map((c) => '⁰¹²³⁴⁵⁶⁷⁸⁹'.indexOf(c)).join('');
  return Number(small[1]) * 10 ** -Number(power);
}

async function openScene(page: Page, label: string, id: string) {
  await page.getByRole('button', { name: label, exact: true }).click();
  await expectHash(page, 'x', (v) => v === id);
}

test.beforeEach(async ({ page }) => {
  await page.goto('./#/b-splines');
  await expect(page.locator('canvas[data-figure="curve"]')).toBeVisible();
});

test('local control: moving one point changes only its segments of the uniform cubic', async ({
  page,
}) => {
  await openScene(page, 'Local control', 'local');
  // The scene moved x4: Q4 … Q7 changed, Q3, Q8 and Q9 did not.
  await expect(value(page, /^segments changed/)).toHaveText('4 of 7');
  await page.getByRole('button', { name: /new “before”/ }).click();
  await expect(value(page, /^segments changed/)).toHaveText('0 of 7');
  const before = (await linkState(page)).p;
  await page.getByRole('button', { name: /^P9 at/ }).focus();
  await page.keyboard.press('ArrowUp');
  await expectHash(page, 'p', (v) => v !== before);
  // The last point acts on the last segment only.
  await expect(value(page, /^segments changed/)).toHaveText('1 of 7');
});

test('clamped knots interpolate the end points; a knot of multiplicity p passes through a point', async ({
  page,
}) => {
  await openScene(page, 'Clamped ends', 'clamped');
  const p = list((await linkState(page)).p);
  await expect(value(page, /^curve start/)).toHaveText(/\(/);
  const start = point(await value(page, /^curve start/).innerText());
  const end = point(await value(page, /^curve end/).innerText());
  expect(Math.hypot(start[0] - p[0][0], start[1] - p[0][1])).toBeLessThan(1e-4);
  expect(Math.hypot(end[0] - p[6][0], end[1] - p[6][1])).toBeLessThan(1e-4);

  await openScene(page, 'Repeated knots', 'repeated');
  const join = await value(page, /^knot 1\.000 ×3/).innerText();
  expect(join).toMatch(/^C⁰, through P₃: distance /);
  expect(written(join.split('distance ')[1])).toBeLessThan(1e-12);
});

test('the knot strip: a knot dropped on its neighbour stacks, and the curve loses a derivative there', async ({
  page,
}) => {
  await openScene(page, 'Knots and Cox–de Boor', 'knots');
  await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '1');
  const from = (await page.getByRole('button', { name: /^u5 at/ }).boundingBox())!;
  const to = (await page.getByRole('button', { name: /^u4 at/ }).boundingBox())!;
  await page.mouse.move(from.x + from.width / 2, from.y + from.height / 2);
  await page.mouse.down();
  await page.mouse.move(to.x + to.width / 2 + 2, to.y + to.height / 2, { steps: 8 });
  await page.mouse.up();
  await expectHash(page, 'u', (v) => v === '0,1,2,3,4,4,6,7,8,9,10');
  await expect(value(page, /^knot 4\.000 ×2/)).toHaveText('C¹');
});

test('the Cox–de Boor triangle: its last row sums to 1 and matches bsplineBasis at every t', async ({
  page,
}) => {
  await openScene(page, 'Knots and Cox–de Boor', 'knots');
  await page.keyboard.press('End');
  await expectHash(page, 'k', (v) => v === '6');
  const knots = (await linkState(page)).u.split(',').map(Number);
  // One row a basis function i; the column N(i,3) is each row's fourth value.
  const lastColumn = page
    .getByRole('table', { name: 'Cox–de Boor triangle' })
    .locator('tbody tr td:nth-of-type(4)');
  await expect(
    page.getByRole('table', { name: 'Cox–de Boor triangle' }).locator('thead th').last(),
  ).toHaveText('Nᵢ,₃');
  const number = page.getByRole('spinbutton', { name: 't value' });
  for (const t of [0, 0.137, 0.5, 0.77, 1]) {
    await number.fill(String(t));
    await number.press('Enter');
    await expectHash(page, 't', (v) => Number(v) === t);
    // u runs over the domain [u3, u7] = [3, 7].
    const u = 3 + 4 * t;
    await expect(value(page, /^parameter u/)).toHaveText(u.toFixed(4));
    // Rows past the last function of degree 3 have no N(i,3): m + 1 = 7 have.
    const cells = (await lastColumn.allInnerTexts()).slice(0, knots.length - 4).map(Number);
    expect(cells).toHaveLength(7);
    expect(Math.abs(cells.reduce((a, b) => a + b, 0) - 1)).toBeLessThan(3e-4);
    cells.forEach((cell, i) =>
      expect(Math.abs(cell - bsplineBasis(knots, 3, i, u))).toBeLessThan(6e-5),
    );
  }
});

test('NURBS: the circle is exact, and a projective map with the weights keeps the curve', async ({
  page,
}) => {
  await openScene(page, 'The exact circle', 'circle');
  const off = await value(page, /^circle: largest/).innerText();
  expect(written(off)).toBeLessThan(1e-9);
  expect(Number(await value(page, /^all weights 1/).innerText())).toBeGreaterThan(0.1);
  await openScene(page, 'Projective map', 'projective');
  expect(written(await value(page, /^H\(P\) vs NURBS/).innerText())).toBeLessThan(1e-9);
  expect(Number(await value(page, /^H\(P\) vs old weights/).innerText())).toBeGreaterThan(0.05);
});

test('NURBS: dragging a halo outwards raises that weight alone and pulls the curve toward its point', async ({
  page,
}) => {
  await openScene(page, 'NURBS weights', 'nurbs');
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '2');
  const number = page.getByRole('spinbutton', { name: 't value' });
  await number.fill('0.5');
  await number.press('Enter');
  await expectHash(page, 't', (v) => v === '0.5');
  const p = list((await linkState(page)).p);
  expect((await linkState(page)).w).toBe('1,1,4,1,1,0.25,1');
  // Clamped uniform knots 0,0,0,0,¼,½,¾,1,1,1,1: at the knot ½ Cox–de Boor gives
  // N2 = 1/6, N3 = 2/3, N4 = 1/6 (by hand), so with w2 = 4, w4 = 1:
  // C(½) = (4·x2 + 4·w3·x3 + x4) / (5 + 4·w3).
  const closedForm = (w3: number) =>
    [0, 1].map((d) => (4 * p[2][d] + 4 * w3 * p[3][d] + p[4][d]) / (5 + 4 * w3));
  const gap = (a: number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);
  const curvePoint = async () => point(await value(page, /^P\(u\)/).innerText());
  const before = await curvePoint();
  expect(gap(before, closedForm(1))).toBeLessThan(1e-4);

  // Pixels per unit from the handles of x0 and x6.
  const centre = async (name: RegExp) => {
    const box = (await page.getByRole('button', { name }).boundingBox())!;
    return [box.x + box.width / 2, box.y + box.height / 2];
  };
  const [s0, s6, [cx, cy]] = [
    await centre(/^P0 at/),
    await centre(/^P6 at/),
    await centre(/^P3 at/),
  ];
  const scale = gap(s0, s6) / gap(p[0], p[6]);
  // A halo unit is 6% of the diagonal of the points' box (10 × 4); weight 1 is one unit.
  const unit = 0.06 * Math.hypot(10, 4) * scale;
  await page.mouse.move(cx + unit, cy);
  await expect(page.locator('canvas[data-figure="curve"]')).toHaveClass(/over-handle/);
  await page.mouse.down();
  await page.mouse.move(cx + 1.8 * unit, cy, { steps: 8 });
  await page.mouse.up();
  await expectHash(page, 'w', (v) => v !== '1,1,4,1,1,0.25,1');
  const w = (await linkState(page)).w.split(',').map(Number);
  // A radius of 1.8 units is 0.3 + 0.7·√w: w = (1.5/0.7)² ≈ 4.59 (to a pixel's worth).
  expect(Math.abs(w[3] - 4.59)).toBeLessThan(0.2);
  expect(w.filter((_, i) => i !== 3)).toEqual([1, 1, 4, 1, 0.25, 1]);
  await expect(page.getByRole('slider', { name: 'w3' })).toHaveValue(String(w[3]));
  await expect.poll(async () => gap(await curvePoint(), closedForm(w[3]))).toBeLessThan(1e-4);
  expect(gap(await curvePoint(), p[3])).toBeLessThan(gap(before, p[3]) - 0.3);

  // The last step writes C(½) with its denominator Σ wᵢNᵢ = (5 + 4·w3)/6; a new weight
  // rewrites the numbers of the same formula.
  await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '3');
  const stepFormula = page.locator('.step-formulas .katex-html');
  await expect(stepFormula).toContainText(((5 + 4 * w[3]) / 6).toFixed(3));
  const slider = page.getByRole('slider', { name: 'w3' });
  await slider.fill('2');
  await expectHash(page, 'w', (v) => v === '1,1,4,2,1,0.25,1');
  await expect(stepFormula).toContainText((13 / 6).toFixed(3));
});

test('the notes: a key to their symbols, and beside the closed scene’s three wrapped points the slides’ x₀ = xₘ, said kindly', async ({
  page,
}) => {
  const key = page.locator('details.notes-key');
  await expect(key.locator('summary')).toHaveText('Symbols here and in the notes');
  await key.locator('summary').click();
  await expect(key).toContainText('cᵢ in the lecture slides (c3 … cm)');
  await expect(key).toContainText('degree is n, and order is n + 1');
  const slip = page.getByRole('note').filter({ hasText: 'x₀ = xₘ' });
  await expect(slip).toBeHidden();
  await openScene(page, 'Closed B-spline', 'closed');
  await expect(slip).toBeVisible();
  await expect(slip).toContainText('closing it takes three, Pₘ₊₁ = P₀, Pₘ₊₂ = P₁ and Pₘ₊₃ = P₂');
  await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '1');
  await expect(page.locator('.step-status')).toContainText(
    'Closed: after P₅ come P₀, P₁, P₂ again (P₆ = P₀, P₇ = P₁, P₈ = P₂)',
  );
  await openScene(page, 'Knots and Cox–de Boor', 'knots');
  await expect(slip).toBeHidden();
  await expect(page.locator('.step-status')).toContainText('The m + 1 = 7 control points P₀ … P₆');
});

test('the uniform cubic bases, derived row by row on the equally spaced knots: their values are the triangle’s', async ({
  page,
}) => {
  await openScene(page, 'Knots and Cox–de Boor', 'knots');
  for (let k = 1; k <= 5; k++) await page.keyboard.press('PageDown');
  await expectHash(page, 'k', (v) => v === '5');
  const stepFormula = page.locator('.step-formulas .katex-html');
  await expect(stepFormula).toContainText('t=u−u4=0.600');
  const lastColumn = page
    .getByRole('table', { name: 'Cox–de Boor triangle' })
    .locator('tbody tr td:nth-of-type(4)');
  const cells = (await lastColumn.allInnerTexts()).map(Number);
  const nonZero = cells.filter((v) => v > 0);
  expect(nonZero).toHaveLength(4);
  const text = (await stepFormula.innerText()).replace(/\s+/g, '');
  for (const value of nonZero) expect(text).toContain(value.toFixed(3));
});

test('every scene at its last step, in presenter view (screenshots)', async ({ page }) => {
  const scenes: [string, number][] = [
    ['uniform', 4],
    ['closed', 4],
    ['local', 3],
    ['knots', 6],
    ['clamped', 6],
    ['repeated', 6],
    ['convert', 4],
    ['properties', 4],
    ['nurbs', 3],
    ['circle', 4],
    ['projective', 3],
  ];
  await page.keyboard.press('p');
  for (const [id, count] of scenes) {
    await expectHash(page, 'x', (v) => v === id);
    await page.keyboard.press('End');
    await expectHash(page, 'k', (v) => v === String(count));
    await snapshot(page, `b-splines-${id}-presenter`);
    await page.keyboard.press('PageDown');
  }
});
