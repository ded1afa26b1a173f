import type { Page } from '@playwright/test';
import { naturalCubicDerivatives } from '../../src/math';
import { expect, expectHash, snapshot, test, linkState, readNumber } from './fixtures';

/** 12 → ₁₂: a village's index as the page's prose writes it. */
const subscript = (i: number) => [...String(i)].map((d) => '₀₁₂₃₄₅₆₇₈₉'[Number(d)]).join('');

const map = (page: Page) => page.locator('canvas[data-figure="map"]');
const pixels = (page: Page) => map(page).evaluate((c: HTMLCanvasElement) => c.toDataURL());
const villages = async (page: Page) =>
  (await linkState(page)).v.split(';').map((p) => p.split(',').map(Number));
const swept = (page: Page) =>
  page.locator('table[aria-label="Tridiagonal system"] tr[data-swept="1"]');
const fixed = (page: Page) =>
  page.locator('table[aria-label="Gradients found"] tr[data-fixed="1"]');

/** Drags a handle (found by its accessible name) by (dx, dy) pixels with the mouse. */
async function drag(page: Page, name: RegExp, dx: number, dy: number) {
  const box = (await page.getByRole('button', { name }).boundingBox())!;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + dx, y + dy, { steps: 6 });
  await page.mouse.up();
}

/** The coefficients [a, b, c, d] of x(p) and y(p) of the segment shown in the panel, from its formula. */
async function segmentCoefficients(page: Page): Promise<number[][]> {
  const tex = await page
    .getByRole('region', { name: 'Segment coefficients' })
    .locator('annotation')
    .first()
    .textContent();
  return ['x', 'y'].map((axis) => {
    const line = tex!.split('\\\\').find((l) => l.trim().startsWith(`${axis}(p)`))!;
    const rhs = line.slice(line.indexOf('&=') + 2).replace(/\s+/g, '');
    const terms = rhs.match(/[+-]?[0-9.]+(\\,p(\^\{\d\})?)?/g)!;
    const coefficients = [0, 0, 0, 0];
    for (const term of terms) {
      const power = term.includes('p^{')
        ? Number(term.match(/\^\{(\d)\}/)![1])
        : term.includes('p')
          ? 1
          : 0;
      coefficients[power] = Number(term.replace(/\\,p.*$/, ''));
    }
    return coefficients;
  });
}

test.beforeEach(async ({ page }) => {
  await page.goto('./#/road');
  await expect(map(page)).toBeVisible();
});

test('every method draws its own road, and says what it is', async ({ page }) => {
  const seen = new Set<string>();
  const methods = [
    ['roman', 'Roman road: straight segments'],
    ['quadratic', 'Quadratic pieces, one chosen gradient'],
    ['hermite', 'Cubic Hermite, parabola gradients'],
    ['natural', 'Natural cubic spline'],
    ['clamped', 'Clamped ends: joining other roads'],
    ['ring', 'Ring road: a closed spline'],
  ] as const;
  for (const [id, name] of methods) {
    await page.getByRole('radio', { name }).check();
    await expectHash(page, 'road', (v) => v === id);
    await expect(page.getByRole('heading', { name })).toBeVisible();
    const image = await pixels(page);
    expect(seen.has(image), `${id} draws a different picture`).toBe(false);
    seen.add(image);
    await snapshot(page, `road-${id}`);
  }
});

test('the overlay draws every answer with a legend, and each curve can be left out', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Every answer at once' }).click();
  await expectHash(page, 'overlay', (v) => v === '1');
  await expectHash(page, 'compare', (v) => v === '0,1,2,3,4,5,6,7,8,9,10');
  // One answer a step: the villages alone, then the Roman road, …
  const status = page.locator('.step-status');
  await expect(status).toHaveText(/^Step 0\/11: The 6 villages/);
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText('Step 1/11: Answer 1 of 11: Roman road (straight)');
  await page.keyboard.press('End');
  await expect(status).toHaveText('Step 11/11: Answer 11 of 11: Cubic B-spline (approximating)');
  const all = await pixels(page);
  await snapshot(page, 'road-overlay-all');
  await page.getByLabel('Lagrange polynomial').uncheck();
  await expectHash(page, 'compare', (v) => !v.split(',').includes('6'));
  expect(await pixels(page)).not.toBe(all);
});

