import type { Page } from '@playwright/test';
import { naturalCubicDerivatives } from '../../src/math';
import { expect, expectHash, snapshot, test, linkState } from './fixtures';

const scene = (page: Page, name: string) =>
  page.getByRole('group', { name: 'Scenes' }).getByRole('button', { name, exact: true });
const joints = (page: Page) => page.getByRole('table', { name: 'Continuity at each joint' });
/** A joint's column heading, which carries its verdict (one column a joint). */
const verdict = (page: Page, joint: number) => joints(page).locator(`th[data-joint="${joint}"]`);
const points = (raw: string) => raw.split(';').map((p) => p.split(',').map(Number));

test.beforeEach(async ({ page }) => {
  await page.goto('./#/bezier-splines');
  await expect(page.locator('canvas[data-figure="main"]')).toBeVisible();
});

test('the inspector reads C² on the C² spline, C¹ on the quadratic one, and what Make G¹, Make C¹ and a corner give', async ({
  page,
}) => {
  await scene(page, 'Continuity inspector').click();
  await page.keyboard.press('End');
  await page.getByRole('button', { name: 'C² spline through the joints' }).click();
  for (const joint of [1, 2])
    await expect(verdict(page, joint)).toHaveAttribute('data-continuity', 'C2');

  await page.getByRole('button', { name: 'C¹ quadratic spline through the joints' }).click();
  for (const joint of [1, 2])
    await expect(verdict(page, joint)).toHaveAttribute('data-continuity', 'C1');

  // Pull c4, the point after joint 1, off the line by keyboard: only C⁰ is left.
  await page.getByRole('button', { name: /^c4 at/ }).focus();
  for (let i = 0; i < 6; i++) await page.keyboard.press('ArrowUp');
  await expect(verdict(page, 1)).toHaveAttribute('data-continuity', 'C0');
  await page.getByRole('button', { name: 'Make G¹ at joint 1' }).click();
  await expect(verdict(page, 1)).toHaveAttribute('data-continuity', 'G1');
  await page.getByRole('button', { name: 'Make C¹ at joint 1' }).click();
  await expect(verdict(page, 1)).toHaveAttribute('data-continuity', 'C1');

  await page.getByRole('button', { name: 'Sharp corner at joint 1' }).click();
  await expect(verdict(page, 1)).toHaveAttribute('data-continuity', 'C0');
  await expect(joints(page).locator('tr[data-quantity="verdict"] td').first()).toHaveText('C⁰');
  await expect(joints(page).locator('tr[data-quantity="ratio"] td').first()).toHaveText('—');
});

test('the solved (3n+1) system gives the natural cubic spline’s control points, residual below 1e-9', async ({
  page,
}) => {
  await scene(page, 'C² by a linear system').click();
  await page.keyboard.press('End');
  await expect(
    page.getByRole('table', { name: 'The linear system' }).locator('tbody tr'),
  ).toHaveCount(10);
  const residualOutput = page.locator('output[aria-label="Residual"]');
  // Read as a person reads it: 0, or a power of ten (3.6 × 10⁻¹⁶), never 3.6e-16.
  await expect(residualOutput).toHaveText(/^(0|\d\.\d × 10⁻[¹²³⁴⁵⁶⁷⁸⁹⁰]+)$/);
  const residual = Number(await residualOutput.getAttribute('data-exact'));
  expect(residual).toBeLessThan(1e-9);

  const p = points((await linkState(page)).p);
  const solved = await page
    .getByRole('table', { name: 'Solved control points' })
    .locator('tbody tr')
    .evaluateAll((rows) =>
      rows.map((r) => (r as HTMLElement).dataset.exact!.split(';')[0].split(',').map(Number)),
    );
  expect(solved).toHaveLength(3 * (p.length - 1) + 1);
  const [dx, dy] = [0, 1].map((d) => naturalCubicDerivatives(p.map((q) => q[d])));
  for (let i = 0; i + 1 < p.length; i++) {
    const expected = [
      p[i],
      [p[i][0] + dx[i] / 3, p[i][1] + dy[i] / 3],
      [p[i + 1][0] - dx[i + 1] / 3, p[i + 1][1] - dy[i + 1] / 3],
      p[i + 1],
    ];
    expected.forEach((q, k) => {
      expect(Math.abs(solved[3 * i + k][0] - q[0])).toBeLessThan(1e-9);
      expect(Math.abs(solved[3 * i + k][1] - q[1])).toBeLessThan(1e-9);
    });
  }
});

test('at the hairpin the uniform Catmull-Rom crosses itself and the centripetal one does not', async ({
  page,
}) => {
  await scene(page, 'Catmull-Rom').click();
  await page.keyboard.press('End');
  const rows = page
    .getByRole('table', { name: 'Self-intersections of the Catmull-Rom splines' })
    .locator('tbody tr');
  await expect(rows.nth(0).locator('td').last()).not.toHaveText('0');
  await expect(rows.nth(1).locator('td').last()).toHaveText('0');
});

test('dragging a point in one cell of the 3 × 3 grid moves it in the other cells of its row only', async ({
  page,
}) => {
  await scene(page, 'C⁰ · C¹ · C² grid').click();
  await page.keyboard.press('End');
  const before = await linkState(page);
  const handle = (cell: string) =>
    page.locator(`[data-figure="${cell}"]`).getByRole('button', { name: /^p2 at/ });
  await handle('spi-c1').focus();
  await page.keyboard.press('ArrowRight');
  await expectHash(page, 'spi', (v) => v !== '' && v !== before.spi);
  const name = await handle('spi-c1').getAttribute('aria-label');
  await expect(handle('spi-c0')).toHaveAttribute('aria-label', name!);
  await expect(handle('spi-c2')).toHaveAttribute('aria-label', name!);
  expect((await linkState(page)).inf ?? '').toBe(before.inf ?? '');
  await snapshot(page, 'bezier-splines-grid');
});

test('the clicker walks every scene from its first step to its last, in presenter view', async ({
  page,
}) => {
  await page.keyboard.press('p');
  const caption = page.locator('.step-caption');
  const scenes = ['why', 'quadratic', 'system', 'grid', 'inspector', 'catmull'];
  for (const id of scenes) {
    await expectHash(page, 'part', (v) => v === id || (id === 'why' && v === ''));
    await expect(caption).toHaveText(/^The |^Three|^The practical/);
    await page.keyboard.press('End');
    await snapshot(page, `bezier-splines-presenter-${id}`);
    await page.keyboard.press('PageDown');
  }
});
