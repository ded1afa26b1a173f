import type { Page } from '@playwright/test';
import {
  expect,
  expectHash,
  hashState,
  snapshot,
  test,
  linkState,
  inLecturesLetter,
  settled,
  readNumber,
  sceneIds,
} from './fixtures';

// This lesson follows the lecture notes, and its tests read its text in their letter, μ.
test.beforeEach(({ page }) => inLecturesLetter(page));

const patches = (page: Page) => page.locator('canvas[data-figure="patches"]');
const basis = (page: Page) => page.locator('canvas[data-figure="basis"]');
const pixels = (page: Page) =>
  Promise.all(
    [patches(page), basis(page)].map((c) => c.evaluate((e: HTMLCanvasElement) => e.toDataURL())),
  ).then((all) => all.join('|'));
const list = (value: string) => value.split(';').map((q) => q.split(',').map(Number));

/** a0 … a3 of the chosen patch as the page prints them. */
async function coefficients(page: Page): Promise<number[][]> {
  const table = page.getByRole('table', { name: 'Coefficients of the patch' });
  const rows = [];
  for (const k of [0, 1, 2, 3]) {
    const cells = await table
      .getByRole('row', { name: new RegExp(`^a${k} `) })
      .locator('td')
      .allInnerTexts();
    rows.push([readNumber(cells[1]), readNumber(cells[2])]);
  }
  return rows;
}

/** Equation 7's solution read back into equation 6: a0 = P_i, a1 = D_i, Σ a_k = P_i+1, a1 + 2a2 + 3a3 = D_i+1 (to the 4 decimals shown). */
async function expectEquation7(page: Page, i: number, D: number[][]) {
  const p = list((await linkState(page)).p);
  await expect
    .poll(async () => {
      const [a0, a1, a2, a3] = await coefficients(page);
      return [0, 1].every(
        (d) =>
          Math.abs(a0[d] - p[i][d]) < 1e-4 &&
          Math.abs(a1[d] - D[i][d]) < 1e-4 &&
          Math.abs(a0[d] + a1[d] + a2[d] + a3[d] - p[i + 1][d]) < 4e-4 &&
          Math.abs(a1[d] + 2 * a2[d] + 3 * a3[d] - D[i + 1][d]) < 6e-4,
      );
    })
    .toBe(true);
}

// The whole construction of the first scene's patch (step 7 of 7): gradients, conditions, patch, basis, P(μ).
test.beforeEach(async ({ page }) => {
  await page.goto('./#/hermite?step=7');
  await expect(patches(page)).toBeVisible();
});

test('dragging a gradient tip sets D = 3 × (tip − P), and the matrix solve follows', async ({
  page,
}) => {
  await expectEquation7(page, 0, list((await linkState(page)).d));
  const before = await pixels(page);
  const tip = page.getByRole('button', { name: /^D0 at \(1\.00, 1\.50\)/ });
  const box = (await tip.boundingBox())!;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 60, y - 30, { steps: 5 });
  await page.mouse.up();
  await expectHash(page, 'd', (v) => v.split(';')[0] !== '3,4.5');
  // The tip is announced where it is drawn, P0 + D0/3. On a busy machine the
  // link may first be written mid-drag, so wait until link and tip agree.
  const tipName = () => {
    const d = list(hashState(page).d)[0];
    return `D0 at (${(d[0] / 3).toFixed(2)}, ${(d[1] / 3).toFixed(2)})`;
  };
  await expect.poll(() => page.getByRole('button', { name: tipName() }).count()).toBe(1);
  const D = list((await linkState(page)).d);
  expect(D[0][0]).toBeGreaterThan(3);
  expect(D[0][1]).toBeGreaterThan(4.5);
  await expectEquation7(page, 0, D);
  expect(await pixels(page)).not.toBe(before);
  await snapshot(page, 'hermite-dragged-gradient');
});

