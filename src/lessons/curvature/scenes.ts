import type { ScriptedScene } from '../../kit/lesson';
import { type Point, cubicInflections } from '../../math';
import type { CurvatureModel } from './model';
import { PART_SCRIPTS, type Reveal } from './scripts';
import { type CurvatureState, LECTURE_CUBIC, type Part, TWISTED_CUBIC } from './state';

/** An S-shaped cubic: symmetric, so it inflects at t = 1/2. */
const S_CURVE: Point[] = [
  [0, 0],
  [1.5, 2.5],
  [2.5, -2.5],
  [4, 0],
];
/** P2 − P1 = P0 − P3 makes P′(1/2) = 0: a cusp. */
const CUSP: Point[] = [
  [0, 0],
  [4, 3],
  [0, 3],
  [4, 0],
];
/** A curve that is slow at its start and fast at its end, so equal t is not equal length. */
const UNEVEN: Point[] = [
  [0, 0],
  [0.3, 2.5],
  [1.2, 2.8],
  [5, 0],
];

/** Five points with a bend each way: a spline through them has joins to look at. */
const SPLINE_POINTS: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2.5],
  [4.5, 0.5],
  [6, 2],
];

/**
 * Four points, one unit apart in x: the natural spline's x is p̄ itself, so its
 * κ and dκ/ds at the joins can be worked by hand (see joinsModel.test.ts); and
 * the Catmull-Rom gradients at P1 and P2, (1, 0) and (1, −0.5), are not
 * parallel, so its κ jumps at the first join.
 */
const JOIN_POINTS: Point[] = [
  [0, 0],
  [1, 1],
  [2, 0],
  [3, 0],
];

type Scene = ScriptedScene<CurvatureState, CurvatureModel, Reveal>;

/** A scene of a part: the fields it sets, and the part's steps. */
const scene = (id: string, label: string, part: Part, fields: Partial<CurvatureState>): Scene => ({
  id,
  label,
  setup: (s) => ({ ...s, part, ...fields }),
  script: PART_SCRIPTS[part],
});

const plane = (id: string, label: string, points: Point[], t: number) =>
  scene(id, label, 'plane', { source: 'bezier', points, t });

const spline = (id: string, label: string, source: 'natural' | 'catmull-rom') =>
  scene(id, label, 'plane', { source, points: SPLINE_POINTS, t: 0.45 });

/** The lesson's scenes, in teaching order. */
export const SCENES: readonly Scene[] = [
  plane('plane', 'Curvature of a plane curve', LECTURE_CUBIC, 0.3),
  plane('inflection', 'An inflection: κ = 0', S_CURVE, cubicInflections(S_CURVE)[0]),
  plane('cusp', 'A cusp: speed 0', CUSP, 0.5),
  scene('helix', 'The Frenet frame of a helix', 'space', {
    spaceCurve: 'helix',
    radius: 1,
    rise: 0.25,
    t: 0.3,
  }),
  scene('twisted', 'A space cubic: the frame flips', 'space', {
    spaceCurve: 'bezier',
    spacePoints: TWISTED_CUBIC,
    t: 0.3,
  }),
  scene('arc', 'Arc length against parameter', 'arc', {
    source: 'bezier',
    points: UNEVEN,
    equalSteps: 8,
    t: 0.5,
  }),
  spline('natural', 'A natural spline: κ is continuous at its C² joins', 'natural'),
  spline('catmull', 'A Catmull-Rom spline: κ jumps at its C¹ joins', 'catmull-rom'),
  {
    ...scene('joins', 'G², G³ and Cⁿ⁻¹', 'joins', {
      source: 'natural',
      points: JOIN_POINTS,
      t: 0.45,
    }),
    // The curve and κ against p̄: the plane curve lifted into space adds nothing here.
    figures: ['curve', 'plot'],
  },
];

/**
 * The scene a state is in, as far as its steps go: the scenes of one part
 * share the part's script, so the part's first scene stands for them all.
 */
const FIRST_SCENE: Readonly<Record<Part, string>> = {
  plane: 'plane',
  space: 'helix',
  arc: 'arc',
  joins: 'joins',
};

export const sceneOf = (state: CurvatureState): string => FIRST_SCENE[state.part];