test('dragging a village changes the road and the link; undo puts it back', async ({ page }) => {
  const before = await pixels(page);
  const start = (await linkState(page)).v;
  await drag(page, /^P2 at/, 30, -50);
  await expectHash(page, 'v', (v) => v !== start);
  const p2 = (await villages(page))[2];
  expect(p2[0]).toBeGreaterThan(42);
  expect(p2[1]).toBeGreaterThan(10);
  expect(await pixels(page)).not.toBe(before);
  await page.keyboard.press('Control+z');
  await expectHash(page, 'v', (v) => v === start);
});

test('the gradient handles move with Tab and the arrow keys', async ({ page }) => {
  await page.getByRole('radio', { name: 'Quadratic pieces, one chosen gradient' }).check();
  const q = page.getByRole('button', { name: /^B0 at/ });
  await q.focus();
  await page.keyboard.press('ArrowUp');
  await expectHash(page, 'q', (v) => v !== '30,0');
  expect(Number((await linkState(page)).q.split(',')[1])).toBeGreaterThan(0);

  await page.getByRole('radio', { name: 'Clamped ends: joining other roads' }).check();
  const before = (await linkState(page)).a;
  await page.getByRole('button', { name: /^D0 at/ }).focus();
  await page.keyboard.press('Shift+ArrowDown');
  await expectHash(page, 'a', (v) => v !== before);
  expect(Number((await linkState(page)).a.split(',')[1])).toBeLessThan(
    Number(before.split(',')[1]),
  );
});

test('the script: the villages, the system, one row swept per step, one D fixed per step, ending at naturalCubicDerivatives', async ({
  page,
}) => {
  const n = (await villages(page)).length;
  const status = page.locator('.step-status');
  await expect(status).toHaveText(
    `Step 0/${2 * n + 1}: The ${n} villages P₀ … P${[...String(n - 1)].map((d) => '₀₁₂₃₄₅₆₇₈₉'[Number(d)]).join('')}, in the order the road visits them`,
  );
  await page.keyboard.press('PageDown');
  await expectHash(page, 'step', (v) => v === '1');
  await expect(swept(page)).toHaveCount(0);
  await expect(fixed(page)).toHaveCount(0);
  const system = page.getByRole('table', { name: 'Tridiagonal system' });
  // Before the sweep the rows are the lecture's [2 1], [1 4 1], …, [1 2].
  await expect(system.getByRole('row', { name: /^row 0 / })).toContainText(/2\s+1/, {
    useInnerText: true,
  });
  await expect(system.getByRole('row', { name: /^row 1 / })).toContainText(/1\s+4\s+1/, {
    useInnerText: true,
  });
  for (let k = 2; k <= 2 * n + 1; k++) {
    await page.keyboard.press('PageDown');
    await expectHash(page, 'step', (v) => v === String(k));
    const s = k - 1;
    if (s <= n) {
      await expect(swept(page)).toHaveCount(s);
      await expect(fixed(page)).toHaveCount(0);
      await expect(system.locator('tr.current')).toHaveAttribute('data-row', String(s - 1));
      await expect(status).toHaveText(
        `Step ${k}/${2 * n + 1}: Forward sweep: row ${s - 1} becomes [1 γ | Γ]`,
      );
    } else {
      await expect(swept(page)).toHaveCount(n);
      await expect(fixed(page)).toHaveCount(s - n);
      await expect(system.locator('tr.current')).toHaveAttribute('data-row', String(2 * n - s));
    }
    if (k === 8) {
      await snapshot(page, 'road-normal-step8');
      await page.keyboard.press('p');
      await expect(page.locator('.caption-formula .katex')).toBeVisible();
      await snapshot(page, 'road-projector-step8');
      await page.keyboard.press('p');
    }
  }
  const v = await villages(page);
  const expected = [0, 1].map((d) => naturalCubicDerivatives(v.map((p) => p[d])));
  for (let i = 0; i < n; i++) {
    const gradients = page.getByRole('table', { name: 'Gradients found' });
    const cells = await gradients.locator(`tr[data-row="${i}"] td`).allTextContents();
    const [dx, dy] = cells.map(readNumber);
    expect(Math.abs(dx - expected[0][i])).toBeLessThanOrEqual(0.0005);
    expect(Math.abs(dy - expected[1][i])).toBeLessThanOrEqual(0.0005);
  }
  // Past the last step the clicker opens the next scene at its first step.
  await page.keyboard.press('PageDown');
  await expectHash(page, 'scene', (v) => v === 'compare');
  await expectHash(page, 'step', (v) => v === '0');
});