test('while a point is dragged the basis plot is left as it is, and the formulas’ MathML catches up on release', async ({
  page,
}) => {
  await settled(page);
  // Count the figures' draws: a canvas is drawn through getContext, and only then.
  await page.evaluate(() => {
    for (const canvas of document.querySelectorAll<HTMLCanvasElement>('canvas[data-figure]')) {
      const get = canvas.getContext.bind(canvas);
      canvas.dataset.draws = '0';
      canvas.getContext = ((...args: Parameters<typeof get>) => {
        canvas.dataset.draws = String(Number(canvas.dataset.draws) + 1);
        return get(...args);
      }) as typeof canvas.getContext;
    }
  });
  const draws = (figure: string) =>
    page
      .locator(`canvas[data-figure="${figure}"]`)
      .evaluate((c: HTMLCanvasElement) => Number(c.dataset.draws));
  const p0 = (await linkState(page)).p.split(';')[0];
  const point = page.getByRole('button', { name: /^P0 at/ });
  const box = (await point.boundingBox())!;
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.mouse.move(x, y);
  await page.mouse.down();
  // Taking the point changes what the pointer is over: every figure is drawn once for that.
  await page.mouse.move(x + 5, y + 5);
  await expect.poll(() => draws('patches')).toBeGreaterThan(0);
  const basisBefore = await draws('basis');
  const patchesBefore = await draws('patches');
  await page.mouse.move(x + 60, y - 40, { steps: 6 });
  await expect.poll(() => draws('patches')).toBeGreaterThan(patchesBefore);
  // H0 … H3 do not depend on the points: the plot was not drawn again.
  expect(await draws('basis')).toBe(basisBefore);
  await page.mouse.up();
  await expectHash(page, 'p', (v) => v.split(';')[0] !== p0);
  expect(await page.locator('aside .formula.live [data-slot]').count()).toBeGreaterThan(4);
  // Every live formula's copy for assistive tools and copying says the numbers it shows.
  const disagreeing = () =>
    page.locator('aside .formula.live').evaluateAll((all) =>
      all.flatMap((formula) => {
        const tex = (formula.querySelector('annotation')?.textContent ?? '').replace(/-/g, '−');
        // Each number shown is in the TeX as often (a matrix's HTML goes column by column).
        const inTex = tex.match(/−?\d+(?:\.\d+)?/g) ?? [];
        const shown = [...formula.querySelectorAll('[data-slot]')].map((s) => s.textContent ?? '');
        const count = (all: string[], text: string) => all.filter((t) => t === text).length;
        const missing = shown.filter((text) => count(shown, text) > count(inTex, text));
        if (missing.length) return [`${missing.join(', ')} not in ${tex}`];
        return [];
      }),
    );
  await expect.poll(disagreeing).toEqual([]);
  // A change of μ does change the plot.
  const basisNow = await draws('basis');
  await page.getByRole('slider', { name: 'μ' }).fill('0.8');
  await expect.poll(() => draws('basis')).toBeGreaterThan(basisNow);
});

test('a gradient tip moves with the keyboard too', async ({ page }) => {
  await page.getByRole('button', { name: /^D1 at/ }).focus();
  await page.keyboard.press('ArrowUp');
  await expectHash(page, 'd', (v) => v.split(';')[1] !== '3,-4.5');
  expect(list((await linkState(page)).d)[1][1]).toBeGreaterThan(-4.5);
  await expectEquation7(page, 0, list((await linkState(page)).d));
});

test('the basis cursor shows H0…H3 at μ and what each weighs', async ({ page }) => {
  await page.getByRole('slider', { name: 'μ' }).fill('0.5');
  await expectHash(page, 'mu', (v) => v === '0.5');
  // At μ = 1/2: H0 = H1 = 1/2, H2 = 1/8, H3 = −1/8.
  const weights = page.getByRole('table', { name: 'Hermite weights at μ' });
  for (const [k, value, weighs] of [
    [0, '0.5000', 'P₀'],
    [1, '0.5000', 'P₁'],
    [2, '0.1250', 'D₀'],
    [3, '−0.1250', 'D₁'],
  ]) {
    const row = weights.getByRole('row', { name: new RegExp(`^H${'₀₁₂₃'[Number(k)]} `) });
    await expect(row).toContainText(String(value));
    await expect(row).toContainText(String(weighs));
  }
  const cursor = page.getByRole('button', { name: /^μ at/ });
  await cursor.focus();
  await page.keyboard.press('ArrowRight');
  await expectHash(page, 'mu', (v) => Number(v) > 0.5);
});

