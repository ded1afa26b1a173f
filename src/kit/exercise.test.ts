import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { MAX_SEED, checkNumbers, checkPoint, newSeed, pointTask, random } from './exercise';

describe('random(seed)', () => {
  it('gives the same numbers for the same seed, and other numbers for another', () => {
    const a = random(42);
    const b = random(42);
    const c = random(43);
    const first = [a.next(), a.next(), a.next()];
    expect([b.next(), b.next(), b.next()]).toEqual(first);
    expect([c.next(), c.next(), c.next()]).not.toEqual(first);
  });
  it('int stays within its bounds, both included, and reaches both', () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: MAX_SEED }), (seed) => {
        const r = random(seed);
        for (let i = 0; i < 50; i++) {
          const n = r.int(-2, 3);
          if (!Number.isInteger(n) || n < -2 || n > 3) return false;
        }
        return true;
      }),
    );
    const r = random(7);
    const seen = new Set(Array.from({ length: 200 }, () => r.int(0, 2)));
    expect([...seen].sort()).toEqual([0, 1, 2]);
  });
  it('next is in [0, 1)', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 2 ** 32 - 1 }), (seed) => {
        const v = random(seed).next();
        return v >= 0 && v < 1;
      }),
    );
  });
});

describe('newSeed', () => {
  it('never repeats the seed shown, and stays in [1, MAX_SEED]', () => {
    // A draw that would give the current seed first must be passed over.
    const draws = [(500 - 1) / MAX_SEED, 0.5];
    const seed = newSeed(500, () => draws.shift() ?? 0);
    expect(seed).not.toBe(500);
    expect(seed).toBe(1 + Math.floor(0.5 * MAX_SEED));
    expect(newSeed(3, () => 0.999999999)).toBeLessThanOrEqual(MAX_SEED);
    expect(newSeed(3, () => 0)).toBe(1);
  });
});

describe('checkNumbers', () => {
  // W(3,1,0.4) = 3 · 0.4 · 0.6² = 0.432 (by hand).
  const answer = [0.432];
  const mistakes = [{ values: [3 * 0.6 * 0.4 ** 2], hint: 'You swapped t and 1 − t.' }];
  it('accepts the answer within the tolerance, and says how close', () => {
    expect(checkNumbers([0.432], answer, 0.005, 'x').correct).toBe(true);
    expect(checkNumbers([0.432], answer, 0.005, 'x').message).toBe('Correct.');
    const near = checkNumbers([0.43], answer, 0.005, 'x');
    expect(near.correct).toBe(true);
    expect(near.message).toMatch(/within 0\.002/);
  });
  it('rejects a wrong answer with the hint of its mistake, or the general hint', () => {
    const swapped = checkNumbers([0.288], answer, 0.005, 'Look at step 2.', mistakes);
    expect(swapped).toEqual({ correct: false, message: 'Not yet. You swapped t and 1 − t.' });
    const other = checkNumbers([0.5], answer, 0.005, 'Look at step 2.', mistakes);
    expect(other).toEqual({ correct: false, message: 'Not yet. Look at step 2.' });
  });
  it('asks for every number when one is missing', () => {
    expect(checkNumbers([NaN, 1], [1, 1], 0.01, 'x').message).toBe('Type every number.');
    expect(checkNumbers([NaN], [1], 0.01, 'x').message).toBe('Type a number.');
  });
  it('is exactly the tolerance band, for any answer', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -100, max: 100, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
        (a, d) => checkNumbers([a + d], [a], 0.01, 'x').correct === Math.abs(a + d - a) <= 0.01,
      ),
    );
  });
});

describe('checkPoint', () => {
  it('says how far the guess is, right or wrong', () => {
    // (1.9, 1.5) is 0.1 from the lecture cubic's x(0.5) = (2, 1.5).
    const right = checkPoint([1.9, 1.5], [2, 1.5], 0.25, 'Look at P₁,₁.');
    expect(right.correct).toBe(true);
    expect(right.message).toBe('Correct. Your guess is 0.1 from the point (2, 1.5).');
    const wrong = checkPoint([2, 0.5], [2, 1.5], 0.25, 'Look at P₁,₁.');
    expect(wrong).toEqual({
      correct: false,
      message: 'Not yet: your guess is 1 from the point (2, 1.5). Look at P₁,₁.',
    });
  });
});

describe('pointTask', () => {
  it('places a guess on its figure, checked as checkPoint checks it, with a hint for that guess', () => {
    const task = pointTask('curve', [2, 1.5], 0.25, (guess) =>
      guess[1] < 1.5 ? 'Too low.' : 'Too high.',
    );
    expect(task).toMatchObject({
      kind: 'point',
      figure: 'curve',
      answer: [2, 1.5],
      tolerance: 0.25,
    });
    expect(task.check([2.2, 1.5]).correct).toBe(true);
    // (2, 0.5) is 1 below the point; (2, 2.5) is 1 above it.
    expect(task.check([2, 0.5]).message).toBe(
      'Not yet: your guess is 1 from the point (2, 1.5). Too low.',
    );
    expect(task.check([2, 2.5]).message).toBe(
      'Not yet: your guess is 1 from the point (2, 1.5). Too high.',
    );
    expect(pointTask('curve', [0, 0], 0.1, 'Look again.').check([1, 0]).message).toBe(
      'Not yet: your guess is 1 from the point (0, 0). Look again.',
    );
  });
});
