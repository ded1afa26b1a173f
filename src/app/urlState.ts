/**
 * A lesson's whole state (points, t, step, options) lives in the URL hash in a
 * compact, human-readable form, e.g. `p=0,0;1,2;3,2;4,0&t=0.5&step=2&split=1`,
 * so a lecturer can write or edit links by hand before class.
 *
 * Every field is described by a schema entry of some kind (see fields.ts);
 * decoding is strict per field: a field that is malformed, hostile or out of
 * range falls back to its default and is reported, while the valid fields
 * are kept. Keys the shell owns (a figure's view, `view.<figure>`) are read
 * apart from the lesson's.
 */
import { type Field, SAFE_VALUE, quote } from './fields';

export type { Field } from './fields';
import { DEFAULT_LETTER, LETTER_KEY, type Letter, parseLetter } from '../render/notation';

/** The schema of a lesson state `S`: one field per key. */
export type Schema<S> = { readonly [K in keyof S]: Field<S[K]> };

export interface Decoded<S> {
  state: S;
  /** What was ignored, in words a person understands; empty when all was valid. */
  issues: string[];
  /** The views of figures the link names (`view.<figure>` = the projection's own text). */
  views: Record<string, string>;
  /** The scene the link names (`scene=<id>`), as an index into the lesson's scenes; 0 without one. */
  scene: number;
  /** Whether the link named a scene it has (then its fields are read over that scene's setup). */
  sceneNamed: boolean;
  /** The fields the link gave, by name (the rest are defaults). */
  given: ReadonlySet<keyof S & string>;
  /** The exercise the link opens (`ex=<id>&seed=<n>`), or null. */
  practice: PracticeLink | null;
}

/** An exercise and the seed of its numbers, as a link carries them. */
export interface PracticeLink {
  id: string;
  seed: number;
  /** The link also carries the figure as the student left it (fields of the state). */
  kept?: boolean;
}

/** The keys of an exercise's link (owned by the shell, like the scene). */
export const EXERCISE_KEY = 'ex';
export const SEED_KEY = 'seed';

/** The link of an exercise: its id and seed say everything it shows. */
export const practiceQuery = (practice: PracticeLink) =>
  `${EXERCISE_KEY}=${encodeURIComponent(practice.id)}&${SEED_KEY}=${practice.seed}`;

/** Where in a link the exercise's keys go: first, before the state they were posed with. */
export const withPractice = (practice: PracticeLink | null, query: string) =>
  practice ? `${practiceQuery(practice)}${query ? `&${query}` : ''}` : query;

/** Longest query string we read at all: a real state is far shorter. */
/**
 * The parameter's letter a link names (`par=mu`, the shell's like the scene),
 * taken out of the query: the rest is the lesson's. A letter that is none of
 * μ, u, t is said, and the reader's own letter stays.
 */
export function takeLetter(query: string): {
  letter: Letter | null;
  issue: string | null;
  rest: string;
} {
  let letter: Letter | null = null;
  let issue: string | null = null;
  const rest = query.split('&').filter((part) => {
    if (!part.startsWith(`${LETTER_KEY}=`)) return true;
    let raw = part.slice(LETTER_KEY.length + 1);
    try {
      raw = decodeURIComponent(raw);
    } catch {
      // Left as written: it is refused below.
    }
    const parsed = parseLetter(raw);
    if (parsed && letter === null) letter = parsed;
    else if (!parsed)
      issue = `${LETTER_KEY}: ${quote(raw)} is not a letter for the parameter (mu, u or t), so it is written as before`;
    return false;
  });
  return { letter, issue, rest: rest.join('&') };
}

/** A lesson's query with the reader's letter in front, when it is not the usual one. */
export const withLetter = (letter: Letter, query: string) =>
  letter === DEFAULT_LETTER ? query : `${LETTER_KEY}=${letter}${query ? `&${query}` : ''}`;

export const MAX_QUERY_LENGTH = 20_000;

/** Prefix of the keys that carry a figure's view (pan and zoom, or camera). */
export const VIEW_PREFIX = 'view.';

/** The key of the lesson's current scene (owned by the shell, like the views). */
export const SCENE_KEY = 'scene';

function copy<V>(value: V): V {
  return (Array.isArray(value) ? value.map((v) => copy(v)) : value) as V;
}

export function defaultsOf<S>(schema: Schema<S>): S {
  const state: Record<string, unknown> = {};
  for (const key of Object.keys(schema) as (keyof S & string)[]) {
    state[key] = copy(schema[key].default);
  }
  return state as S;
}

/** The field's key in the link: its own short key, else its name. */
export const keyOf = <S>(schema: Schema<S>, name: keyof S & string): string =>
  schema[name].key ?? name;