test('Catmull-Rom: gradients from the neighbours, C1 joins measured on the patches', async ({
  page,
}) => {
  await page.getByRole('button', { name: 'Several points, Catmull-Rom' }).click();
  await expectHash(page, 'mode', (v) => v === 'catmull-rom');
  await page.keyboard.press('End');
  await expectHash(page, 'step', (v) => v === '10');
  await expect(page.getByRole('heading', { name: /^Patch 2 of 4/ })).toBeVisible();
  const joins = page.getByRole('table', { name: 'Joins' });
  for (const k of [1, 2, 3]) {
    const row = joins.getByRole('row', { name: new RegExp(`^P${'₀₁₂₃'[k]} `) });
    await expect(row).toContainText(/C¹|C²/);
  }
  // D2 = (P3 − P1) / 2 = ((6.5 − 2) / 2, (−1 − 2) / 2), drawn at P2 + D2/3.
  const p = list((await linkState(page)).p);
  const tip = [p[2][0] + (p[3][0] - p[1][0]) / 6, p[2][1] + (p[3][1] - p[1][1]) / 6];
  await expect(
    page.getByRole('button', { name: `D2 at (${tip[0].toFixed(2)}, ${tip[1].toFixed(2)})` }),
  ).toBeVisible();
  // The end gradients are zero: the tips sit on the points.
  await expect(page.getByRole('button', { name: 'D0 at (0.00, 0.00)' })).toBeVisible();
  const i = 1;
  const D = p.map((_, k) =>
    k === 0 || k === p.length - 1
      ? [0, 0]
      : [(p[k + 1][0] - p[k - 1][0]) / 2, (p[k + 1][1] - p[k - 1][1]) / 2],
  );
  await expectEquation7(page, i, D);
  // The next patch, chosen in the panel.
  await page.getByRole('button', { name: 'Next patch' }).click();
  await expect(page.getByRole('heading', { name: /^Patch 3 of 4/ })).toBeVisible();
  await expectEquation7(page, 2, D);
  // Dragging a tip switches to gradients by hand.
  await page.getByRole('button', { name: /^D2 at/ }).focus();
  await page.keyboard.press('ArrowUp');
  await expectHash(page, 'mode', (v) => v === 'hand');
  await expect(page.getByLabel(/^By hand/)).toBeChecked();
  await snapshot(page, 'hermite-catmull-rom');
});

test('two points in Catmull-Rom mode: zero gradients, and the figure says why', async ({
  page,
}) => {
  await page.getByLabel(/^From the neighbours/).check();
  await expectHash(page, 'mode', (v) => v === 'catmull-rom');
  await expect(page.getByText(/Two points have no neighbours/)).toBeVisible();
  // a2 = 3(P1 − P0) − 2D0 − D1 = (12, 0) with both gradients zero.
  await expect(
    page
      .getByRole('table', { name: 'Coefficients of the patch' })
      .getByRole('row', { name: /^a2 / }),
  ).toContainText('12.0000');
  await snapshot(page, 'hermite-two-points-catmull-rom');
});

