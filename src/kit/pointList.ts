/**
 * A list of points the user moves, declared once (after mafs' `useMovable`
 * with `constrain`): the declaration gives the figure's handles with their
 * accessible names, the drag and keyboard moves (through the shell), the
 * constraint, adding a point where a person sketches it and removing one,
 * and the panel's "add / remove a point" buttons. Ids are typed: a lesson
 * never parses a handle id back into an index.
 */
import type { Handle } from '../app/lesson';
import { type Control, pointButtons } from '../app/panelControls';
import { extendPolygon, insertPoint } from '../interact/editPoints';
import type { Point } from '../math';
import { stackedLabels } from './labels';

/** Which point of which list: what a lesson is handed instead of a handle's id. */
export interface PointRef {
  /** The list's id (its field in the state). */
  list: string;
  index: number;
}

export interface PointListSpec<S> {
  /** The list's id: also the prefix of its handles' ids (`p` → `p0`, `p1`, …). */
  id: string;
  /** The points in the state. */
  get(state: S): readonly Point[];
  /** The state with these points (a new state; the points are new arrays). */
  set(state: S, points: Point[]): S;
  /** The point's name in lecture notation, with subscripts after `_` (`P_{3}`). */
  label(index: number): string;
  /** Fewest and most points the lesson allows (adding and removing stop there). */
  min: number;
  max: number;
  /**
   * Where point `index` may go when dragged to `to` (to a line, to an order);
   * without it, anywhere.
   */
  constrain?(state: S, index: number, to: Point): Point;
  /** Extra handle settings for point `index` (colour, shape, size, …). */
  style?(index: number, state: S): Omit<Handle, 'id' | 'label' | 'position'>;
  /**
   * After an edit that adds or removes a point, the state's other fields (a
   * step shown to its end stays at the end, say): `before` is the state before.
   */
  after?(before: S, after: S): S;
  /** Button texts, when the points are not "control points". */
  addLabel?: string;
  removeLabel?: string;
}

/** What one declaration gives a figure and a panel. */
export interface PointList<S> {
  readonly id: string;
  /** Points can be added or removed (fewer allowed than most): a fixed list offers neither. */
  readonly resizable: boolean;
  /** The handles the shell draws, drags and moves by keyboard. */
  handles(state: S): Handle[];
  /** The handle with this id is one of this list's: which point it is, else null. */
  ref(handleId: string): PointRef | null;
  /** The state with point `index` at `to` (constrained). */
  move(state: S, index: number, to: Point): S;
  /** A point added where the user pointed (into the nearest edge); null at the most points. */
  add(state: S, at: Point): S | null;
  /** Point `index` removed; null at the fewest points. */
  remove(state: S, index: number): S | null;
  /** "Add a control point" / "Remove the last control point" for the panel. */
  buttons(api: { get(): S; set(next: S): void }): Control<S>;
}

export function pointList<S>(spec: PointListSpec<S>): PointList<S> {
  const handleId = (index: number) => `${spec.id}${index}`;
  const pattern = new RegExp(`^${spec.id.replace(/[^A-Za-z0-9]/g, '')}(\\d+)$`);
  const edited = (before: S, points: Point[]) => {
    const after = spec.set(before, points);
    return spec.after ? spec.after(before, after) : after;
  };
  return {
    id: spec.id,
    resizable: spec.min < spec.max,
    handles(state) {
      const points = spec.get(state);
      // Points on one spot share one label (`P_0 = P_1`); each keeps its own spoken name.
      const labels = stackedLabels(points, spec.label);
      return points.map((position, index) => ({
        ...spec.style?.(index, state),
        id: handleId(index),
        ...labels[index],
        position,
      }));
    },
    ref(id) {
      const match = pattern.exec(id);
      if (!match) return null;
      return { list: spec.id, index: Number(match[1]) };
    },
    move(state, index, to) {
      const at = spec.constrain ? spec.constrain(state, index, to) : to;
      const points = spec.get(state).map((p, k) => (k === index ? [...at] : p));
      return spec.set(state, points);
    },
    add(state, at) {
      const points = spec.get(state);
      if (points.length >= spec.max) return null;
      return edited(state, insertPoint(points, [at[0], at[1]] as Point));
    },
    remove(state, index) {
      const points = spec.get(state);
      if (points.length <= spec.min) return null;
      return edited(
        state,
        points.filter((_, k) => k !== index),
      );
    },
    buttons: (api) =>
      pointButtons(api, {
        addLabel: spec.addLabel ?? 'Add a control point',
        removeLabel: spec.removeLabel ?? 'Remove the last control point',
        count: (s) => spec.get(s).length,
        min: spec.min,
        max: spec.max,
        add: (s) => edited(s, [...spec.get(s), extendPolygon(spec.get(s))]),
        remove: (s) => edited(s, spec.get(s).slice(0, -1)),
      }),
  };
}
