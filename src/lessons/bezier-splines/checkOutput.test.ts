import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type Point, cubicSplineC2, quadraticSplineC1 } from '../../math';
import { checkOutput, differenceRows } from './checkOutput';
import { printedSlack, readPoints } from './pastedPoints';
import { type SplineKind, expectedOutput, rowName } from './splineRows';
import { FOUR_POINTS, INFINITY, SEMI, SPIRAL } from './state';

// The four points A = (0, 0), D = (1, 2.5), G = (4, 2.5), J = (5, 0), worked by
// hand in workedExample.test.ts:
//   C¹ (b₀ the midpoint): (0, 0), (0.5, 1.25), (1, 2.5), (1.5, 3.75), (4, 2.5), (6.5, 1.25), (5, 0)
//   C² (natural): A (0, 0), B (1/9, 1), C (2/9, 2), D (1, 2.5), E (16/9, 3), F (29/9, 3),
//                 G (4, 2.5), H (43/9, 2), I (44/9, 1), J (5, 0)
const C1_BY_HAND: Point[] = [
  [0, 0],
  [0.5, 1.25],
  [1, 2.5],
  [1.5, 3.75],
  [4, 2.5],
  [6.5, 1.25],
  [5, 0],
];
const C2_BY_HAND: Point[] = [
  [0, 0],
  [1 / 9, 1],
  [2 / 9, 2],
  [1, 2.5],
  [16 / 9, 3],
  [29 / 9, 3],
  [4, 2.5],
  [43 / 9, 2],
  [44 / 9, 1],
  [5, 0],
];

/** One row a line, "x y", every digit: what a program printing with setprecision(17) shows. */
const lines = (rows: readonly Point[]) => rows.map(([x, y]) => `${x} ${y}`).join('\n');

/** The C² control points from the maths module's other route (the natural spline's tridiagonal solve). */
const naturalRows = (p: readonly Point[]) => {
  const pieces = cubicSplineC2(p);
  return [p[0], ...pieces.flatMap((s) => s.slice(1))];
};
const quadraticRows = (p: readonly Point[]) => {
  const mid: Point = [(p[0][0] + p[1][0]) / 2, (p[0][1] + p[1][1]) / 2];
  return [p[0], ...quadraticSplineC1(p, mid).flatMap((s) => s.slice(1))];
};

describe('what the practical’s functions should print', () => {
  it('is the hand-worked C¹ and C² control points for the four points', () => {
    expect(expectedOutput(FOUR_POINTS, 'C1')).toEqual(C1_BY_HAND);
    expectedOutput(FOUR_POINTS, 'C2').forEach((q, j) =>
      q.forEach((v, d) => expect(v).toBeCloseTo(C2_BY_HAND[j][d], 12)),
    );
  });
  it('names the rows pᵢ, bᵢ in turn for C¹; A … J for four points, cⱼ otherwise, for C²', () => {
    expect([0, 1, 2, 5, 6].map((j) => rowName(j, 'C1', 3))).toEqual(['p₀', 'b₀', 'p₁', 'b₂', 'p₃']);
    expect([0, 4, 9].map((j) => rowName(j, 'C2', 3))).toEqual(['A', 'E', 'J']);
    expect(rowName(13, 'C2', 9)).toBe('c₁₃');
  });
});