test('the ring road closes smoothly: the last segment meets the first with equal gradient and curvature', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Villages round a lake' }).click();
  await expectHash(page, 'road', (v) => v === 'ring');
  // The cyclic system, then the seven segments one a step: the whole ring at step 8.
  await page.keyboard.press('End');
  await expectHash(page, 'step', (v) => v === '8');
  const n = (await villages(page)).length;
  const slider = page.getByRole('slider', { name: 'p̄ along the road' });
  await slider.fill(String(n - 0.5));
  await expect(page.getByText(`Segment ${n - 1}: from P${subscript(n - 1)} to P₀`)).toBeVisible();
  const last = await segmentCoefficients(page);
  await slider.fill('0.5');
  await expect(page.getByText('Segment 0: from P₀ to P₁')).toBeVisible();
  const first = await segmentCoefficients(page);
  for (let d = 0; d < 2; d++) {
    const [a, b, c, e] = last[d];
    // Position, gradient and second derivative at p = 1 of the last segment and p = 0 of the first.
    expect(a + b + c + e).toBeCloseTo(first[d][0], 2);
    expect(b + 2 * c + 3 * e).toBeCloseTo(first[d][1], 2);
    expect(2 * c + 6 * e).toBeCloseTo(2 * first[d][2], 2);
  }
  await snapshot(page, 'road-ring');
});

test('500 villages load from a short enough link and a drag completes', async ({ page }) => {
  await page.getByRole('button', { name: 'Valley: 500 villages' }).click();
  await expectHash(page, 'v', (v) => v.split(';').length === 500);
  // The solve of 500 rows in chunks of 56: the system, 9 sweeps, 9 substitutions.
  await page.keyboard.press('End');
  await expectHash(page, 'step', (v) => v === '19');
  await expect(page.locator('.step-status')).toHaveText(
    /^Step 19\/19: Back substitution reaches D₀/,
  );
  const query = new URL(page.url()).hash;
  expect(query.length).toBeLessThan(20_000);
  // Only a few rows of the 500-row system are drawn.
  const rows = await page.locator('table[aria-label="Tridiagonal system"] tr[data-row]').count();
  expect(rows).toBeLessThan(20);
  await expect(
    page.getByRole('table', { name: 'Tridiagonal system' }).getByText(/494 more rows/),
  ).toBeVisible();
  const before = (await linkState(page)).v.split(';')[250];
  await drag(page, /^P250 at/, 25, 25);
  await expectHash(page, 'v', (v) => v.split(';')[250] !== before);
  // Reloading the link gives the same villages (the preset is seeded, not random).
  const link = page.url();
  await page.goto('./#/');
  await page.goto(link);
  await expectHash(page, 'v', (v) => v.split(';').length === 500);
  await snapshot(page, 'road-valley-500');
});

test('villages on one spot, in a line, or only two still draw a road and say why', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Two villages on one spot' }).click();
  await expect(page.getByRole('note').getByText(/on top of each other \(P₂ = P₃\)/)).toBeVisible();
  await page.getByRole('button', { name: 'Villages in a line' }).click();
  await expect(page.getByRole('note').getByText(/All villages lie on one line/)).toBeVisible();
  await page.getByRole('button', { name: 'Two villages', exact: true }).click();
  await expect(page.getByRole('note').getByText(/Two villages: one segment/)).toBeVisible();
  await expect(page.getByRole('button', { name: 'Remove the last village' })).toBeDisabled();
  // The ring road cannot be drawn through two villages, and says so.
  await page.getByRole('radio', { name: 'Ring road: a closed spline' }).check();
  await expect(page.getByText('A ring road needs at least three villages.')).toBeVisible();
  await snapshot(page, 'road-two-villages-ring');
});
