import { describe, expect, it } from 'vitest';
import lesson from './lesson';
import type { QuadraticState } from './state';

const state = (points: number[][], step = 0, mu = 0.5): QuadraticState => ({ points, step, mu });
const derive = (s: QuadraticState) => lesson.derive(s);
const LECTURE = [
  [0, 0],
  [1, 2],
  [4, 1],
];

describe('quadratic model: the parabola y(x)', () => {
  it('solves the lecture points: y = −7/12 x² + 31/12 x, apex at x = 31/14', () => {
    // a0 = 0; a2 + a1 = 2; 16 a2 + 4 a1 = 1  ⇒  12 a2 = −7.
    const { parabola, apex, panelWarning } = derive(state(LECTURE)).explicit;
    expect(parabola.kind).toBe('ok');
    if (parabola.kind !== 'ok') return;
    const [a0, a1, a2] = parabola.coefficients;
    expect(a0).toBeCloseTo(0, 12);
    expect(a1).toBeCloseTo(31 / 12, 12);
    expect(a2).toBeCloseTo(-7 / 12, 12);
    // y′ = 0 at x = −a1 / 2a2 = 31/14, where y = a1² / (−4 a2) = 961/336.
    expect(apex![0]).toBeCloseTo(31 / 14, 12);
    expect(apex![1]).toBeCloseTo(961 / 336, 12);
    expect(panelWarning).toBeNull();
  });

  it('fits the view, at every step alike, to every curve the construction will draw', () => {
    const { bounds } = derive(state(LECTURE));
    for (const step of [1, 2, 3, 4, 5]) expect(derive(state(LECTURE, step)).bounds).toEqual(bounds);
    // Widest to the left, the family's μ1 = 0.8: x(μ) = 13.75μ² − 9.75μ, sampled at μ = 0.35.
    expect(bounds.minX).toBeCloseTo(13.75 * 0.35 ** 2 - 9.75 * 0.35, 12);
    expect(bounds.maxX).toBe(4);
    expect(bounds.minY).toBe(0);
    // Highest, the family's μ1 = 0.2: y(μ) = −11.25μ² + 12.25μ, sampled at μ = 0.54 (above the apex 961/336).
    expect(bounds.maxY).toBeCloseTo(-11.25 * 0.54 ** 2 + 12.25 * 0.54, 12);
  });

  it('says which points share an x', () => {
    const same = derive(
      state([
        [1, 0],
        [1, 2.5],
        [3.5, 1.5],
      ]),
    ).explicit;
    expect(same.parabola.kind).toBe('same-x');
    expect(same.column).toEqual([
      [1, 0],
      [1, 2.5],
    ]);
    expect(same.panelWarning).toBe(
      'There is none: P0 and P1 share x = 1, so the system below has equal rows and no solution.',
    );
    expect(
      derive(
        state([
          [2, 0],
          [2, 1],
          [2, 3],
        ]),
      ).explicit.figureNote,
    ).toBe('No parabola y(x): all three points share x = 2, and a function has one y at each x.');
    expect(
      derive(
        state([
          [1, 1],
          [1, 1],
          [1, 1],
        ]),
      ).explicit.figureNote,
    ).toContain('all three points are at one spot, (1, 1)');
  });

  it('finds a parabola that goes backwards in x, and says so', () => {
    const back = derive(
      state([
        [0, 0],
        [4, 2],
        [2, 3.5],
      ]),
    ).explicit;
    expect(back.parabola.kind).toBe('backwards');
    expect(back.panelWarning).toContain('x1 = 4 is not between x0 = 0 and x2 = 2');
  });
});

describe('quadratic model: the parametric quadratic', () => {
  it('solves equation 3 at μ1 = 1/2: a0 = P0, a2 = (4, −6), a1 = (0, 7)', () => {
    // a2 = (P1 − P0 − ½(P2 − P0)) / (½ · (−½)) = ((1, 2) − (2, ½)) / (−¼); a1 = P2 − P0 − a2.
    const { coefficients, atMu } = derive(state(LECTURE, 2)).parametric;
    const [a0, a1, a2] = coefficients;
    expect(a0).toEqual([0, 0]);
    expect(a1[0]).toBeCloseTo(0, 12);
    expect(a1[1]).toBeCloseTo(7, 12);
    expect(a2[0]).toBeCloseTo(4, 12);
    expect(a2[1]).toBeCloseTo(-6, 12);
    expect(atMu[0]).toBeCloseTo(1, 12);
    expect(atMu[1]).toBeCloseTo(2, 12);
  });

  it('puts its ticks at μ = 0, 0.1, …, 1 on the drawn curve, P1 at the middle one', () => {
    const current = derive(state(LECTURE, 2)).parametric.current!;
    expect(current.ticks).toHaveLength(11);
    expect(current.ticks[0]).toEqual([0, 0]);
    expect(current.ticks[5][0]).toBeCloseTo(1, 12);
    expect(current.ticks[5][1]).toBeCloseTo(2, 12);
    expect(current.ticks[10]).toEqual([4, 1]);
    expect(current.curve).toContain(current.ticks[3]);
  });

  it('chooses μ1 by chord length √2 − 1 and by centripetal 1 / (1 + ⁴√2)', () => {
    // d0 = |(1, 2)| = √5, d1 = |(3, −1)| = √10, so d1 = √2 d0.
    const { rules, d0, d1 } = derive(state(LECTURE)).parametric;
    expect(d0).toBeCloseTo(Math.sqrt(5), 12);
    expect(d1).toBeCloseTo(Math.sqrt(10), 12);
    expect(rules.map((rule) => rule.id)).toEqual(['uniform', 'chord', 'centripetal']);
    expect(rules[0].mu).toBe(0.5);
    expect(rules[1].mu).toBeCloseTo(Math.SQRT2 - 1, 12);
    expect(rules[2].mu).toBeCloseTo(1 / (1 + Math.SQRT2 ** 0.5), 12);
  });

  it('draws the family without the slider’s own value, and only usable rules', () => {
    expect(derive(state(LECTURE, 4, 0.5)).parametric.members.map((m) => m.mu)).toEqual([
      0.2, 0.35, 0.8,
    ]);
    // Among them, the chosen μ1's curve says so, in words the projected picture
    // can show (presenter view hides the slider).
    expect(derive(state(LECTURE, 4, 0.5)).parametric.current?.text).toBe('chosen: μ_1 = 0.5');
    // P1 on P0: chord length and centripetal both give μ1 = 0, where there is no curve.
    const onP0 = derive(
      state(
        [
          [0, 0],
          [0, 0],
          [4, 1],
        ],
        5,
      ),
    ).parametric;
    expect(onP0.rules.map((rule) => rule.usable)).toEqual([true, false, false]);
    expect(onP0.members.map((m) => m.mu)).toEqual([0.5]);
  });

  it('has no parametric curve to draw before step 2', () => {
    for (const step of [0, 1]) {
      const { current, members } = derive(state(LECTURE, step)).parametric;
      expect(current).toBeNull();
      expect(members).toEqual([]);
    }
  });
});