test('the Bézier view lists B0…B3 at P ± D/3 and walks its own steps', async ({ page }) => {
  const before = await pixels(page);
  await page.getByLabel(/Show each patch as a Bézier curve/).check();
  await expectHash(page, 'bezier', (v) => v === '1');
  // Its own script, shown to its end: seven steps, the last P(μ) from either blend.
  await expectHash(page, 'step', (v) => v === '6');
  const status = page.locator('.step-status');
  await expect(status).toHaveText('Step 6/6: P(μ) from either blend is one point');
  // P0 = (0, 0), D0 = (3, 4.5) → B1 = (1, 1.5); P1 = (4, 0), D1 = (3, −4.5) → B2 = (3, 1.5).
  const controls = page.getByRole('table', { name: 'Bézier control points' });
  await expect(controls.getByRole('row', { name: /^B₁ / })).toHaveText(/B₁\s*1\.0000\s*1\.5000/);
  await expect(controls.getByRole('row', { name: /^B₂ / })).toHaveText(/B₂\s*3\.0000\s*1\.5000/);
  expect(await pixels(page)).not.toBe(before);
  // B1 is the tip of D0's arrow; B2 = (3, 1.5) is D1's tip (5, −1.5) mirrored through P1 = (4, 0).
  await expect(page.getByRole('button', { name: /^D0 at \(1\.00, 1\.50\)/ })).toBeVisible();
  await expect(page.getByRole('button', { name: /^D1 at \(5\.00, -1\.50\)/ })).toBeVisible();
  await page.keyboard.press('Home');
  await expect(status).toHaveText(
    'Step 0/6: A cubic Bézier curve: its control points B₀ … B₃ and their polygon',
  );
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await expect(status).toHaveText(
    "Step 2/6: The end legs are a third of the gradients: B₁ is the tip of D₀'s arrow, B₂ is D₁'s tip mirrored through P₁",
  );
  await snapshot(page, 'hermite-bezier');
});

test('points can be added and removed, gradients with them', async ({ page }) => {
  await page.getByRole('button', { name: 'Add a point' }).click();
  await expectHash(page, 'p', (v) => v.split(';').length === 3);
  expect((await linkState(page)).d.split(';').length).toBe(3);
  await expect(page.getByRole('table', { name: 'Joins' })).toBeVisible();
  await page.getByRole('button', { name: /^P2 at/ }).focus();
  await page.keyboard.press('Delete');
  await expectHash(page, 'p', (v) => v.split(';').length === 2);
  expect((await linkState(page)).d.split(';').length).toBe(2);
});

test('a link with too few gradients is repaired and says so', async ({ page }) => {
  await page.goto('./#/hermite?p=0,0;2,1;4,0;6,1&d=1,1;1,0');
  await expect(page.getByRole('status').getByText(/2 gradients for 4 points/)).toBeVisible();
  await expectHash(page, 'd', (v) => v.split(';').length === 4);
});

test('the script builds the patch from its points, and every scene steps from nothing', async ({
  page,
}) => {
  await page.goto('./#/hermite?step=0');
  const status = page.locator('.step-status');
  const captions = [
    'The points P₀ and P₁: where the curve must pass',
    'The gradients D₀ and D₁, set by hand (arrows drawn a third as long)',
    'Patch 1, from P₀ to P₁: its ends at μ = 0 and μ = 1 give four conditions on a₀ … a₃',
    'The four conditions as one matrix, the data in the order P₀, D₀, P₁, D₁',
    'Patch 1 of 1, from P₀ to P₁: the inverse matrix gives a₀ … a₃',
    'Read down the columns of the inverse: H₀ and H₁ weight the end points, and H₀ + H₁ = 1',
    'H₂ and H₃ weight the end gradients: H₂ is never negative, H₃ never positive',
    'P(μ) on patch 1: H₀P₀ + H₁P₁ + H₂D₀ + H₃D₁',
  ];
  // The matrix step writes the conditions of the step before as a matrix: the figure stays.
  const sameFigure = new Set([3]);
  await expect(page.getByRole('button', { name: /^D0 at/ })).toHaveCount(0);
  let previous = await pixels(page);
  for (const [k, caption] of captions.entries()) {
    if (k > 0) await page.keyboard.press('PageDown');
    await expect(status).toHaveText(`Step ${k}/7: ${caption}`);
    if (k > 0 && !sameFigure.has(k)) await expect.poll(() => pixels(page)).not.toBe(previous);
    previous = await pixels(page);
  }
  // The gradients' tips became handles at step 1.
  await expect(page.getByRole('button', { name: /^D0 at/ })).toHaveCount(1);
  // In presenter view the patch step's formula is the lecture's inverse matrix (equation 7) with its numbers.
  for (let k = 7; k > 4; k--) await page.keyboard.press('PageUp');
  await expect(status).toHaveText(`Step 4/7: ${captions[4]}`);
  await page.keyboard.press('p');
  await expect(page.locator('.caption-formula .katex')).toBeVisible();
  const tex = await page.locator('.caption-formula annotation').first().textContent();
  expect(tex).toContain('-3 & -2 & 3 & -1');
  // a2 = −3P0 − 2D0 + 3P1 − D1 = (3, −4.5) for the first scene's patch, worked out by hand.
  expect(tex).toContain('-4.5');
  await snapshot(page, 'hermite-script-patch-projector');
  // Every scene with the clicker alone, from step 0 to its last (at most 20 steps).
  // Away and back: the lesson opens afresh at the first scene.
  await page.goto('./#/');
  await page.goto('./#/hermite?scene=one&step=0');
  const ids = await sceneIds(page);
  if (!(await page.evaluate(() => document.documentElement.classList.contains('projector'))))
    await page.keyboard.press('p');
  for (const id of ids) {
    await expectHash(page, 'scene', (v) => v === id);
    await expectHash(page, 'step', (v) => v === '0');
    const first = await pixels(page);
    await snapshot(page, `hermite-projector-${id}-first`);
    await page.keyboard.press('End');
    await expect(status).toHaveText(/^Step (\d+)\/\1:/);
    expect(Number((await status.innerText()).match(/^Step (\d+)/)![1])).toBeLessThanOrEqual(20);
    expect(await pixels(page)).not.toBe(first);
    await snapshot(page, `hermite-projector-${id}-last`);
    await page.keyboard.press('PageDown');
  }
});