/** Every key the link may use for each field (its key, its name, its earlier keys) → the field's name. */
function fieldsByKey<S>(schema: Schema<S>): Map<string, keyof S & string> {
  const names = Object.keys(schema) as (keyof S & string)[];
  const byKey = new Map<string, keyof S & string>();
  // Current keys first, so an old alias never shadows another field's key.
  for (const name of names) byKey.set(keyOf(schema, name), name);
  for (const name of names)
    for (const alias of [name, ...(schema[name].aliases ?? [])])
      if (!byKey.has(alias)) byKey.set(alias, name);
  return byKey;
}

/**
 * The state as a query string: the scene (if the lesson has scenes), the
 * fields in schema order, then the views in figure order.
 */
export function encodeState<S>(
  schema: Schema<S>,
  state: S,
  views: Readonly<Record<string, string>> = {},
  scene?: string,
): string {
  const parts: string[] = [];
  if (scene !== undefined) parts.push(`${SCENE_KEY}=${scene}`);
  for (const name of Object.keys(schema) as (keyof S & string)[]) {
    parts.push(`${keyOf(schema, name)}=${schema[name].encode(state[name])}`);
  }
  for (const [figure, view] of Object.entries(views)) parts.push(`${VIEW_PREFIX}${figure}=${view}`);
  return parts.join('&');
}

/**
 * Reads a query string against the schema. Never throws: whatever cannot be
 * read is replaced by its default and listed in `issues`.
 */
export function decodeState<S>(
  schema: Schema<S>,
  query: string,
  figures: readonly string[] = [],
  scenes: readonly string[] = [],
  exercises: readonly string[] = [],
): Decoded<S> {
  const state = defaultsOf(schema) as Record<string, unknown>;
  const issues: string[] = [];
  const views: Record<string, string> = {};
  let scene = 0;
  let exercise: string | null = null;
  let seed: number | null = null;
  if (query.length > MAX_QUERY_LENGTH) {
    issues.push(
      `the link's state is ${query.length} characters long (at most ${MAX_QUERY_LENGTH}), so all of it was ignored`,
    );
    return {
      state: state as S,
      issues,
      views,
      scene,
      sceneNamed: false,
      given: new Set(),
      practice: null,
    };
  }
  const seen = new Set<string>();
  const byKey = fieldsByKey(schema);
  const given = new Set<keyof S & string>();
  let sceneNamed = false;
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
      issues.push(`${quote(rawKey)}: not readable`);
      continue;
    }
    if (seen.has(key)) {
      issues.push(`${quote(key)} given twice; the first was kept`);
      continue;
    }
    if (key.startsWith(VIEW_PREFIX) && figures.includes(key.slice(VIEW_PREFIX.length))) {
      seen.add(key);
      if (SAFE_VALUE.test(raw)) views[key.slice(VIEW_PREFIX.length)] = raw;
      else
        issues.push(`${key}: ${quote(raw)} has characters that do not belong; the view was fitted`);
      continue;
    }
    if (key === SCENE_KEY && scenes.length > 0) {
      seen.add(key);
      const index = scenes.indexOf(raw);
      if (index >= 0) {
        scene = index;
        sceneNamed = true;
      } else
        issues.push(
          `${SCENE_KEY}: ${quote(raw)} is not a scene of this lesson; the script starts at its first`,
        );
      continue;
    }
    if (key === EXERCISE_KEY && exercises.length > 0) {
      seen.add(key);
      if (exercises.includes(raw)) exercise = raw;
      else issues.push(`${EXERCISE_KEY}: ${quote(raw)} is not an exercise of this lesson`);
      continue;
    }
    if (key === SEED_KEY && exercises.length > 0) {
      seen.add(key);
      const n = Number(raw);
      if (/^[0-9]{1,6}$/.test(raw) && n >= 1) seed = n;
      else issues.push(`${SEED_KEY}: ${quote(raw)} is not a whole number from 1 to 999999`);
      continue;
    }
    const name = byKey.get(key);
    if (name === undefined) {
      issues.push(`unknown setting ${quote(key)}`);
      continue;
    }
    // A field given under two of its keys (its key and an old alias): the first is kept.
    if (given.has(name)) {
      issues.push(`${quote(key)} given twice; the first was kept`);
      continue;
    }
    seen.add(key);
    given.add(name);
    if (!SAFE_VALUE.test(raw)) {
      issues.push(`${key}: ${quote(raw)} has characters that do not belong; the default was used`);
      continue;
    }
    const result = schema[name].decode(raw);
    if (result.ok) state[name] = result.value;
    else issues.push(`${key}: ${result.why}; the default was used`);
  }
  if (seed !== null && exercise === null && !issues.some((i) => i.startsWith(EXERCISE_KEY)))
    issues.push(`${SEED_KEY}: a seed without an exercise (ex=…) was ignored`);
  const practice =
    exercise === null ? null : { id: exercise, seed: seed ?? 1, kept: given.size > 0 };
  return { state: state as S, issues, views, scene, sceneNamed, given, practice };
}
