/**
 * The kinds of field a lesson's state can hold in its link: each kind knows
 * its default, how to write a value short and readable, and how to read one
 * back strictly, saying in plain words what was wrong. The table is open: a
 * lesson that needs a new kind of value adds a factory here (or in its own
 * folder), not a branch in a switch.
 */

export type Point = readonly number[];

export type FieldResult<V> = { ok: true; value: V } | { ok: false; why: string };

/** One field of a lesson's state in the link. */
export interface Field<V> {
  readonly default: V;
  encode(value: V): string;
  decode(raw: string): FieldResult<V>;
  /**
   * The field's short key in the link, when it is not the field's name in code
   * (`points` in code, `p` in the link). Without it the name is the key.
   */
  readonly key?: string;
  /** Earlier keys of the field: links that use them keep opening the same picture. */
  readonly aliases?: readonly string[];
}

/**
 * The field under a short link key (and any earlier keys), so that code can
 * name it in whole words: `points: linkKey(points({ … }), 'p')`.
 */
export function linkKey<V>(field: Field<V>, key: string, ...aliases: string[]): Field<V> {
  return { ...field, key, aliases };
}

/** Characters a legitimate value can contain; anything else is rejected outright. */
export const SAFE_VALUE = /^[0-9A-Za-z.,;_+-]*$/;

/** Reads a plain decimal number (no hex, no Infinity, no NaN); null if it is not one. */
export function parseNumber(text: string): number | null {
  if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(text)) return null;
  const value = Number(text);
  return Number.isFinite(value) ? value : null;
}

/** Shortest decimal that reads back within 1e-9 relative: keeps links short and exact enough. */
export function formatNumber(value: number): string {
  if (Number.isInteger(value)) return String(value);
  return String(Number(value.toPrecision(10)));
}

/** "1 point", "3 points". */
export const count = (n: number, noun: string) => `${n} ${noun}${n === 1 ? '' : 's'}`;

/** A raw value quoted for a message, cut short. */
export function quote(text: string): string {
  const shown = text.length > 24 ? `${text.slice(0, 24)}…` : text;
  return JSON.stringify(shown);
}

const ok = <V>(value: V): FieldResult<V> => ({ ok: true, value });
const fail = <V>(why: string): FieldResult<V> => ({ ok: false, why });

/** A number in [min, max]. */
export function number(options: { default: number; min: number; max: number }): Field<number> {
  return {
    default: options.default,
    encode: formatNumber,
    decode(raw) {
      const v = parseNumber(raw);
      if (v === null) return fail(`${quote(raw)} is not a number`);
      if (v < options.min || v > options.max)
        return fail(`${quote(raw)} is outside ${options.min} to ${options.max}`);
      return ok(v);
    },
  };
}

/** A whole number in [min, max]. */
export function int(options: { default: number; min: number; max: number }): Field<number> {
  const base = number(options);
  return {
    ...base,
    decode(raw) {
      const v = parseNumber(raw);
      if (v !== null && !Number.isInteger(v)) return fail(`${quote(raw)} is not a whole number`);
      return base.decode(raw);
    },
  };
}

/** The largest step a link may name: past a construction's last, the last is shown. */
const LAST_STEP_IN_A_LINK = 999;

/**
 * The step of a lesson's construction. Its last step depends on the state
 * (the scene, the points), so the field takes any step a link gives and the
 * kit shows one past the last as the last, saying so (normalizeState): one
 * rule for every lesson, where a maximum of each lesson's own sent some links
 * to step 0 ("the default was used") and others to the last step.
 */
export function stepField(): Field<number> {
  return int({ default: 0, min: 0, max: LAST_STEP_IN_A_LINK });
}

export function bool(options: { default: boolean }): Field<boolean> {
  return {
    default: options.default,
    encode: (v) => (v ? '1' : '0'),
    decode(raw) {
      if (raw === '1' || raw === 'true') return ok(true);
      if (raw === '0' || raw === 'false') return ok(false);
      return fail(`${quote(raw)} is not 0 or 1`);
    },
  };
}

/** One of a few named values. */
export function choice<V extends string>(options: { default: V; values: readonly V[] }): Field<V> {
  return {
    default: options.default,
    encode: (v) => v,
    decode(raw) {
      if ((options.values as readonly string[]).includes(raw)) return ok(raw as V);
      return fail(`${quote(raw)} is not one of ${options.values.join(', ')}`);
    },
  };
}

export interface ListOptions {
  min: number;
  max: number;
  /** Range of each value. */
  low: number;
  high: number;
  /** What one value is called in messages (default "value"). */
  noun?: string;
}

