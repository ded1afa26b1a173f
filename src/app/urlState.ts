/**
 * A lesson's whole state (points, t, step, options) lives in the URL hash in a
 * compact, human-readable form, e.g. `p=0,0;1,2;3,2;4,0&t=0.5&step=2&split=1`,
 * so a lecturer can write or edit links by hand before class.
 *
 * Every field is described by a schema entry; decoding is strict per field:
 * a field that is malformed, hostile or out of range falls back to its default
 * and is reported, while the valid fields are kept.
 */

export type Point2 = readonly [number, number];

export interface PointsField {
  kind: 'points';
  default: readonly Point2[];
  min: number;
  max: number;
  /** Largest absolute coordinate accepted (default 1e6). */
  limit?: number;
}
export interface NumberField {
  kind: 'number';
  default: number;
  min: number;
  max: number;
}
export interface IntField {
  kind: 'int';
  default: number;
  min: number;
  max: number;
}
export interface BoolField {
  kind: 'bool';
  default: boolean;
}
export interface EnumField<V extends string = string> {
  kind: 'enum';
  default: V;
  values: readonly V[];
}
export interface NumbersField {
  kind: 'numbers';
  default: readonly number[];
  min: number;
  max: number;
  /** Range of each value. */
  low: number;
  high: number;
}

export type Field = PointsField | NumberField | IntField | BoolField | EnumField | NumbersField;

// Brackets keep a union of strings (an enum) from being split into one field per member.
type FieldFor<V> = [V] extends [readonly Point2[]]
  ? PointsField
  : [V] extends [readonly number[]]
    ? NumbersField
    : [V] extends [boolean]
      ? BoolField
      : [V] extends [number]
        ? NumberField | IntField
        : [V] extends [string]
          ? EnumField<V>
          : never;

/** The schema of a lesson state `S`: one field per key. */
export type Schema<S> = { readonly [K in keyof S]: FieldFor<S[K]> };

export interface Decoded<S> {
  state: S;
  /** What was ignored, in words a person understands; empty when all was valid. */
  issues: string[];
}

/** Longest query string we read at all: a real state is far shorter. */
export const MAX_QUERY_LENGTH = 20_000;

export function defaultsOf<S>(schema: Schema<S>): S {
  const state: Record<string, unknown> = {};
  for (const key of Object.keys(schema) as (keyof S & string)[]) {
    const field = schema[key] as Field;
    state[key] = copyValue(field.default);
  }
  return state as S;
}

function copyValue(value: Field['default']): unknown {
  if (Array.isArray(value)) {
    return value.map((v: unknown) => (Array.isArray(v) ? [...v] : v));
  }
  return value;
}

/** Shortest decimal that reads back within 1e-9 relative: keeps links short and exact enough. */
export function formatNumber(value: number): string {
  if (Number.isInteger(value)) return String(value);
  const short = Number(value.toPrecision(10));
  return String(short);
}

function encodeField(field: Field, value: unknown): string {
  switch (field.kind) {
    case 'points':
      return (value as readonly Point2[])
        .map((p) => `${formatNumber(p[0])},${formatNumber(p[1])}`)
        .join(';');
    case 'numbers':
      return (value as readonly number[]).map(formatNumber).join(',');
    case 'number':
    case 'int':
      return formatNumber(value as number);
    case 'bool':
      return value ? '1' : '0';
    case 'enum':
      return String(value);
  }
}

/** The state as a query string, fields in schema order. */
export function encodeState<S>(schema: Schema<S>, state: S): string {
  const parts: string[] = [];
  for (const key of Object.keys(schema) as (keyof S & string)[]) {
    parts.push(`${key}=${encodeField(schema[key] as Field, state[key])}`);
  }
  return parts.join('&');
}

/** Characters a legitimate value can contain; anything else is rejected outright. */
const SAFE_VALUE = /^[0-9A-Za-z.,;_+-]*$/;

function parseNumber(text: string): number | null {
  if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(text)) return null;
  const value = Number(text);
  return Number.isFinite(value) ? value : null;
}

/** "1 point", "3 points". */
const count = (n: number, noun: string) => `${n} ${noun}${n === 1 ? '' : 's'}`;

function describe(text: string): string {
  const shown = text.length > 24 ? `${text.slice(0, 24)}…` : text;
  return JSON.stringify(shown);
}

type FieldResult = { ok: true; value: unknown } | { ok: false; why: string };

