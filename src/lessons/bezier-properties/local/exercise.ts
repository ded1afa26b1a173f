import { type ExerciseSpec, checkNumbers, random } from '../../../kit/exercise';
import { sub, words } from '../../../kit/format';
import { type Point, bernstein, binomial } from '../../../math';
import { opened } from '../exerciseSetup';
import { SCRIPTS } from '../scripts';
import { type PropertiesState, copy } from '../state';

// The exercise on property 3, no local control: how far the curve moves at
// most when one inner point moves.

/**
 * Property 3, no local control: one point of a long polygon moves, and the
 * curve moves by W(N, i, t) times that, at most W(N, i, i/N) times.
 */
export const localMove: ExerciseSpec<PropertiesState> = {
  id: 'local-move',
  title: 'How far does the curve move?',
  kind: 'number',
  pose(seed, defaults) {
    const r = random(seed);
    const n = r.int(3, 6);
    const i = r.int(1, n - 1);
    const shift = r.int(1, 3);
    const up = r.pick([true, false]);
    const spacing = n <= 3 ? 2 : 1;
    // The ends on the ground, the inner points above: never on one line.
    const before: Point[] = Array.from({ length: n + 1 }, (_, k) => [
      spacing * k,
      k === 0 || k === n ? 0 : r.int(1, 3),
    ]);
    const after = before.map((q, k) => (k === i ? [q[0], q[1] + (up ? shift : -shift)] : q));
    const peak = i / n;
    const largest = bernstein(n, i, peak);
    const answer = [largest * shift];
    const tolerance = 0.01;
    const c = binomial(n, i);
    const mistakes = [
      {
        values: [shift],
        hint: `Step “After”: the curve moves by W(${n}, ${i}, t) times P${sub(i)}’s move, a share of it; only an end point drags its end of the curve the whole way.`,
      },
      {
        values: [largest],
        hint: `W(${n}, ${i}, ${i}/${n}) = ${words(largest)} is the share at the largest move: multiply it by the move, ${shift}.`,
      },
      {
        values: [bernstein(n, i, 0.5) * shift],
        hint: `W(${n}, ${i}, t) is largest at t = i/N = ${i}/${n}, not at t = ½.`,
      },
      {
        values: [(largest / c) * shift],
        hint: `W(${n}, ${i}, t) = C(${n}, ${i})·tⁱ·(1 − t)ᴺ⁻ⁱ: the binomial coefficient C(${n}, ${i}) = ${c} is missing.`,
      },
      {
        values: [bernstein(n + 1, i, i / (n + 1)) * shift],
        hint: `N is the degree, ${n}, one less than the ${n + 1} control points.`,
      },
    ];
    const hint = `P(t) moves by W(${n}, ${i}, t)·ΔP${sub(i)}; that weight is largest at t = ${i}/${n}, where it is C(${n}, ${i})·(${i}/${n})${sup(i)}·(${n - i}/${n})${sup(n - i)}.`;
    return {
      state: opened(defaults, 'local', { points: copy(before), before }, (s) =>
        SCRIPTS.local.stepOf(s, 'before'),
      ),
      prompt: `If P${sub(i)} of this curve of degree ${n} moves ${up ? 'up' : 'down'} by ${shift}, how far does the curve move at most (to 2 decimals)?`,
      task: {
        kind: 'number',
        fields: ['largest move'],
        tolerance,
        answer,
        check: (values) => checkNumbers(values, answer, tolerance, hint, mistakes),
      },
      working: opened(defaults, 'local', { points: after, before }, 'last'),
    };
  },
};

const SUPERSCRIPTS = '⁰¹²³⁴⁵⁶⁷⁸⁹';
/** 3 → "³": a power in plain text. */
const sup = (k: number) => [...String(k)].map((d) => SUPERSCRIPTS[Number(d)]).join('');
