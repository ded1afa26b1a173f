import { type Field, stepField, number, points, quote } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/**
 * What the figure walks through: the construction level by level (its
 * subdivision's two halves on top, or not), the pseudocode line by line, or
 * the construction expanded back into the Bernstein form.
 */
export type Mode = 'construction' | 'halves' | 'pseudocode' | 'bernstein';

/** Everything the de Casteljau lesson shows, and all of it goes in the link. */
export interface DeCasteljauState {
  /** Control points P0 … Pn. */
  p: Point[];
  t: number;
  /** The step of the walk shown (see script.ts, pseudocode.ts and bernsteinForm.ts for what each reveals). */
  step: number;
  /** Which walk the figure shows (`split` in the link; see `modeField`). */
  mode: Mode;
}

export const MAX_POINTS = 16;

/**
 * The lesson's own cubic, a symmetric arch (it is not in the notes, whose
 * figures give no coordinates): P(0.5) = (2, 1.5).
 */
export const ARCH_CUBIC: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

/** How each mode reads in the link. */
const MODE_KEYS: Record<Mode, string> = {
  construction: '0',
  halves: '1',
  pseudocode: 'code',
  bernstein: 'bernstein',
};

/**
 * The mode under the link key `split`: the lesson's only choice used to be
 * "show the subdivision's halves", `split=0` or `split=1`, and every link made
 * then opens the same picture (0 is the construction, 1 its halves).
 */
const modeField: Field<Mode> = {
  default: 'construction',
  key: 'split',
  encode: (mode) => MODE_KEYS[mode],
  decode(raw) {
    const old = raw === 'true' ? '1' : raw === 'false' ? '0' : raw;
    const mode = (Object.keys(MODE_KEYS) as Mode[]).find((m) => MODE_KEYS[m] === old);
    return mode
      ? { ok: true, value: mode }
      : { ok: false, why: `${quote(raw)} is not one of 0, 1, code, bernstein` };
  },
};

export const schema: Schema<DeCasteljauState> = {
  p: points({ default: ARCH_CUBIC, min: 2, max: MAX_POINTS }),
  // Figure 5 of the lecture notes draws its construction at μ ≈ 0.6.
  t: number({ default: 0.6, min: 0, max: 1 }),
  // Every lesson opens at its first scene's step 0: the first clicker press is the first step.
  step: stepField(),
  mode: modeField,
};

/** Degree of the curve. */
export const degree = (state: DeCasteljauState) => state.p.length - 1;
