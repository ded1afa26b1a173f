/**
 * A lesson made of the kit: its state schema, its scenes in teaching order,
 * one script of named steps (or one per scene), its figures with their point
 * lists, and its panel. `defineLesson` turns it into what the shell hosts, so
 * the shell's clicker, links, presenter view, undo and export work unchanged.
 */
import type {
  DrawInfo,
  FigureSpec,
  HandoutTable,
  Handle,
  LayoutNode,
  LessonApi,
  LessonDefinition,
  LessonPanel,
  NumberKeys,
  ParameterSpec,
} from '../app/lesson';
import type { Schema } from '../app/urlState';
import type { Point } from '../math';
import type { ExerciseSpec } from './exercise';
import type { Letter } from '../render/notation';
import type { Painter } from '../render/painter';
import { boundsOf, unionBounds } from '../render/projection';
import { subscriptNames } from './format';
import type { PointList } from './pointList';
import type { Script, Revealed } from './script';

/** A scene: a figure of the lecture, with the state it opens with (at step 0). */
export interface SceneSpec<S> {
  /** Stable id, in the link as `scene=<id>`. */
  id: string;
  label: string;
  /** The state this scene opens with, from the current one (the shell then sets step 0). */
  setup(current: S): S;
  /** The figures this scene shows (all of the lesson's when absent). */
  figures?: readonly string[];
}

/** A scene with steps of its own (the lesson's `sceneOf` tells which scene a state is in). */
export interface ScriptedScene<S, M, N extends string> extends SceneSpec<S> {
  script?: Script<S, M, N>;
}

/**
 * A figure of the kit: a shell figure whose movable points come from point
 * lists. `handles`/`moveHandle` remain for handles that are not a list's
 * points (a cursor, a knot on its line).
 */
export interface KitFigure<S, M extends { state: S }> extends Omit<
  FigureSpec<S, M>,
  'addPoint' | 'removeHandle' | 'draw'
> {
  draw(painter: Painter, model: M, info: DrawInfo): void;
  /** The point lists whose handles this figure shows, drags and edits. */
  points?: readonly PointList<S>[];
  /** The list a double-click or long-press on empty space adds to. */
  addTo?: PointList<S>;
  /**
   * Handles in index order across the lists (D₀, P₀, D₁, P₁, …: Tab visits
   * each point with its own gradient, and each point is drawn over its own
   * tip), instead of one list after the other.
   */
  interleave?: boolean;
}

export interface KitLessonSpec<S, M extends { state: S }, N extends string> {
  slug: string;
  schema: Schema<S>;
  /** The state's field (an `int`) that holds the step. */
  step: NumberKeys<S>;
  /** The steps every scene walks, unless the scene has a script of its own. */
  script?: Script<S, M, N>;
  /**
   * Which scene a state is in (its id), for lessons whose scenes differ in
   * their steps or their figures: a field of the state says so.
   */
  sceneOf?(state: S): string;
  /**
   * Everything the figures and the panel show, computed once per state,
   * with what the current step reveals.
   */
  derive(state: S, shown: Revealed<N>): M;
  scenes: readonly ScriptedScene<S, M, N>[];
  figures: readonly KitFigure<S, M>[];
  layout?: 'row' | 'column' | LayoutNode;
  /** The figures arranged for a tall subject, in presenter view (see LessonDefinition.tallLayout). */
  tallLayout?: LayoutNode;
  parameter?: ParameterSpec<S>;
  /** The letter the lesson writes its curve parameter with (see LessonDefinition.letter). */
  letter?: Letter;
  normalize?(state: S): { state: S; issues: string[] };
  panel(api: LessonApi<S, M>): LessonPanel<S, M>;
  /** The tables a handout prints under a scene's last frame (see LessonDefinition.tables). */
  tables?(model: M, state: S): HandoutTable[];
  /** At least three exercises, written for this lesson's ideas (see exercise.ts). */
  exercises?: readonly ExerciseSpec<S>[];
}

