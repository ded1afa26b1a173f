import type { Page } from '@playwright/test';
import { expect, inLecturesLetter, LECTURE_LETTER_LESSONS, settled, test } from './fixtures';
import bSplines from './practice/b-splines';
import bezierProperties from './practice/bezier-properties';
import bezierSplines from './practice/bezier-splines';
import blending from './practice/blending';
import curvature from './practice/curvature';
import deCasteljau from './practice/de-casteljau';
import hermite from './practice/hermite';
import lagrange from './practice/lagrange';
import quadratic from './practice/quadratic';
import raster from './practice/raster';
import road from './practice/road';
import surface from './practice/surface';
import type { PracticeCase } from './practice/types';

/**
 * Every exercise of every lesson, solved as a student on a phone solves it:
 * opened by its link, its numbers read in the prompt, the answer (worked out
 * by hand in the data files, never by the app) tapped, typed or dragged with
 * a finger, and Check says "Correct"; a wrong number gets a hint first.
 */
const LESSONS: Record<string, readonly PracticeCase[]> = {
  'de-casteljau': deCasteljau,
  blending,
  'bezier-properties': bezierProperties,
  quadratic,
  lagrange,
  hermite,
  road,
  'bezier-splines': bezierSplines,
  'b-splines': bSplines,
  curvature,
  surface,
  raster,
};

test.use({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });

type Probe = { screen: [number, number] | null; handle: number[] | null } | null;

/** A figure's point on the screen, and a handle's place in the figure (the app's own hook). */
function probe(page: Page, figure: string, point: readonly number[] | null, id: string | null) {
  return page.evaluate(
    ([figure, point, id]) =>
      (
        window as unknown as {
          splineLab: { probe(f: string, p: readonly number[] | null, id: string | null): Probe };
        }
      ).splineLab.probe(figure, point, id),
    [figure, point, id] as const,
  );
}

/** A finger's drag, through Chromium's own input pipeline (real touch pointer events). */
async function touchDrag(page: Page, from: [number, number], to: [number, number]) {
  const cdp = await page.context().newCDPSession(page);
  const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', [x, y]: [number, number]) =>
    cdp.send('Input.dispatchTouchEvent', {
      type,
      touchPoints: type === 'touchEnd' ? [] : [{ x, y }],
    });
  await touch('touchStart', from);
  for (let i = 1; i <= 8; i++)
    await touch('touchMove', [
      from[0] + ((to[0] - from[0]) * i) / 8,
      from[1] + ((to[1] - from[1]) * i) / 8,
    ]);
  await touch('touchEnd', to);
  await cdp.detach();
}

/** Moves a handle to `to` (figure coordinates): a finger's drag in the plane, the arrow keys in space. */
async function move(page: Page, figure: string, handle: string, to: readonly [number, number]) {
  const proxy = page.locator(`.figure[data-figure="${figure}"] [data-handle="${handle}"]`);
  const start = await probe(page, figure, null, handle);
  expect(start?.handle, `handle ${handle} of ${figure}`).toBeTruthy();
  if (start!.handle!.length === 3) {
    // In space a finger moves a point in the plane facing the eye: the keys
    // move it along x and y exactly, as a student with a keyboard does.
    await proxy.focus();
    for (const [axis, more, less] of [
      [0, 'ArrowRight', 'ArrowLeft'],
      [1, 'ArrowUp', 'ArrowDown'],
    ] as const) {
      for (let i = 0; i < 200; i++) {
        const now = (await probe(page, figure, null, handle))!.handle!;
        if (Math.abs(now[axis] - to[axis]) < 1e-9) break;
        await page.keyboard.press(now[axis] < to[axis] ? more : less);
        await settled(page);
      }
    }
    return;
  }
  await proxy.scrollIntoViewIfNeeded();
  const box = (await proxy.boundingBox())!;
  const target = (await probe(page, figure, [...to], null))!.screen!;
  await touchDrag(page, [box.x + box.width / 2, box.y + box.height / 2], target);
  await settled(page);
}

const card = (page: Page) => page.locator('section.practice');
const result = (page: Page) => card(page).locator('.practice-result');

