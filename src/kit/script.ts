/**
 * A scene's script: its steps in teaching order, each named after what it
 * reveals, with its caption and formula side by side (as a presenter's script
 * reads). A step may repeat (the levels of a construction, the rows of a
 * system): it is then one declaration for as many presses as the state asks.
 *
 * Drawing code asks what is shown by name (`shown.has('polygon')`,
 * `shown.count('level')`), never compares step numbers: inserting a step
 * anywhere moves every later number and no drawing code changes.
 * (After reveal.js fragments, declared on the thing revealed, and Motion
 * Canvas's named slides.)
 */

/** What a caption or a formula is given: the state, its model, and which repeat this is. */
export interface StepAt<S, M> {
  state: S;
  model: M;
  /** 1, 2, … for a repeated step (level 1, level 2); 0 for a step that does not repeat. */
  index: number;
  /** How many times this step repeats now (1 for a step that does not repeat). */
  times: number;
}

type Text<S, M> = string | ((at: StepAt<S, M>) => string);

/** One declared step (or run of repeated steps). */
export interface StepSpec<S, M, N extends string = string> {
  readonly name: N;
  /** For a repeated step: how many presses it takes in this state (may be 0). */
  readonly times?: (state: S) => number;
  /** What the step shows, in one short sentence of words and Unicode (no TeX). */
  readonly caption: Text<S, M>;
  /** The step's formula with its numbers (TeX), or null where it has none. */
  readonly formula?: (at: StepAt<S, M>) => string | null;
  /**
   * The same formula laid out for a narrow box (a laptop's side panel, a
   * phone), where `formula` is laid out for the projector's width: fewer
   * terms a line, a table turned on its side. See `narrow`.
   */
  readonly narrow?: (at: StepAt<S, M>) => string | null;
}

/** `spec` with a layout of its formula for a narrow box (the panel's copy). */
export const narrow = <S, M, N extends string>(
  spec: StepSpec<S, M, N>,
  formula: (at: StepAt<S, M>) => string | null,
): StepSpec<S, M, N> => ({ ...spec, narrow: formula });

/** A step shown once. */
export function step<S, M, N extends string>(
  name: N,
  caption: Text<S, M>,
  formula?: (at: StepAt<S, M>) => string | null,
): StepSpec<S, M, N> {
  return { name, caption, formula };
}

/** A step repeated `times(state)` times: one press for each (level 1 … n). */
export function repeat<S, M, N extends string>(
  name: N,
  times: (state: S) => number,
  caption: Text<S, M>,
  formula?: (at: StepAt<S, M>) => string | null,
): StepSpec<S, M, N> {
  return { name, times, caption, formula };
}

/**
 * What the current step has revealed: every step up to and including it.
 * Made once per state by `Script.shown`, and read by figures and panels.
 */
export class Revealed<N extends string = string> {
  private readonly reached: ReadonlyMap<string, number>;

  constructor(
    /** The current step's number, 0 … last. */
    readonly k: number,
    /** The number of the script's last step. */
    readonly lastStep: number,
    /** The current step's name. */
    readonly name: N,
    /** For a repeated current step, which repeat it is (1-based); else 0. */
    readonly index: number,
    reached: ReadonlyMap<string, number>,
  ) {
    this.reached = reached;
  }

  /** The step `name` has been reached (for a repeated one: its `index`-th repeat, or its first). */
  has(name: N, index = 1): boolean {
    return (this.reached.get(name) ?? 0) >= index;
  }

  /** How many repeats of `name` have been reached (for a step shown once: 0 or 1). */
  count(name: N): number {
    return this.reached.get(name) ?? 0;
  }

  /** Every step reached so far is one of `names` (what a figure needs none of its other inputs for). */
  only(names: readonly N[]): boolean {
    for (const name of this.reached.keys()) if (!names.includes(name as N)) return false;
    return true;
  }

  /** The current step is `name` (what only this step says, e.g. a label of its own). */
  is(name: N): boolean {
    return this.name === name;
  }

  /** The script is at its last step: everything is shown. */
  get last(): boolean {
    return this.k >= this.lastStep;
  }