/** The shell's lesson from the kit's. */
export function defineLesson<S, M extends { state: S }, N extends string>(
  spec: KitLessonSpec<S, M, N>,
): LessonDefinition<S, M> {
  const sceneOf = (state: S) => {
    const id = spec.sceneOf?.(state);
    return spec.scenes.find((scene) => scene.id === id);
  };
  const scriptOf = (state: S): Script<S, M, N> => {
    const script = sceneOf(state)?.script ?? spec.script;
    if (!script) throw new Error(`${spec.slug}: no script for scene ${spec.sceneOf?.(state)}`);
    return script;
  };
  const stepOf = (state: S) => state[spec.step] as unknown as number;
  // One model per state object: the shell, the captions and the formulas share it.
  const models = new WeakMap<object, M>();
  const derive = (state: S): M => {
    const key = state as object;
    let model = models.get(key);
    if (!model) {
      model = spec.derive(state, scriptOf(state).shown(state, stepOf(state)));
      models.set(key, model);
    }
    return model;
  };
  return {
    slug: spec.slug,
    schema: spec.schema,
    derive,
    figures: spec.figures.map((figure) => shellFigure(figure)),
    layout: spec.layout,
    tallLayout: spec.tallLayout,
    parameter: spec.parameter,
    letter: spec.letter,
    steps: {
      key: spec.step,
      count: (state) => scriptOf(state).lastStep(state),
      describe: (state, k) => subscriptNames(scriptOf(state).caption(state, derive(state), k)),
      formula: (model, state) => scriptOf(state).formula(state, model, stepOf(state)),
    },
    scenes: spec.scenes.map((scene) => ({
      id: scene.id,
      label: scene.label,
      apply: (current: S) => scene.setup(current),
    })),
    normalize: spec.normalize,
    figuresShown: (state) => sceneOf(state)?.figures ?? null,
    sceneOf: (state) => sceneOf(state)?.id,
    panel: spec.panel,
    tables: spec.tables,
    exercises: spec.exercises,
  };
}

/** The list that owns a handle id, and the point's index in it. */
function owner<S>(lists: readonly PointList<S>[], id: string) {
  for (const list of lists) {
    const ref = list.ref(id);
    if (ref) return { list, index: ref.index };
  }
  return null;
}

function shellFigure<S, M extends { state: S }>(figure: KitFigure<S, M>): FigureSpec<S, M> {
  const { points = [], addTo, interleave = false, ...rest } = figure;
  const listed = (state: S): Handle[] => {
    const lists = points.map((list) => list.handles(state));
    if (!interleave) return lists.flat();
    const longest = Math.max(0, ...lists.map((handles) => handles.length));
    return Array.from({ length: longest }, (_, i) =>
      lists.flatMap((handles) => (i < handles.length ? [handles[i]] : [])),
    ).flat();
  };
  if (points.length === 0 && !addTo) return rest;
  const handles = (model: M): Handle[] => [
    ...listed(model.state),
    ...(figure.handles?.(model) ?? []),
  ];
  return {
    ...rest,
    // A figure in the plane is fitted to take in every handle it shows, as
    // well as its subject: a point that can be moved is on screen. (A figure
    // in space fits a sphere round its box, which its handles' far corners
    // would only shrink; it turns to show what it hides.)
    bounds:
      rest.kind !== 'geometry'
        ? rest.bounds
        : (model: M) => {
            const subject = rest.bounds(model);
            const shown = handles(model);
            return shown.length
              ? unionBounds(subject, boundsOf(shown.map((h) => h.position)))
              : subject;
          },
    handles,
    moveHandle(state: S, id: string, to: Point, model: M): S {
      const found = owner(points, id);
      if (found) return found.list.move(state, found.index, to);
      return figure.moveHandle?.(state, id, to, model) ?? state;
    },
    addPoint: addTo?.resizable ? (state: S, at: Point) => addTo.add(state, at) : undefined,
    // Delete and right-click only where a list can lose a point (three points of a parabola cannot).
    removeHandle: points.some((list) => list.resizable)
      ? (state: S, id: string): S | null => {
          const found = owner(points, id);
          return found ? found.list.remove(state, found.index) : null;
        }
      : undefined,
  };
}
