import { describe, expect, it } from 'vitest';
import { add, cross, distance, dot, norm, pointBetween, scale, subtract, zeroVector } from './vec';

describe('vector helpers', () => {
  it('work coordinate by coordinate in any dimension', () => {
    expect(add([1, 2], [3, 4])).toEqual([4, 6]);
    expect(subtract([1, 2, 3], [3, 2, 1])).toEqual([-2, 0, 2]);
    expect(scale([1, -2], 3)).toEqual([3, -6]);
    expect(dot([1, 2, 3], [4, 5, 6])).toBe(32);
    expect(norm([3, 4])).toBe(5);
    expect(distance([1, 1, 1], [3, 3, 2])).toBe(3);
    expect(cross([1, 0, 0], [0, 1, 0])).toEqual([0, 0, 1]);
    expect(zeroVector(3)).toEqual([0, 0, 0]);
  });

  it('pointBetween is exact at both ends, even for large coordinates', () => {
    const a = [1e6 + 0.1, -3];
    const b = [1e-6, 7];
    expect(pointBetween(a, b, 0)).toEqual(a);
    expect(pointBetween(a, b, 1)).toEqual(b);
    expect(pointBetween([0, 0], [2, 4], 0.25)).toEqual([0.5, 1]);
  });

  it('returns fresh arrays', () => {
    const a = [1, 2];
    expect(add(a, [0, 0])).not.toBe(a);
    expect(scale(a, 1)).not.toBe(a);
  });
});