  /**
   * One string for everything this says (two Revealed with the same key show
   * the same), for a figure's `drawnFrom`: made once per state's Revealed.
   */
  get key(): string {
    this.keyText ??= [this.k, this.lastStep, this.name, this.index, ...this.reached].join('|');
    return this.keyText;
  }

  private keyText: string | undefined;
}

/** Where step k falls: its declaration, and which repeat of it. */
interface Place<S, M> {
  spec: StepSpec<S, M>;
  index: number;
  times: number;
}

/** The steps of a scene, in teaching order. */
export class Script<S, M, N extends string = string> {
  constructor(readonly steps: readonly StepSpec<S, M, N>[]) {
    const names = steps.map((s) => s.name);
    const twice = names.find((name, i) => names.indexOf(name) !== i);
    if (twice !== undefined) throw new Error(`Script: the step name "${twice}" is used twice`);
  }

  /** Every press of this state's script, in order. */
  private places(state: S): Place<S, M>[] {
    const places: Place<S, M>[] = [];
    for (const spec of this.steps) {
      if (!spec.times) {
        places.push({ spec, index: 0, times: 1 });
        continue;
      }
      const times = Math.max(0, Math.floor(spec.times(state)));
      for (let index = 1; index <= times; index++) places.push({ spec, index, times });
    }
    return places;
  }

  /** The number of the last step (steps run 0 … lastStep). */
  lastStep(state: S): number {
    return this.places(state).length - 1;
  }

  /** What steps 0 … k reveal; k is clamped to the script. */
  shown(state: S, k: number): Revealed<N> {
    const places = this.places(state);
    const at = Math.max(0, Math.min(places.length - 1, Math.floor(k)));
    const reached = new Map<string, number>();
    for (let i = 0; i <= at; i++) {
      const { spec, index } = places[i];
      reached.set(spec.name, Math.max(reached.get(spec.name) ?? 0, index === 0 ? 1 : index));
    }
    const here = places[at];
    return new Revealed<N>(at, places.length - 1, here.spec.name as N, here.index, reached);
  }

  /** Step k's caption. */
  caption(state: S, model: M, k: number): string {
    const place = this.place(state, k);
    const { caption } = place.spec;
    return typeof caption === 'string' ? caption : caption(this.at(state, model, place));
  }

  /** Step k's formula, or null; `narrowBox`: laid out for a narrow box, where the step has such a layout. */
  formula(state: S, model: M, k: number, narrowBox = false): string | null {
    const place = this.place(state, k);
    const layout = (narrowBox && place.spec.narrow) || place.spec.formula;
    return layout?.(this.at(state, model, place)) ?? null;
  }

  /** The step number of the first (or `index`-th) repeat of `name`; −1 if the script has none now. */
  stepOf(state: S, name: N, index = 1): number {
    return this.places(state).findIndex(
      (p) => p.spec.name === name && (p.index === 0 || p.index === index),
    );
  }

  /**
   * The step after an edit that changes how many steps there are (a point
   * added): a script shown to its end stays shown to its end; otherwise the
   * step stays where it was (within the new script).
   */
  keepEnd(before: S, step: number, after: S): number {
    const last = this.lastStep(after);
    return step >= this.lastStep(before) ? last : Math.min(step, last);
  }

  /** `after` (an edit of `before`) with its step field kept at the end if `before` was at its end. */
  keptAtEnd<K extends keyof S>(before: S, after: S, field: K): S {
    const step = this.keepEnd(before, before[field] as unknown as number, after);
    return { ...after, [field]: step };
  }

  private place(state: S, k: number): Place<S, M> {
    const places = this.places(state);
    return places[Math.max(0, Math.min(places.length - 1, Math.floor(k)))];
  }

  private at(state: S, model: M, place: Place<S, M>): StepAt<S, M> {
    return { state, model, index: place.index, times: place.times };
  }
}

/** A script from its steps (the names are checked to be unique). */
export const script = <S, M, N extends string>(...steps: StepSpec<S, M, N>[]): Script<S, M, N> =>
  new Script(steps);
