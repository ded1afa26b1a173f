// Checks the per-frame measurement before trusting it: the same traced drag
// over a page that does nothing should cost about nothing a frame, and over a
// page whose pointermove listener spins BUSY_MS, about BUSY_MS a frame. A
// third page is the reference every drag is compared with: a canvas of the
// same size stroking one long path per move.
import type { Browser } from '@playwright/test';
import { circlePath, tracedDrag, type DragLimits, type DragResult } from './drag';
import { freshContext, nextFrames } from './page';
import { BUSY_MS, REFERENCE_SEGMENTS } from './server';

export interface MethodCheck {
  readonly page: string;
  readonly expected: string;
  readonly result: DragResult;
}

export async function checkMethod(
  browser: Browser,
  base: string,
  limits: DragLimits,
): Promise<MethodCheck[]> {
  const pages = [
    { file: 'idle.html', page: 'idle page (no listeners)', expected: '≈ 0 + harness' },
    {
      file: 'busy.html',
      page: `busy page (pointermove spins ${BUSY_MS} ms)`,
      expected: `idle + ${BUSY_MS}`,
    },
    {
      file: 'reference.html',
      page: `reference page (strokes ${REFERENCE_SEGMENTS} segments a move)`,
      expected: 'the ratios below divide by its p95',
    },
  ];
  const checks: MethodCheck[] = [];
  for (const { file, page: name, expected } of pages)
    checks.push({ page: name, expected, result: await dragCheckPage(browser, base, file, limits) });
  return checks;
}

/**
 * The reference page's drag, measured again beside each lesson's: a machine
 * whose speed drifts through a run (another process, its clock) moves both
 * figures of a ratio alike, not one of them.
 */
export function referenceDrag(
  browser: Browser,
  base: string,
  limits: DragLimits,
): Promise<DragResult> {
  return dragCheckPage(browser, base, 'reference.html', limits);
}

async function dragCheckPage(
  browser: Browser,
  base: string,
  file: string,
  limits: DragLimits,
): Promise<DragResult> {
  const context = await freshContext(browser, { watchFigure: false });
  try {
    const page = await context.newPage();
    await page.goto(`${base}__bench/${file}`);
    for (let i = 0; i < 5; i++) await nextFrames(page);
    return await tracedDrag(
      browser,
      page,
      circlePath([960, 540], [960, 0], limits.frames),
      { selector: 'body', index: 0, property: 'transform' },
      limits,
    );
  } finally {
    await context.close();
  }
}
