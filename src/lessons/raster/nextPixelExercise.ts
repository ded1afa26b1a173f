/**
 * The exercise on segments to pixels: the next pixel a line rasteriser lights,
 * on a segment chosen so that the step asked about is a real decision.
 */
import {
  type ExerciseSpec,
  type Mistake,
  type Random,
  checkNumbers,
  random,
} from '../../kit/exercise';
import { pointWords, words } from '../../kit/format';
import type { Point } from '../../math';
import { sceneState } from './exerciseSetup';
import { lineSteps } from './raster';
import type { RasterState } from './state';

/** Pixels are whole numbers: the answer is exact. */
export const PIXEL_TOLERANCE = 0;

/**
 * A segment between pixel centres that lights 7 to 12 pixels (one press each
 * in the pixel scene), along x (left to right) or along y (bottom to top), and
 * a step k whose next pixel is a real decision: the ideal line crosses more
 * than half way to the next row (or column), so rounding and cutting off
 * differ, and never at a tie. Drawn again if no step decides.
 */
function pixelSegment(r: Random) {
  for (;;) {
    const run = r.int(6, 11);
    const rise = r.int(1, run - 1) * r.pick([1, -1]);
    const steep = r.next() < 0.5;
    // The raster's last pixel along the run and across it.
    const [alongEnd, acrossEnd] = steep ? [23, 31] : [31, 23];
    const start = r.int(1, alongEnd - run);
    const side = r.int(1 + Math.max(0, -rise), acrossEnd - Math.max(0, rise));
    const first: Point = steep ? [side, start] : [start, side];
    const last: Point = steep ? [side + rise, start + run] : [start + run, side + rise];
    const decisions = Array.from({ length: run - 1 }, (_, k) => k).filter(
      (k) => ((k + 1) * Math.abs(rise)) % run > run / 2,
    );
    if (decisions.length) return { first, last, k: r.pick(decisions) };
  }
}

export const nextPixel: ExerciseSpec<RasterState> = {
  id: 'next-pixel',
  title: 'Which pixel comes next?',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const { first, last, k } = pixelSegment(r);
    // A curve of degree 1, from pixel centre to pixel centre (pixel (i, j) is the unit square at (i, j)).
    const points: Point[] = [first, last].map(([i, j]) => [i + 0.5, j + 0.5]);
    // The plot scene: the segment without pixels (the pixel scene's table would list them all).
    const state = sceneState(defaults, 'plot', points);
    const { pixels, major } = lineSteps(points[0], points[1], 1);
    const [now, next] = [pixels[k], pixels[k + 1]];
    const answer = [...next];
    const along = major === 'x' ? 0 : 1;
    const across = 1 - along;
    const run = last[along] - first[along];
    const rise = last[across] - first[across];
    // The ideal line at the next step, and the wrong ways to make it a pixel.
    const ideal = first[across] + ((k + 1) * rise) / run;
    const pixelAt = (a: number, b: number) => (along === 0 ? [a, b] : [b, a]);
    const mistakes: Mistake[] = [
      {
        values: pixelAt(next[along], first[across] + Math.trunc(((k + 1) * rise) / run)),
        hint: `The ideal line crosses at ${major === 'x' ? 'y' : 'x'} = ${words(ideal)}: take the nearest ${major === 'x' ? 'row' : 'column'}, not the one it has passed.`,
      },
      {
        values: pixelAt(next[along], now[across]),
        hint: `Work out where the ideal line crosses ${major} = ${next[along]}, then take the nearest pixel across: it moves on here.`,
      },
      {
        values: pixelAt(now[along], now[across] + Math.sign(rise)),
        hint: `Step along the longer axis, ${major}: it changes by ${Math.abs(run)} pixels, the other by only ${Math.abs(rise)}.`,
      },
    ].filter((m) => m.values.some((v, d) => v !== answer[d]));
    return {
      state,
      prompt: `A line rasteriser draws the segment from pixel ${pointWords(first)} to pixel ${pointWords(last)}, one pixel per step. Which pixel does it light after ${pointWords(now)} (exact whole numbers)?`,
      task: {
        kind: 'number',
        fields: ['x', 'y'],
        tolerance: PIXEL_TOLERANCE,
        answer,
        check: (values) =>
          checkNumbers(
            values,
            answer,
            PIXEL_TOLERANCE,
            `Step ${major} by one, find where the ideal line through the end pixels crosses there, and round to the nearest pixel.`,
            mistakes,
          ),
      },
      // The raster, the end pixels, then one pixel per press with its ideal crossing and rounding.
      working: { ...state, view: 'pixels' },
    };
  },
};