/** The pmatrix bodies of a TeX formula, each as rows of cells. */
function pmatrices(tex: string): string[][][] {
  return [...tex.matchAll(/\\begin\{pmatrix\}(.*?)\\end\{pmatrix\}/g)].map((m) =>
    m[1].split('\\\\').map((row) => row.split('&').map((cell) => cell.trim())),
  );
}

/** The numbers of a cell: "-4.500" → [−4.5], "(3,\ 4)" → [3, 4]. */
const numbersOf = (cell: string) =>
  [...cell.replace(/−/g, '-').matchAll(/-?\d+(?:\.\d+)?/g)].map((m) => Number(m[0]));

test('the panel’s matrix and its inverse are the lecture’s, and the inverse times the data is the patch', async ({
  page,
}) => {
  await page.goto('./#/hermite?scene=one&step=7');
  await settled(page);
  const texts = await page
    .locator('aside .katex annotation')
    .evaluateAll((all) => all.map((a) => a.textContent ?? ''));
  // Equation 6 as a matrix (the lecture notes' rows), then equation 7 with the patch's numbers.
  const conditions = texts.find((t) => t.includes('1 & 1 & 1 & 1'))!;
  expect(pmatrices(conditions)[0].map((row) => row.map(Number))).toEqual([
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [1, 1, 1, 1],
    [0, 1, 2, 3],
  ]);
  const inverted = texts.find((t) => t.includes('-3 & -2 & 3 & -1'))!;
  const [, inverse, data, coefficients] = pmatrices(inverted);
  const M = inverse.map((row) => row.map(Number));
  // The lecture notes' inverse, rows 1 0 0 0 / 0 1 0 0 / −3 −2 3 −1 / 2 1 −2 1.
  expect(M).toEqual([
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [-3, -2, 3, -1],
    [2, 1, -2, 1],
  ]);
  // The data in the lecture's order: P0 = (0, 0), D0 = (3, 4.5), P1 = (4, 0), D1 = (3, −4.5).
  const d = data.map((row) => row.flatMap(numbersOf));
  expect(d).toEqual([
    [0, 0],
    [3, 4.5],
    [4, 0],
    [3, -4.5],
  ]);
  // The inverse times the data, here, is the page's a0 … a3 (computed by the maths module).
  const a = coefficients.map((row) => row.flatMap(numbersOf));
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 2; c++) {
      const product = M[r].reduce((sum, m, k) => sum + m * d[k][c], 0);
      expect(a[r][c]).toBeCloseTo(product, 3);
    }
});
