import type { ScriptedScene } from '../../kit/lesson';
import { defaultsOf } from '../../app/urlState';
import { gridFigureIds } from './gridFigures';
import type { BezierSplinesModel } from './model';
import { type Reveal, scripts } from './script';
import {
  type BezierSplinesState,
  FOUR_POINTS,
  HAIRPIN,
  HAND_BUILT,
  LECTURE_POINTS,
  type Part,
  handTangents,
  midpoint,
  schema,
} from './state';

type State = BezierSplinesState;

const defaults = defaultsOf(schema);

/** A part of the lesson: its own steps, and the main figure (the grid scene shows the 3 × 3 grid instead). */
const scene = (
  id: Part,
  label: string,
  change: Partial<State> = {},
): ScriptedScene<State, BezierSplinesModel, Reveal> => ({
  id,
  label,
  setup: (current) => ({ ...current, ...change, part: id, step: 0 }),
  figures: id === 'grid' ? gridFigureIds : ['main'],
  script: scripts[id],
});

/** The parts in teaching order; the first opens the lesson as its link's defaults. */
export const scenes: ScriptedScene<State, BezierSplinesModel, Reveal>[] = [
  { ...scene('why', 'Why pieces'), setup: () => defaults },
  scene('quadratic', 'C¹ quadratic spline', {
    points: LECTURE_POINTS,
    firstControl: [midpoint(LECTURE_POINTS[0], LECTURE_POINTS[1])],
    tangents: handTangents(LECTURE_POINTS),
  }),
  scene('system', 'C² by a linear system', {
    points: FOUR_POINTS,
    tangents: handTangents(FOUR_POINTS),
  }),
  scene('grid', 'C⁰ · C¹ · C² grid'),
  scene('inspector', 'Continuity inspector', { handBuilt: HAND_BUILT }),
  scene('catmull', 'Catmull-Rom', { points: HAIRPIN, tangents: handTangents(HAIRPIN) }),
  scene('worked', 'C¹ and C² by hand', {
    points: FOUR_POINTS,
    tangents: handTangents(FOUR_POINTS),
  }),
  scene('degree', 'Degree d ⇒ Cᵈ⁻¹', {
    points: FOUR_POINTS,
    tangents: handTangents(FOUR_POINTS),
  }),
];
