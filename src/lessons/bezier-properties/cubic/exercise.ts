import { type ExerciseSpec, type Random, type Verdict, random } from '../../../kit/exercise';
import { pointWords, sub } from '../../../kit/format';
import { type Point, cubicInflections, cubicSelfIntersection, distance } from '../../../math';
import { opened } from '../exerciseSetup';
import type { PropertiesState } from '../state';

// The exercise on property 8: one inner point of an arch moved until the
// cubic inflects, on a spot a finger's slip does not undo.

/** An inflection this close to an end of the curve is too small to see. */
const END_MARGIN = 0.05;
/** A solution still holds this far away in every direction: a finger's slip does not undo it. */
const SLIP = 0.3;

/** The inflections of the cubic far enough from its ends to be seen. */
const visibleInflections = (p: readonly Point[]) =>
  cubicInflections(p).filter((t) => t >= END_MARGIN && t <= 1 - END_MARGIN);

/** Where P_k can go, on the grid inside the polygon's box, for the cubic to inflect with a margin. */
function inflectingSpots(p: readonly Point[], k: number): Point[] {
  const xs = p.map((q) => q[0]);
  const ys = p.map((q) => q[1]);
  const around = [
    [0, 0],
    ...Array.from({ length: 8 }, (_, j) => [
      Math.cos((j * Math.PI) / 4),
      Math.sin((j * Math.PI) / 4),
    ]),
  ];
  const spots: Point[] = [];
  for (let x = Math.min(...xs); x <= Math.max(...xs); x++)
    for (let y = Math.min(...ys); y <= Math.max(...ys); y++) {
      // Not on or beside another control point: the polygon keeps four distinct corners.
      if (p.some((q, i) => i !== k && distance(q, [x, y]) < 1)) continue;
      const holds = around.every(
        ([dx, dy]) =>
          visibleInflections(p.map((q, i) => (i === k ? [x + SLIP * dx, y + SLIP * dy] : q)))
            .length > 0,
      );
      if (holds) spots.push([x, y]);
    }
  return spots;
}

/** An arch every seed can fall back on: P₂ has room to make it inflect. */
const FALLBACK_ARCH: Point[] = [
  [0, 0],
  [1, 3],
  [4, 3],
  [5, 0],
];

/**
 * A cubic that turns one way only (an arch: no inflection, no loop), the
 * inner point to move, and the grid spots where moving it makes the cubic
 * inflect.
 */
function oneWayArch(r: Random): { p: Point[]; k: number; spots: Point[] } {
  for (let tries = 0; tries < 20; tries++) {
    const p: Point[] = [
      [0, r.int(0, 1)],
      [r.int(0, 2), r.int(3, 4)],
      [r.int(3, 5), r.int(2, 4)],
      [r.int(5, 6), r.int(0, 1)],
    ];
    if (cubicInflections(p).length > 0 || cubicSelfIntersection(p) !== null) continue;
    const k = r.pick([1, 2]);
    const spots = inflectingSpots(p, k);
    if (spots.length > 0) return { p, k, spots };
  }
  return { p: FALLBACK_ARCH, k: 2, spots: inflectingSpots(FALLBACK_ARCH, 2) };
}

/** Property 8: move one inner point until the cubic turns both ways. */
export const inflection: ExerciseSpec<PropertiesState> = {
  id: 'inflection',
  title: 'Make the cubic turn both ways',
  kind: 'construct',
  pose(seed, defaults) {
    const r = random(seed);
    const { p, k, spots } = oneWayArch(r);
    const spot = r.pick(spots);
    const name = `P${sub(k)}`;
    const check = (s: PropertiesState): Verdict => {
      const strayed = s.points.findIndex((q, i) => i !== k && distance(q, p[i]) > 1e-9);
      if (strayed >= 0)
        return {
          correct: false,
          message: `Move only ${name}: P${sub(strayed)} belongs at ${pointWords(p[strayed])}.`,
        };
      const seen = visibleInflections(s.points);
      if (seen.length > 0)
        return {
          correct: true,
          message: `Correct: the cubic turns both ways, with an inflection at t = ${seen.map((t) => t.toFixed(2)).join(' and ')}.`,
        };
      const loop = cubicSelfIntersection(s.points);
      if (loop)
        return {
          correct: false,
          message: `Not yet: that is a loop (the curve crosses itself at t = ${loop[0].toFixed(2)} and ${loop[1].toFixed(2)}), and along a loop a cubic turns one way only. Pull ${name} back out of it.`,
        };
      const all = cubicInflections(s.points);
      if (all.length > 0)
        return {
          correct: false,
          message: `Not yet: the only inflection is at t = ${all[0].toFixed(2)}, too near the end to see; move ${name} further the same way.`,
        };
      return {
        correct: false,
        message: `Not yet: no inflection, the cubic still turns one way only. Move ${name} so the polygon bends one way at P₁ and the other way at P₂.`,
      };
    };
    const state = opened(defaults, 'cubic', { points: p }, 'last');
    const solved = { ...state, points: p.map((q, i) => (i === k ? spot : q)) };
    return {
      state,
      prompt: `Move only ${name} until the cubic turns both ways, with an inflection where its curvature changes sign.`,
      task: { kind: 'construct', check, solution: solved },
      working: solved,
    };
  },
};
