import { describe, expect, it } from 'vitest';
import { signedAngle } from './signedAngle';

describe('signedAngle', () => {
  it('is positive anticlockwise, negative clockwise', () => {
    expect(signedAngle([1, 0], [0, 2])).toBeCloseTo(Math.PI / 2, 15);
    expect(signedAngle([1, 0], [1, -1])).toBeCloseTo(-Math.PI / 4, 15);
  });

  it('is 0 for the same direction and π for the opposite one', () => {
    expect(signedAngle([3, 4], [6, 8])).toBe(0);
    expect(signedAngle([1, 0], [-1, 0])).toBeCloseTo(Math.PI, 15);
  });

  it('is 0 when a vector is zero', () => {
    expect(signedAngle([0, 0], [1, 1])).toBe(0);
  });
});
