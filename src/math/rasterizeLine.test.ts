import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { rasterizeLine, rasterizeLineInBox } from './rasterizeLine';

describe('rasterizeLine', () => {
  it('lights the pixels worked out by hand', () => {
    const cases: [[number, number, number, number], [number, number][]][] = [
      // Horizontal, vertical (drawn downwards) and the two diagonals.
      [
        [0, 0, 3, 0],
        [
          [0, 0],
          [1, 0],
          [2, 0],
          [3, 0],
        ],
      ],
      [
        [2, 1, 2, -2],
        [
          [2, 1],
          [2, 0],
          [2, -1],
          [2, -2],
        ],
      ],
      [
        [0, 0, 3, 3],
        [
          [0, 0],
          [1, 1],
          [2, 2],
          [3, 3],
        ],
      ],
      [
        [0, 0, -2, 2],
        [
          [0, 0],
          [-1, 1],
          [-2, 2],
        ],
      ],
      // Bresenham's shallow line: ideal y = 0, 0.4, 0.8, 1.2, 1.6, 2.
      [
        [0, 0, 5, 2],
        [
          [0, 0],
          [1, 0],
          [2, 1],
          [3, 1],
          [4, 2],
          [5, 2],
        ],
      ],
      // Steep: y is the major axis, ideal x = 0, 0.4, 0.8, 1.2, 1.6, 2.
      [
        [0, 0, 2, 5],
        [
          [0, 0],
          [0, 1],
          [1, 2],
          [1, 3],
          [2, 4],
          [2, 5],
        ],
      ],
      // Ties (ideal y = 0.5, −0.5) go to the larger coordinate.
      [
        [0, 0, 2, 1],
        [
          [0, 0],
          [1, 1],
          [2, 1],
        ],
      ],
      [
        [0, 0, 2, -1],
        [
          [0, 0],
          [1, 0],
          [2, -1],
        ],
      ],
      // Ends rounded first: (0.4, −0.6) → (0, −1) and (3.5, 1.49) → (4, 1);
      // ideal y = −1, −0.5, 0, 0.5, 1.
      [
        [0.4, -0.6, 3.5, 1.49],
        [
          [0, -1],
          [1, 0],
          [2, 0],
          [3, 1],
          [4, 1],
        ],
      ],
      // Both ends in one pixel: a single pixel, with no −0.
      [[0.2, 0.4, -0.3, 0.1], [[0, 0]]],
      [[1.4, 2.6, 1.4, 2.6], [[1, 3]]],
    ];
    for (const [[x0, y0, x1, y1], pixels] of cases) {
      expect(rasterizeLine(x0, y0, x1, y1), `${x0}, ${y0} → ${x1}, ${y1}`).toEqual(pixels);
    }
  });

  const end = fc.double({ min: -200, max: 200, noNaN: true });
  const integer = fc.integer({ min: -100, max: 100 });

  it('has one pixel per step along the major axis, 8-connected, within ½ of the line', () => {
    fc.assert(
      fc.property(end, end, end, end, (x0, y0, x1, y1) => {
        const pixels = rasterizeLine(x0, y0, x1, y1);
        const [startX, startY, endX, endY] = [x0, y0, x1, y1].map((v) => Math.round(v) + 0);
        const [dx, dy] = [endX - startX, endY - startY];
        const xMajor = Math.abs(dx) >= Math.abs(dy);
        expect(pixels).toHaveLength(Math.max(Math.abs(dx), Math.abs(dy)) + 1);
        expect(pixels[0]).toEqual([startX, startY]);
        expect(pixels[pixels.length - 1]).toEqual([endX, endY]);
        // One message per broken rule and pixel, so that a failure says which.
        const broken: string[] = [];
        pixels.forEach(([x, y], k) => {
          if (!Number.isInteger(x) || !Number.isInteger(y)) broken.push(`${k}: not integer`);
          if (k > 0) {
            const [px, py] = pixels[k - 1];
            // Exactly one unit along the major axis, at most one across it.
            if (Math.abs(xMajor ? x - px : y - py) !== 1) broken.push(`${k}: major step`);
            if (Math.abs(xMajor ? y - py : x - px) > 1) broken.push(`${k}: not a neighbour`);
          }
          // Across the major axis, from the ideal line through the end pixels.
          const across = xMajor
            ? y - (startY + ((x - startX) * dy) / dx)
            : x - (startX + ((y - startY) * dx) / dy);
          if ((dx !== 0 || dy !== 0) && Math.abs(across) > 0.5 + 1e-12) {
            broken.push(`${k}: ${across} across`);
          }
        });
        expect(broken).toEqual([]);
      }),
    );
  });

  it('lights the same pixels drawn backwards, transposed or moved by whole pixels', () => {
    fc.assert(
      fc.property(integer, integer, integer, integer, integer, integer, (x0, y0, x1, y1, a, b) => {
        const pixels = rasterizeLine(x0, y0, x1, y1);
        expect(rasterizeLine(x1, y1, x0, y0)).toEqual(pixels.slice().reverse());
        expect(rasterizeLine(y0, x0, y1, x1)).toEqual(pixels.map(([x, y]) => [y, x]));
        expect(rasterizeLine(x0 + a, y0 + b, x1 + a, y1 + b)).toEqual(
          pixels.map(([x, y]) => [x + a, y + b]),
        );
      }),
    );
  });

  it('rejects coordinates that are not finite numbers', () => {
    expect(() => rasterizeLine(NaN, 0, 1, 1)).toThrow(
      'rasterizeLine: x0 is NaN; it must be a finite number.',
    );
    expect(() => rasterizeLine(0, 0, 1, Infinity)).toThrow(/^rasterizeLine: y1 is Infinity/);
    expect(() => rasterizeLine(0, '1' as unknown as number, 1, 1)).toThrow(RangeError);
  });
});

describe('rasterizeLineInBox', () => {
  const box = { left: -3, bottom: -2, right: 4, top: 5 };
  const inside = ([i, j]: [number, number]) =>
    i >= box.left && i <= box.right && j >= box.bottom && j <= box.top;

  it('is rasterizeLine with the pixels outside the box left out, in the same order', () => {
    const coordinate = fc.double({ min: -30, max: 30, noNaN: true });
    fc.assert(
      fc.property(coordinate, coordinate, coordinate, coordinate, (x0, y0, x1, y1) => {
        expect(rasterizeLineInBox(x0, y0, x1, y1, box)).toEqual(
          rasterizeLine(x0, y0, x1, y1).filter(inside),
        );
      }),
      { numRuns: 500 },
    );
  });

  it('a line ten million pixels long costs only the box: y = 0.3x lights (x, ⌊0.3x + ½⌋)', () => {
    const far = { left: 5_000_000, bottom: 0, right: 5_000_003, top: 10_000_000 };
    // 0.3·5 000 001 = 1 500 000.3 → 1 500 000; 0.3·5 000 002 = 1 500 000.6 → 1 500 001.
    expect(rasterizeLineInBox(0, 0, 10_000_000, 3_000_000, far)).toEqual([
      [5_000_000, 1_500_000],
      [5_000_001, 1_500_000],
      [5_000_002, 1_500_001],
      [5_000_003, 1_500_001],
    ]);
    expect(rasterizeLineInBox(0, 0, 10_000_000, 3_000_000, box)).toEqual([
      [0, 0],
      [1, 0],
      [2, 1],
      [3, 1],
      [4, 1],
    ]);
  });
});