/** A list of numbers, each in [low, high], separated by commas. */
export function numbers(
  options: ListOptions & {
    default: readonly number[];
    check?: (values: number[]) => string | null;
  },
): Field<number[]> {
  const noun = options.noun ?? 'value';
  return {
    default: [...options.default],
    encode: (values) => values.map(formatNumber).join(','),
    decode(raw) {
      const items = raw === '' ? [] : raw.split(',');
      if (items.length > options.max)
        return fail(`${count(items.length, noun)} given, at most ${options.max} allowed`);
      const values: number[] = [];
      for (const item of items) {
        const v = parseNumber(item);
        if (v === null || v < options.low || v > options.high)
          return fail(`${quote(item)} is not a number from ${options.low} to ${options.high}`);
        values.push(v);
      }
      if (values.length < options.min)
        return fail(`${count(values.length, noun)} given, at least ${options.min} needed`);
      const problem = options.check?.(values);
      return problem ? fail(problem) : ok(values);
    },
  };
}

/** A knot vector: numbers that never decrease. */
export function knots(
  options: Omit<ListOptions, 'noun'> & { default: readonly number[] },
): Field<number[]> {
  return numbers({
    ...options,
    noun: 'knot',
    check: (values) => {
      const i = values.findIndex((v, k) => k > 0 && v < values[k - 1]);
      return i < 0
        ? null
        : `knot ${i} (${formatNumber(values[i])}) is below knot ${i - 1} (${formatNumber(values[i - 1])}): knots never decrease`;
    },
  });
}

/** Weights of rational curves: positive numbers. */
export function weights(
  options: Omit<ListOptions, 'noun' | 'low'> & { default: readonly number[] },
): Field<number[]> {
  return numbers({
    ...options,
    low: 0,
    noun: 'weight',
    check: (values) => (values.some((v) => v <= 0) ? 'every weight must be above 0' : null),
  });
}

export interface PointOptions {
  /** Coordinates per point: 2 (x,y) or 3 (x,y,z). */
  dimension?: 2 | 3;
  /** Largest absolute coordinate accepted (default 1e6). */
  limit?: number;
}

function readPoint(item: string, dimension: number, limit: number): FieldResult<Point> {
  const coords = item.split(',');
  const shape = dimension === 3 ? 'x,y,z' : 'x,y';
  if (coords.length !== dimension) return fail(`${quote(item)} is not a point ${shape}`);
  const point: number[] = [];
  for (const text of coords) {
    const v = parseNumber(text);
    if (v === null)
      return fail(`${quote(item)} is not a point of ${dimension === 3 ? 'three' : 'two'} numbers`);
    if (Math.abs(v) > limit) return fail(`${quote(item)} is beyond ±${limit}`);
    point.push(v);
  }
  return ok(point);
}

const writePoint = (p: Point) => p.map(formatNumber).join(',');

/** A list of points `x,y;x,y;…` (or `x,y,z;…`), between min and max of them. */
export function points(
  options: PointOptions & { default: readonly Point[]; min: number; max: number },
): Field<Point[]> {
  const dimension = options.dimension ?? 2;
  const limit = options.limit ?? 1e6;
  return {
    default: options.default.map((p) => [...p]),
    encode: (list) => list.map(writePoint).join(';'),
    decode(raw) {
      const items = raw === '' ? [] : raw.split(';');
      // Too many is refused before anything is parsed; what is there must be
      // points before their number matters ("garbage" is not "1 point").
      if (items.length > options.max)
        return fail(`${count(items.length, 'point')} given, at most ${options.max} allowed`);
      const list: Point[] = [];
      for (const item of items) {
        const point = readPoint(item, dimension, limit);
        if (!point.ok) return point as FieldResult<Point[]>;
        list.push(point.value);
      }
      if (list.length < options.min)
        return fail(`${count(list.length, 'point')} given, at least ${options.min} needed`);
      return ok(list);
    },
  };
}

/**
 * A rows × columns grid of points (a surface patch's control net), row by
 * row: `x,y,z;x,y,z;…` with exactly rows·columns points.
 */
export function pointGrid(
  options: PointOptions & { default: readonly (readonly Point[])[]; rows: number; columns: number },
): Field<Point[][]> {
  const flat = points({ ...options, default: [], min: 0, max: options.rows * options.columns });
  const total = options.rows * options.columns;
  return {
    default: options.default.map((row) => row.map((p) => [...p])),
    encode: (grid) => flat.encode(grid.flat()),
    decode(raw) {
      const list = flat.decode(raw);
      if (!list.ok) return list as FieldResult<Point[][]>;
      if (list.value.length !== total)
        return fail(
          `${count(list.value.length, 'point')} given, a ${options.rows} × ${options.columns} grid needs ${total}`,
        );
      const grid: Point[][] = [];
      for (let r = 0; r < options.rows; r++)
        grid.push(list.value.slice(r * options.columns, (r + 1) * options.columns));
      return ok(grid);
    },
  };
}
