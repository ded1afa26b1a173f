import type { Page } from '@playwright/test';
import { chordDeviation, flatteningTree, type Point } from '../../src/math';
import { expect, expectHash, snapshot, test, linkState } from './fixtures';

const figure = (page: Page, id: string) => page.locator(`canvas[data-figure="${id}"]`);
const pixels = (page: Page, id: string) =>
  figure(page, id).evaluate((c: HTMLCanvasElement) => c.toDataURL());
const pointsOf = (value: string): Point[] =>
  decodeURIComponent(value)
    .split(';')
    .map((q) => q.split(',').map(Number));
const row = (page: Page, polyline: string) =>
  page
    .getByRole('table', { name: 'Uniform against adaptive' })
    .locator(`tr[data-polyline="${polyline}"]`);
const numberOf = async (page: Page, polyline: string, key: 'segments' | 'gap') =>
  Number(await row(page, polyline).getAttribute(`data-${key}`));

test.beforeEach(async ({ page }) => {
  await page.goto('./#/raster');
  await expect(figure(page, 'curve')).toBeVisible();
});

test('adaptive flattening stays below the tolerance with fewer segments than uniform sampling for the same gap', async ({
  page,
}) => {
  await page.locator('[data-scene="compare"]').click();
  await expectHash(page, 'x', (v) => v === 'compare');
  const tolerance = page.getByRole('slider', { name: 'Tolerance τ in pixels' });
  for (const tol of [0.5, 0.2, 1.5]) {
    await tolerance.fill(String(tol));
    await expectHash(page, 'tol', (v) => v === String(tol));
    await expect(row(page, 'adaptive')).toContainText(`τ = ${tol.toFixed(2)} px`);
    const gap = await numberOf(page, 'adaptive', 'gap');
    const adaptive = await numberOf(page, 'adaptive', 'segments');
    expect(gap).toBeLessThanOrEqual(tol);
    expect(await numberOf(page, 'same', 'gap')).toBeLessThanOrEqual(gap);
    expect(adaptive).toBeLessThan(await numberOf(page, 'same', 'segments'));
    // The page's numbers are the maths' own, for the curve in the link (zoom 1: units are pixels).
    const p = pointsOf((await linkState(page)).p);
    const leaves = flatteningTree(p, tol).filter((node) => !node.split);
    expect(adaptive).toBe(leaves.length);
    const own = chordDeviation(p, [0, ...leaves.map((node) => node.t1)]).distance;
    expect(Math.abs(gap - own)).toBeLessThan(1e-9);
  }
  await page.keyboard.press('p');
  await page.keyboard.press('End');
  await expect(page.locator('.caption')).toContainText('to be sure of τ');
  await snapshot(page, 'raster-compare-presenter');
});

test('a rasterised segment is an 8-connected path from end pixel to end pixel, one pixel per step along the major axis', async ({
  page,
}) => {
  await page.locator('[data-scene="pixels"]').click();
  await expectHash(page, 'x', (v) => v === 'pixels');
  const table = page.getByRole('table', { name: 'Pixels of the segment' });
  const title = page.getByText(/^Segment \d+ runs from/);
  const first = Number(/^Segment (\d+)/.exec(await title.innerText())![1]);
  for (let round = 0; round < 3; round++) {
    // The panel writes the title and the table in one update, a frame after
    // the click: wait for this round's segment, then read both at once, so
    // the rows and the ends are of the same segment.
    await expect(title).toHaveText(new RegExp(`^Segment ${first + round} runs from`));
    await expect(table.locator('tbody tr').first()).toBeVisible();
    const { rows, from, to } = await table.evaluate((element) => {
      const ends = document.querySelector<HTMLElement>('[data-from][data-to]')!.dataset;
      return {
        rows: [...element.querySelectorAll('tbody tr')].map((tr) =>
          [...tr.querySelectorAll('td')].map((td) =>
            Number(td.textContent!.replace(/\u2212/g, '-')),
          ),
        ),
        from: ends.from!.split(',').map(Number),
        to: ends.to!.split(',').map(Number),
      };
    });
    const path = rows.map((cells) => [cells[1], cells[2]]);
    expect(path[0]).toEqual(from.map(Math.round));
    expect(path[path.length - 1]).toEqual(to.map(Math.round));
    const run = to.map(Math.round).map((v, d) => Math.abs(v - path[0][d]));
    const major = run[0] >= run[1] ? 0 : 1;
    expect(path).toHaveLength(Math.max(...run) + 1);
    for (let k = 1; k < path.length; k++) {
      const step = [0, 1].map((d) => Math.abs(path[k][d] - path[k - 1][d]));
      expect(Math.max(...step), `pixels ${k - 1} and ${k} are 8-neighbours`).toBe(1);
      expect(step[major], `step ${k} moves one pixel along the major axis`).toBe(1);
    }
    await page.getByRole('button', { name: 'Next segment ▶' }).click();
  }
  // The clicker lights the pixels a few at a time, to the whole curve.
  const before = await pixels(page, 'side');
  await page.keyboard.press('PageDown');
  await page.keyboard.press('PageDown');
  await expectHash(page, 'step', (v) => v === '2');
  await expect.poll(() => pixels(page, 'side')).not.toBe(before);
  await page.keyboard.press('End');
  await expect(
    page.getByText(/Every segment drawn the same way: \d+ pixels make the curve/),
  ).toBeVisible();
});