function decodeField(field: Field, raw: string): FieldResult {
  if (!SAFE_VALUE.test(raw))
    return { ok: false, why: `${describe(raw)} has characters that do not belong` };
  switch (field.kind) {
    case 'points': {
      const items = raw === '' ? [] : raw.split(';');
      // Too many is refused before anything is parsed; what is there must be
      // points before their number matters ("garbage" is not "1 point").
      if (items.length > field.max) {
        return {
          ok: false,
          why: `${count(items.length, 'point')} given, at most ${field.max} allowed`,
        };
      }
      const limit = field.limit ?? 1e6;
      const points: Point2[] = [];
      for (const item of items) {
        const coords = item.split(',');
        if (coords.length !== 2) return { ok: false, why: `${describe(item)} is not a point x,y` };
        const x = parseNumber(coords[0]);
        const y = parseNumber(coords[1]);
        if (x === null || y === null) {
          return { ok: false, why: `${describe(item)} is not a point of two numbers` };
        }
        if (Math.abs(x) > limit || Math.abs(y) > limit) {
          return { ok: false, why: `${describe(item)} is beyond ±${limit}` };
        }
        points.push([x, y]);
      }
      if (points.length < field.min) {
        return {
          ok: false,
          why: `${count(points.length, 'point')} given, at least ${field.min} needed`,
        };
      }
      return { ok: true, value: points };
    }
    case 'numbers': {
      const items = raw === '' ? [] : raw.split(',');
      if (items.length > field.max) {
        return {
          ok: false,
          why: `${count(items.length, 'value')} given, at most ${field.max} allowed`,
        };
      }
      const values: number[] = [];
      for (const item of items) {
        const v = parseNumber(item);
        if (v === null || v < field.low || v > field.high) {
          return {
            ok: false,
            why: `${describe(item)} is not a number from ${field.low} to ${field.high}`,
          };
        }
        values.push(v);
      }
      if (values.length < field.min) {
        return {
          ok: false,
          why: `${count(values.length, 'value')} given, at least ${field.min} needed`,
        };
      }
      return { ok: true, value: values };
    }
    case 'number':
    case 'int': {
      const v = parseNumber(raw);
      if (v === null) return { ok: false, why: `${describe(raw)} is not a number` };
      if (field.kind === 'int' && !Number.isInteger(v))
        return { ok: false, why: `${describe(raw)} is not a whole number` };
      if (v < field.min || v > field.max) {
        return { ok: false, why: `${describe(raw)} is outside ${field.min} to ${field.max}` };
      }
      return { ok: true, value: v };
    }
    case 'bool':
      if (raw === '1' || raw === 'true') return { ok: true, value: true };
      if (raw === '0' || raw === 'false') return { ok: true, value: false };
      return { ok: false, why: `${describe(raw)} is not 0 or 1` };
    case 'enum':
      if ((field.values as readonly string[]).includes(raw)) return { ok: true, value: raw };
      return { ok: false, why: `${describe(raw)} is not one of ${field.values.join(', ')}` };
  }
}

/**
 * Reads a query string against the schema. Never throws: whatever cannot be
 * read is replaced by its default and listed in `issues`.
 */
export function decodeState<S>(schema: Schema<S>, query: string): Decoded<S> {
  const state = defaultsOf(schema) as Record<string, unknown>;
  const issues: string[] = [];
  if (query.length > MAX_QUERY_LENGTH) {
    issues.push(
      `the link's state is ${query.length} characters long (at most ${MAX_QUERY_LENGTH}), so all of it was ignored`,
    );
    return { state: state as S, issues };
  }
  if (query === '') return { state: state as S, issues };
  const seen = new Set<string>();
  for (const part of query.split('&')) {
    if (part === '') continue;
    const eq = part.indexOf('=');
    const rawKey = eq < 0 ? part : part.slice(0, eq);
    let raw = eq < 0 ? '' : part.slice(eq + 1);
    let key = rawKey;
    try {
      key = decodeURIComponent(rawKey);
      raw = decodeURIComponent(raw);
    } catch {
      issues.push(`${describe(rawKey)}: not readable`);
      continue;
    }
    if (!Object.prototype.hasOwnProperty.call(schema, key)) {
      issues.push(`unknown setting ${describe(key)}`);
      continue;
    }
    if (seen.has(key)) {
      issues.push(`${key} given twice; the first was kept`);
      continue;
    }
    seen.add(key);
    const result = decodeField(schema[key as keyof S] as Field, raw);
    if (result.ok) state[key] = result.value;
    else issues.push(`${key}: ${result.why}; the default was used`);
  }
  return { state: state as S, issues };
}