for (const [slug, cases] of Object.entries(LESSONS)) {
  test(`${slug}: every exercise, solved by touch, is correct (and a wrong number gets a hint)`, async ({
    page,
  }) => {
    test.setTimeout(60_000);
    // The practice data of a lesson that follows the lecture notes is written in μ.
    if (LECTURE_LETTER_LESSONS.includes(slug)) await inLecturesLetter(page);
    expect(new Set(cases.map((c) => Object.keys(c.answer)[0])).size, 'one of each kind').toBe(3);
    for (const exercise of cases) {
      await page.goto(`./#/${slug}?ex=${exercise.id}&seed=${exercise.seed}`);
      await expect(card(page)).toBeVisible();
      await settled(page);
      const prompt = card(page).locator('.practice-prompt');
      for (const text of exercise.prompt) await expect(prompt).toContainText(text);
      await expect(page).toHaveURL(new RegExp(`ex=${exercise.id}&seed=${exercise.seed}(&|$)`));
      const answer = exercise.answer;
      const fields = card(page).locator('.practice-fields input');
      const check = card(page).getByRole('button', { name: 'Check' });
      if ('numbers' in answer) {
        for (const [i, value] of answer.wrong.entries()) await fields.nth(i).fill(String(value));
        await check.tap();
        await expect(result(page)).toHaveText(/^Not yet\. .+/);
        await expect(result(page)).toHaveClass(/wrong/);
        for (const [i, value] of answer.numbers.entries()) await fields.nth(i).fill(String(value));
      } else if ('point' in answer) {
        // The guess is a tap where the answer is, on the figure the card names.
        const id = (await card(page).locator('.practice-fields').getAttribute('data-figure'))!;
        const at = (await probe(page, id, [...answer.point], null))!.screen!;
        const tappable = await card(page).locator('.practice-help').textContent();
        if (/^Tap/.test(tappable ?? '')) {
          await page.touchscreen.tap(at[0], at[1]);
          await expect(fields.first()).not.toHaveValue('');
        } else {
          // A figure in space turns under the finger: the guess is typed.
          for (const [i, value] of answer.point.entries()) await fields.nth(i).fill(String(value));
        }
      } else {
        // Not yet made: Check says what is still off.
        await check.tap();
        await expect(result(page)).toHaveClass(/wrong/);
        for (const step of answer.moves) await move(page, step.figure, step.handle, step.to);
      }
      await check.tap();
      await expect(result(page)).toHaveText(/^Correct/);
      await expect(result(page)).toHaveClass(/right/);
    }
    // The gallery shows what was solved on this device.
    await page.goto('./#/');
    await expect(page.locator(`.card[data-slug="${slug}"] .card-progress`)).toHaveText(
      `Practice: all ${cases.length} solved ✓`,
    );
  });
}

test('Show me walks the working to its last step and gives the answer; New numbers gives another seed; the card works by keyboard', async ({
  page,
}) => {
  // de Casteljau, seed 2: P₂,₀ at t = 0.3 is (0.36, 1.69) (worked in practice/de-casteljau.ts).
  await page.goto('./#/de-casteljau?ex=level-point&seed=2');
  await expect(card(page)).toBeVisible();
  // The question folds the lesson's text away (its tables would give the answer).
  await expect(page.locator('aside.panel .presets')).toBeHidden();
  await card(page).getByRole('button', { name: 'Show me' }).tap();
  await expect(result(page)).toHaveText(/The answer: 0\.36, 1\.69\.$/);
  await expect(page.locator('.step-status')).toHaveText(/^Step 5\/5/);
  await expect(page.locator('aside.panel .presets')).toBeVisible();
  // By keyboard: Tab into the fields, type, Enter checks.
  await card(page).locator('.practice-fields input').first().focus();
  await page.keyboard.type('0.36');
  await page.keyboard.press('Tab');
  await page.keyboard.type('1,69');
  await page.keyboard.press('Enter');
  await expect(result(page)).toHaveText(/^Correct/);
  await expect(result(page)).toHaveAttribute('aria-live', 'polite');
  await card(page).getByRole('button', { name: 'New numbers' }).tap();
  await expect(page).not.toHaveURL(/seed=2(&|$)/);
  await expect(page).toHaveURL(/ex=level-point&seed=\d+&/);
  await expect(result(page)).toHaveText('');
});

test('a link to an exercise that does not exist opens the lesson with a notice', async ({
  page,
}) => {
  await page.goto('./#/de-casteljau?ex=nope&seed=4');
  await expect(page.locator('.notice')).toContainText('"nope" is not an exercise of this lesson');
  await expect(card(page)).toBeHidden();
  await expect(page.getByRole('button', { name: 'Practice' })).toBeVisible();
});
