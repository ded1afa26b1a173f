import { describe, expect, it } from 'vitest';
import { clipToBand } from './clipToBand';

const pieces = (curve: number[], low: number, high: number) =>
  clipToBand(curve, low, high).map((piece) => Array.from(piece));

describe('clipToBand', () => {
  it('keeps a curve that stays inside whole', () => {
    expect(pieces([0, 0, 1, 0.5, 2, -0.5], -1, 1)).toEqual([[0, 0, 1, 0.5, 2, -0.5]]);
  });

  it('cuts a peak out, ending each piece on the edge it crosses', () => {
    // (0, 0) → (1, 2) meets y = 1 half way, at x = 0.5; (1, 2) → (2, 0) at x = 1.5.
    expect(pieces([0, 0, 1, 2, 2, 0], -1, 1)).toEqual([
      [0, 0, 0.5, 1],
      [1.5, 1, 2, 0],
    ]);
  });

  it('cuts at the lower edge too', () => {
    // (0, 0) → (1, −3) meets y = −1 a third of the way.
    const [piece] = pieces([0, 0, 1, -3], -1, 1);
    expect(piece[0]).toBe(0);
    expect(piece[2]).toBeCloseTo(1 / 3, 12);
    expect(piece[3]).toBe(-1);
  });

  it('gives nothing for a curve wholly outside', () => {
    expect(pieces([0, 5, 1, 6, 2, 7], -1, 1)).toEqual([]);
  });
});