describe('correct output passes', () => {
  it('says all N control points agree to 1e-6, whatever separates the numbers', () => {
    const spellings = [
      lines(C2_BY_HAND),
      C2_BY_HAND.map(([x, y]) => `${x}, ${y}`).join('; '),
      `[${C2_BY_HAND.map(([x, y]) => `[${x}, ${y}]`).join(', ')}]`,
      C2_BY_HAND.flat().join('\n'),
      // numpy prints "[[0.         0.        ]\n [0.11111111 1.        ] …]"
      `[${C2_BY_HAND.map(([x, y]) => `[${x.toFixed(8)} ${y.toFixed(8)}]`).join('\n ')}]`,
      // Eigen prints the transpose of a 10 × 2 matrix as two rows.
      `${C2_BY_HAND.map((q) => q[0]).join(' ')}\n${C2_BY_HAND.map((q) => q[1]).join(' ')}`,
    ];
    for (const text of spellings) {
      const verdict = checkOutput(text, FOUR_POINTS, 'C2');
      expect(verdict.status, text).toBe('pass');
      expect(verdict.summary).toBe('All 10 control points agree to 1e-6.');
      expect(verdict.differences).toEqual([]);
    }
    expect(checkOutput(lines(C1_BY_HAND), FOUR_POINTS, 'C1').summary).toBe(
      'All 7 control points agree to 1e-6.',
    );
  });

  it('says so for the transpose', () => {
    const text = `${C2_BY_HAND.map((q) => q[0]).join(' ')}\n${C2_BY_HAND.map((q) => q[1]).join(' ')}`;
    expect(checkOutput(text, FOUR_POINTS, 'C2').why[0]).toMatch(
      /^Read as two rows, all x then all y/,
    );
  });

  it('passes each dataset’s output from the maths module’s other routes', () => {
    for (const p of [INFINITY, SPIRAL, SEMI]) {
      expect(checkOutput(lines(naturalRows(p)), p, 'C2').status).toBe('pass');
      expect(checkOutput(lines(quadraticRows(p)), p, 'C1').status).toBe('pass');
    }
  });

  it('passes C++’s default six digits as agreeing to the digits printed', () => {
    // std::cout << matrix: 1.77778 for 16/9 is 2.2e−6 off, more than 1e-6, less than the rounding 5e−6.
    const eigen = C2_BY_HAND.map(
      ([x, y]) => `${Number(x.toPrecision(6))} ${Number(y.toPrecision(6))}`,
    );
    expect(eigen[4]).toBe('1.77778 3');
    const verdict = checkOutput(eigen.join('\n'), FOUR_POINTS, 'C2');
    expect(verdict.status).toBe('rounded');
    expect(verdict.summary).toMatch(
      /^All 10 control points agree to the digits printed \(the largest difference, 2\.2 × 10⁻⁶/,
    );
  });

  it('allows a printed number its rounding, and no more', () => {
    // 0.111111 stands for anything within 5e−7; 1.77778 within 5e−6; "2" (six digits) within 5e−6.
    expect(printedSlack('0.111111')).toBeCloseTo(5e-7, 18);
    expect(printedSlack('1.77778')).toBeCloseTo(5e-6, 18);
    expect(printedSlack('2')).toBeCloseTo(5e-6, 18);
    expect(printedSlack('1.5e-3')).toBeCloseTo(5e-5, 18);
    expect(printedSlack('0')).toBe(0);
    // Two decimals: 0.11 for 1/9 is 1.1e−3 off, within its rounding 5e−3 (agrees to the digits
    // printed); 0.12 is 8.9e−3 off, beyond it.
    const two = C2_BY_HAND.map(([x, y]) => `${x.toFixed(2)} ${y.toFixed(2)}`);
    expect(checkOutput(two.join('\n'), FOUR_POINTS, 'C2').status).toBe('rounded');
    two[1] = '0.12 1.00';
    expect(checkOutput(two.join('\n'), FOUR_POINTS, 'C2').differences.map((d) => d.row)).toEqual([
      1,
    ]);
  });
});

describe('a planted error is found at its row', () => {
  it('C²: one coordinate of row 13 of the spiral moved by 0.25', () => {
    const rows = naturalRows(SPIRAL);
    rows[13] = [rows[13][0], rows[13][1] + 0.25];
    const verdict = checkOutput(lines(rows), SPIRAL, 'C2');
    expect(verdict.status).toBe('fail');
    expect(verdict.differences.map((d) => [d.row, d.name])).toEqual([[13, 'c₁₃']]);
    expect(verdict.differences[0].distance).toBeCloseTo(0.25, 12);
    expect(verdict.summary).toBe(
      '1 of 28 control points differ; the first is row 13 (c₁₃), by 0.25.',
    );
    // c₁₃ takes part in C¹ at c₁₂ and C² at c₁₂ and c₁₅: those are named.
    expect(verdict.why.join(' ')).toMatch(/C¹ at c₁₂: c₁₁ − 2c₁₂ \+ c₁₃ = 0 does not hold/);
    expect(verdict.why.join(' ')).toMatch(/C² at c₁₅: c₁₃ − 2c₁₄ \+ 2c₁₆ − c₁₇ = 0 does not hold/);
    expect(differenceRows(verdict)[0].slice(0, 2)).toEqual(['13', 'c₁₃']);
    expect(differenceRows(verdict)[0][4]).toBe('0.25');
  });

  it('C¹: a joint row that is not the point, and a bᵢ that does not follow from the one before', () => {
    const rows = quadraticRows(INFINITY);
    const joint = rows.map((q, j): Point => (j === 4 ? [q[0] + 1, q[1]] : q));
    const atJoint = checkOutput(lines(joint), INFINITY, 'C1');
    expect(atJoint.differences.map((d) => d.row)).toEqual([4]);
    expect(atJoint.why[0]).toBe(
      'Row 4 should be the point p₂ = (0, 0): rows 0, 2, 4, … are the given points.',
    );
    // Row 5 is b₂; the program carried its slip on, so b₃, b₄, … are wrong too, alternately.
    const carried = rows.map((q) => q.slice());
    carried[5][1] += 0.5;
    for (let j = 7; j < carried.length; j += 2) carried[j][1] += (j - 5) % 4 === 0 ? 0.5 : -0.5;
    const verdict = checkOutput(lines(carried), INFINITY, 'C1');
    expect(verdict.differences[0]).toMatchObject({ row: 5, name: 'b₂' });
    expect(verdict.differences.map((d) => d.row)).toEqual([5, 7, 9, 11, 13, 15]);
    expect(verdict.why).toEqual([
      // b₀ = ½((3, 0) + (2.12, 1.5)) = (2.56, 0.75); b₁ = 2(2.12, 1.5) − (2.56, 0.75) = (1.68, 2.25);
      // b₂ = 2(0, 0) − (1.68, 2.25) = (−1.68, −2.25), and the paste has −1.75.
      'Row 5 (b₂) does not follow from your own b₁ = (1.68, 2.25): 2p₂ − b₁ = (−1.68, −2.25).',
    ]);
  });
});

describe('the likely why', () => {
  const c1 = (text: Point[]) => checkOutput(lines(text), FOUR_POINTS, 'C1');
  const c2 = (text: Point[]) => checkOutput(lines(text), FOUR_POINTS, 'C2');

  it('C¹: forgot the factor 2 (bᵢ = pᵢ − bᵢ₋₁)', () => {
    // b₁ = (1, 2.5) − (0.5, 1.25) = (0.5, 1.25); b₂ = (4, 2.5) − (0.5, 1.25) = (3.5, 1.25).
    const verdict = c1([
      [0, 0],
      [0.5, 1.25],
      [1, 2.5],
      [0.5, 1.25],
      [4, 2.5],
      [3.5, 1.25],
      [5, 0],
    ]);
    expect(verdict.differences.map((d) => d.row)).toEqual([3, 5]);
    expect(verdict.why[0]).toMatch(/^Forgot the factor 2/);
  });

  it('C¹ from the wrong side, a mirrored tangent (bᵢ = bᵢ₋₁)', () => {
    const verdict = c1([
      [0, 0],
      [0.5, 1.25],
      [1, 2.5],
      [0.5, 1.25],
      [4, 2.5],
      [0.5, 1.25],
      [5, 0],
    ]);
    expect(verdict.why[0]).toMatch(/^C¹ from the wrong side, a mirrored tangent/);
  });

  it('C¹ off by one piece (reflected through pᵢ₊₁)', () => {
    // b₁ = 2(4, 2.5) − (0.5, 1.25) = (7.5, 3.75); b₂ = 2(5, 0) − (7.5, 3.75) = (2.5, −3.75).
    const verdict = c1([
      [0, 0],
      [0.5, 1.25],
      [1, 2.5],
      [7.5, 3.75],
      [4, 2.5],
      [2.5, -3.75],
      [5, 0],
    ]);
    expect(verdict.why[0]).toMatch(/^Off by one piece: your bᵢ = 2pᵢ₊₁ − bᵢ₋₁/);
  });

  it('C¹: a b₀ other than the midpoint, the rest correct from it', () => {
    // b₀ = (0, 1): b₁ = (2, 5) − (0, 1) = (2, 4); b₂ = (8, 5) − (2, 4) = (6, 1).
    const verdict = c1([
      [0, 0],
      [0, 1],
      [1, 2.5],
      [2, 4],
      [4, 2.5],
      [6, 1],
      [5, 0],
    ]);
    expect(verdict.why).toEqual([
      'b₀ (row 1) is (0, 1), not the midpoint ½(p₀ + p₁) = (0.5, 1.25), the practical’s suggestion this check uses.',
      'Every later bᵢ follows correctly from your b₀ by bᵢ = 2pᵢ − bᵢ₋₁.',
    ]);
  });

  it('C² from the wrong side, a mirrored tangent (E = C, H = F)', () => {
    // Solved by hand: C = 2B, E = C = 2B, F = B − 4B + 4B = B, H = F = B, I = E − 2F + 2H = 2B,
    // H − 2I + J = −3B + J = 0: B = (5/3, 0).
    const verdict = c2([
      [0, 0],
      [5 / 3, 0],
      [10 / 3, 0],
      [1, 2.5],
      [10 / 3, 0],
      [5 / 3, 0],
      [4, 2.5],
      [5 / 3, 0],
      [10 / 3, 0],
      [5, 0],
    ]);
    expect(verdict.differences[0]).toMatchObject({ row: 1, name: 'B' });
    expect(verdict.why[0]).toBe(
      'C¹ from the wrong side, a mirrored tangent: your E = C, so the second piece leaves D back the way the first came in. C¹ is C − 2D + E = 0.',
    );
  });

  it('C²: forgot the factors 2 in the C² rows', () => {
    // B − C + E − F = 0 instead: C = 2B, E = 2D − 2B, F = 2D − 3B, H = 2G − 2D + 3B,
    // I = 2G − 2D + 4B; the end gives B = (2D − 2G + J)/5 = (−0.2, 0).
    const verdict = c2([
      [0, 0],
      [-0.2, 0],
      [-0.4, 0],
      [1, 2.5],
      [2.4, 5],
      [2.6, 5],
      [4, 2.5],
      [5.4, 0],
      [5.2, 0],
      [5, 0],
    ]);
    expect(verdict.why[0]).toBe('Forgot the factors 2 in C²: B − 2C + 2E − F = 0.');
  });

  it('x and y swapped, or the rows reversed', () => {
    expect(c2(C2_BY_HAND.map(([x, y]) => [y, x])).why[0]).toBe(
      'x and y are swapped: each row is x, then y.',
    );
    expect(c2([...C2_BY_HAND].reverse()).why[0]).toMatch(/^The rows are in reverse order/);
  });

  it('a nan where the solve failed', () => {
    const text = lines(C2_BY_HAND).split('\n');
    text[4] = '-nan(ind) -nan(ind)';
    const verdict = checkOutput(text.join('\n'), FOUR_POINTS, 'C2');
    expect(verdict.differences.map((d) => [d.row, d.name])).toEqual([[4, 'E']]);
    expect(verdict.why[0]).toMatch(/^Row 4 \(E\) is not a number \(nan or inf\)/);
    expect(differenceRows(verdict)[0][4]).toBe('not a number');
  });
});

describe('the wrong number of rows', () => {
  it('says the expected count 3n + 1 or 2n + 1', () => {
    const verdict = checkOutput(lines(C2_BY_HAND.slice(0, 7)), FOUR_POINTS, 'C2');
    expect(verdict.status).toBe('fail');
    expect(verdict.summary).toBe(
      'Expected 3n + 1 = 10 control points for n = 3 pieces through 4 points; got 7.',
    );
    // 7 rows is computeSplineC1's count here.
    expect(verdict.why[0]).toMatch(/2n \+ 1 = 7 is what computeSplineC1 returns/);
    expect(checkOutput(lines(C1_BY_HAND.slice(0, 5)), FOUR_POINTS, 'C1').summary).toBe(
      'Expected 2n + 1 = 7 control points for n = 3 pieces through 4 points; got 5.',
    );
  });

  it('finds the one row missing, or one too many', () => {
    const missing = C2_BY_HAND.filter((_, j) => j !== 6);
    expect(checkOutput(lines(missing), FOUR_POINTS, 'C2').why[0]).toBe(
      'Row 6 (G) is missing; the others agree: a loop that stops one step early, or starts one late?',
    );
    const extra = [...C1_BY_HAND, [5, 0] as Point];
    expect(checkOutput(lines(extra), FOUR_POINTS, 'C1').why[0]).toMatch(/^Row 6 is one too many/);
  });

  it('knows the points given instead of the control points', () => {
    const verdict = checkOutput(lines(FOUR_POINTS), FOUR_POINTS, 'C2');
    expect(verdict.why[0]).toBe(
      'These are the 4 given points themselves, not the control points: computeSplineC2 returns 3n + 1 = 10 rows, the given points every third row.',
    );
  });

  it('knows the other spline’s output, and each piece listed whole', () => {
    expect(checkOutput(lines(C1_BY_HAND), FOUR_POINTS, 'C2').why[0]).toBe(
      'These are the C¹ spline’s control points: choose C¹ above.',
    );
    // Three pieces of four control points, the joints D and G twice: 12 rows.
    const whole = [0, 1, 2, 3, 3, 4, 5, 6, 6, 7, 8, 9].map((j) => C2_BY_HAND[j]);
    const verdict = checkOutput(lines(whole), FOUR_POINTS, 'C2');
    expect(verdict.why).toEqual([
      'Each piece’s 4 control points listed separately, every inner joint twice (12 rows): computeSplineC2 shares the joints, 3n + 1 = 10 rows.',
      'Read without the repeats, all 10 control points agree.',
    ]);
    // Only b₀, b₁, b₂, one of them wrong: row 2 is b₂.
    const inner = checkOutput('0.5 1.25\n1.5 3.75\n6.5 1.5', FOUR_POINTS, 'C1');
    expect(inner.differences.map((d) => [d.row, d.name])).toEqual([[2, 'b₂']]);
  });
});

describe('text that is not numbers', () => {
  it('gets a clear message, never a crash', () => {
    const read = (text: string, kind: SplineKind = 'C2') => checkOutput(text, FOUR_POINTS, kind);
    expect(read('')).toMatchObject({ status: 'unreadable' });
    expect(read('   \n ').summary).toMatch(/^No numbers yet/);
    expect(read('0 0\nb0 = (0.5, 1.25)').summary).toBe(
      '“b0” on line 2 is not a number. Paste only the numbers your program printed, x and y of each control point; spaces, commas, semicolons, brackets and new lines may separate them.',
    );
    expect(read('<img src=x onerror=alert(1)>').summary).toMatch(
      /^“<img” on line 1 is not a number/,
    );
    expect(read('1 2 3').summary).toBe(
      '3 numbers do not pair into x y points: one is missing or one too many (the last, 3, has no partner).',
    );
  });

  it('never throws, whatever is pasted, and always says something', () => {
    const pasted = fc.oneof(
      fc.string(),
      fc
        .array(fc.oneof(fc.double(), fc.constantFrom('nan', 'inf', '-', '.', 'e5')), {
          maxLength: 40,
        })
        .map((v) => v.join(' ')),
    );
    fc.assert(
      fc.property(pasted, fc.constantFrom<SplineKind>('C1', 'C2'), (text, kind) => {
        const verdict = checkOutput(text, FOUR_POINTS, kind);
        expect(verdict.summary.length).toBeGreaterThan(10);
        differenceRows(verdict);
      }),
      { numRuns: 500 },
    );
  });

  it('reads a true minus sign and Windows’ -nan(ind) as C prints them', () => {
    const read = readPoints('−1.5 2\n-nan(ind) inf');
    expect(read).toMatchObject({ ok: true });
    if (read.ok) {
      expect(read.points[0]).toEqual([-1.5, 2]);
      expect(read.points[1][0]).toBeNaN();
      expect(read.points[1][1]).toBe(Infinity);
    }
  });
});
