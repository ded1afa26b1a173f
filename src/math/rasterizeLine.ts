import { checkNumber } from './validate';

// Line rasterisation for the raster lesson (Bresenham, "Algorithm for computer
// control of a digital plotter", IBM Systems Journal 4(1), 1965): after
// rounding both ends to pixel centres, step one pixel along the major axis and
// light, across it, the pixel nearest the ideal line through the two end
// pixels. With integer ends that nearest pixel is found by integer additions
// alone, so the result is exact for any length. A tie (the line exactly half
// way between two pixels) goes to the larger coordinate, whichever way the
// line is drawn, so drawing it backwards lights the same pixels.

/**
 * The pixels (integer centres) a line rasteriser lights from (x0, y0) to
 * (x1, y1): from the pixel nearest the start to the pixel nearest the end, one
 * per unit step along the major axis (`max(|Δx|, |Δy|) + 1` pixels after
 * rounding the ends), consecutive pixels 8-neighbours, each within ½ pixel
 * across the major axis of the line through the two end pixels.
 */
export function rasterizeLine(x0: number, y0: number, x1: number, y1: number): [number, number][] {
  const caller = 'rasterizeLine';
  checkNumber(caller, 'x0', x0);
  checkNumber(caller, 'y0', y0);
  checkNumber(caller, 'x1', x1);
  checkNumber(caller, 'y1', y1);
  // Math.round sends halves up; + 0 turns its −0 into 0.
  const [startX, startY, endX, endY] = [x0, y0, x1, y1].map((v) => Math.round(v) + 0);
  const dx = endX - startX;
  const dy = endY - startY;
  if (Math.abs(dx) >= Math.abs(dy)) {
    return alongMajor(startX, startY, endX, endY, (major, minor) => [major, minor]);
  }
  return alongMajor(startY, startX, endY, endX, (major, minor) => [minor, major]);
}

/**
 * The pixels of a line whose major axis is the first coordinate, as
 * `pixel(major, minor)`, always walked from the smaller major coordinate so
 * that ties are broken the same way in both directions.
 */
function alongMajor(
  startMajor: number,
  startMinor: number,
  endMajor: number,
  endMinor: number,
  pixel: (major: number, minor: number) => [number, number],
): [number, number][] {
  if (endMajor < startMajor) {
    return alongMajor(endMajor, endMinor, startMajor, startMinor, pixel).reverse();
  }
  const run = endMajor - startMajor;
  const rise = endMinor - startMinor;
  const pixels = new Array<[number, number]>(run + 1);
  // At step k the ideal minor coordinate is startMinor + k·rise/run, and the
  // pixel is its floor after adding ½: minor = startMinor + q with
  // 2k·rise + run = 2run·q + remainder, 0 ≤ remainder < 2run (|rise| ≤ run).
  let minor = startMinor;
  let remainder = run;
  for (let k = 0; k <= run; k++) {
    pixels[k] = pixel(startMajor + k, minor);
    remainder += 2 * rise;
    if (remainder >= 2 * run) {
      remainder -= 2 * run;
      minor++;
    } else if (remainder < 0) {
      remainder += 2 * run;
      minor--;
    }
  }
  return pixels;
}

/** A rectangle of whole pixels: centres from (left, bottom) to (right, top), inclusive. */
export interface PixelBox {
  left: number;
  bottom: number;
  right: number;
  top: number;
}

/**
 * The pixels of `rasterizeLine(x0, y0, x1, y1)` that lie in `box`, in the same
 * order, found without walking the pixels outside it: the pixel at step k is
 * the closed form of the walk, minor = start + ⌊(2k·rise + run) / 2run⌋, so the
 * work is in proportion to the box, not to the line (exact while 2·run·rise <
 * 2⁵³, i.e. for lines up to about 6·10⁷ pixels long).
 */
export function rasterizeLineInBox(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  box: PixelBox,
): [number, number][] {
  const caller = 'rasterizeLineInBox';
  for (const [name, v] of [
    ['x0', x0],
    ['y0', y0],
    ['x1', x1],
    ['y1', y1],
  ] as const)
    checkNumber(caller, name, v);
  const [startX, startY, endX, endY] = [x0, y0, x1, y1].map((v) => Math.round(v) + 0);
  if (Math.abs(endX - startX) >= Math.abs(endY - startY)) {
    return majorInBox(
      startX,
      startY,
      endX,
      endY,
      box.left,
      box.right,
      box.bottom,
      box.top,
      (a, b) => [a, b],
    );
  }
  return majorInBox(
    startY,
    startX,
    endY,
    endX,
    box.bottom,
    box.top,
    box.left,
    box.right,
    (a, b) => [b, a],
  );
}

/** alongMajor's pixels whose major coordinate is in [low, high] and minor in [minorLow, minorHigh]. */
function majorInBox(
  startMajor: number,
  startMinor: number,
  endMajor: number,
  endMinor: number,
  low: number,
  high: number,
  minorLow: number,
  minorHigh: number,
  pixel: (major: number, minor: number) => [number, number],
): [number, number][] {
  if (endMajor < startMajor) {
    return majorInBox(
      endMajor,
      endMinor,
      startMajor,
      startMinor,
      low,
      high,
      minorLow,
      minorHigh,
      pixel,
    ).reverse();
  }
  const run = endMajor - startMajor;
  const rise = endMinor - startMinor;
  let first = Math.max(0, low - startMajor);
  let last = Math.min(run, high - startMajor);
  if (rise !== 0) {
    // The pixel is within ½ of the ideal minor startMinor + k·rise/run: keep
    // the steps whose ideal is within [minorLow − 1, minorHigh + 1].
    const a = ((minorLow - 1 - startMinor) * run) / rise;
    const b = ((minorHigh + 1 - startMinor) * run) / rise;
    first = Math.max(first, Math.floor(Math.min(a, b)));
    last = Math.min(last, Math.ceil(Math.max(a, b)));
  }
  const pixels: [number, number][] = [];
  for (let k = first; k <= last; k++) {
    const minor =
      run === 0 ? startMinor : startMinor + Math.floor((2 * k * rise + run) / (2 * run));
    if (minor >= minorLow && minor <= minorHigh) pixels.push(pixel(startMajor + k, minor));
  }
  return pixels;
}