test('the clicker walks every scene from its first step to its last, in presenter view', async ({
  page,
}) => {
  await page.keyboard.press('p');
  // The lecturer's controls (Next) are off the projected picture until M.
  await page.keyboard.press('m');
  const scenes = await page
    .locator('[data-scene]')
    .evaluateAll((buttons) => buttons.map((b) => (b as HTMLElement).dataset.scene!));
  expect(scenes).toEqual(['plot', 'compare', 'subdivide', 'pixels', 'coverage', 'zoom']);
  const next = page.getByRole('button', { name: 'Next ▶' });
  for (const scene of scenes) {
    await expectHash(page, 'scene', (v) => v === scene);
    await expectHash(page, 'step', (v) => v === '0');
    const first = await pixels(page, 'curve');
    let presses = 0;
    // Step to the scene's last step (the next press opens the next scene).
    while (presses < 25) {
      const status = await page.locator('.step-status').innerText();
      const [k, count] = /Step (\d+)\/(\d+)/.exec(status)!.slice(1).map(Number);
      if (k === count) break;
      await page.keyboard.press('PageDown');
      await expect(page.locator('.step-status')).toContainText(`Step ${k + 1}/${count}`);
      presses++;
    }
    expect(presses).toBeGreaterThan(0);
    expect(presses).toBeLessThanOrEqual(20);
    await expect(page.locator('.caption')).not.toBeEmpty();
    const both = [await pixels(page, 'curve'), await pixels(page, 'side')];
    if (scene !== 'compare' && scene !== 'subdivide' && scene !== 'zoom')
      expect(both[0]).not.toBe(first);
    await snapshot(page, `raster-presenter-${scene}`);
    if (scene === 'zoom') await expect(next).toBeDisabled();
    else await page.keyboard.press('PageDown');
  }
});

test('moving a control point redraws both figures and keeps the numbers in step with the link', async ({
  page,
}) => {
  await page.locator('[data-scene="compare"]').click();
  const before = [await pixels(page, 'curve'), await pixels(page, 'side')];
  const p5 = page.getByRole('button', { name: /^P5 at/ });
  await p5.focus();
  await page.keyboard.press('Shift+ArrowLeft');
  await expectHash(page, 'p', (v) => pointsOf(v)[5][0] < 31);
  await expect.poll(() => pixels(page, 'side')).not.toBe(before[1]);
  expect(await pixels(page, 'curve')).not.toBe(before[0]);
  const p = pointsOf((await linkState(page)).p);
  const leaves = flatteningTree(p, 0.5).filter((node) => !node.split);
  await expect.poll(() => numberOf(page, 'adaptive', 'segments')).toBe(leaves.length);
  // A link with the state opens the same picture and numbers.
  const other = await page.context().newPage();
  await other.goto(page.url());
  await expect(other.locator('tr[data-polyline="adaptive"]')).toHaveAttribute(
    'data-gap',
    (await row(page, 'adaptive').getAttribute('data-gap'))!,
  );
  await other.close();
});

test('the number of uniform segments is shown as a whole number, the one the figure draws', async ({
  page,
}) => {
  // A link may hold a value between whole numbers (6.4 from a Play paused midway): the
  // figure draws the nearest whole number of segments, 6, and the field says so.
  await page.goto('./#/raster?x=compare&n=6.4');
  const field = page.getByRole('spinbutton', { name: 'n value' });
  const slider = page.getByRole('slider', { name: 'n', exact: true });
  await expect(field).toHaveValue('6');
  await expect(slider).toHaveAttribute('aria-valuetext', 'n = 6');
  expect(await numberOf(page, 'uniform', 'segments')).toBe(6);
  await slider.fill('9');
  await expectHash(page, 'n', (v) => v === '9');
  await expect(field).toHaveValue('9');
  expect(await numberOf(page, 'uniform', 'segments')).toBe(9);
});

test('a link written by hand opens the scene it shows: its caption, its button and its next press', async ({
  page,
}) => {
  // "x=compare" sets the comparison's state; without "scene=" the page must
  // still say it is the comparison, scene 2 of 6, not the first scene.
  await page.goto('./#/raster?x=compare&step=4');
  await page.keyboard.press('p');
  await expect(page.locator('.caption-scene')).toContainText('scene 2/6, step 4/');
  await expectHash(page, 'scene', (v) => v === 'compare');
  await page.keyboard.press('m');
  await expect(page.locator('[data-scene="compare"]')).toHaveAttribute('aria-pressed', 'true');
  await expect(page.locator('[data-scene="plot"]')).toHaveAttribute('aria-pressed', 'false');
  // Back from step 0 is the scene before it, the plot at its last step.
  await page.keyboard.press('Home');
  await expectHash(page, 'step', (v) => v === '0');
  await page.keyboard.press('PageUp');
  await expectHash(page, 'scene', (v) => v === 'plot');
});
