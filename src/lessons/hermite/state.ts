import { bool, choice, int, stepField, linkKey, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { catmullRomTangents } from '../../math';

export type GradientMode = 'hand' | 'catmull-rom';

/** Everything the Hermite lesson shows, and all of it goes in the link. */
export interface HermiteState {
  /** The points P0 … Pm joined by cubic patches (link key `p`). */
  points: Point[];
  /** The gradients D0 … Dm set by hand, one per point (link key `d`). */
  handGradients: Point[];
  /** Gradients by hand, or from the neighbours (Catmull-Rom). */
  mode: GradientMode;
  /** The local parameter μ on the chosen patch (the lecture's letter). */
  mu: number;
  /** Which patch the matrix, the basis and P(μ) are about: 0 … m − 1. */
  patch: number;
  /** The Bézier view: each patch's control polygon, and the "bezier" scene's steps (bezierScript). */
  bezier: boolean;
  /** The step of the script (`construction`, or `bezierScript` in the Bézier view: script.ts). */
  step: number;
}

export const MAX_POINTS = 10;

/** The first scene's one patch: P0 = (0, 0) to P1 = (4, 0), leaving up and arriving down. */
export const ONE_PATCH: Point[] = [
  [0, 0],
  [4, 0],
];
export const ONE_PATCH_GRADIENTS: Point[] = [
  [3, 4.5],
  [3, -4.5],
];

// The order of the fields is the order of the link's keys.
export const schema: Schema<HermiteState> = {
  points: linkKey(points({ default: ONE_PATCH, min: 2, max: MAX_POINTS }), 'p'),
  handGradients: linkKey(points({ default: ONE_PATCH_GRADIENTS, min: 2, max: MAX_POINTS }), 'd'),
  mode: choice<GradientMode>({ default: 'hand', values: ['hand', 'catmull-rom'] }),
  mu: number({ default: 0.3, min: 0, max: 1 }),
  patch: int({ default: 0, min: 0, max: MAX_POINTS - 2 }),
  bezier: bool({ default: false }),
  // The construction's last step: seven steps and one per patch, 0-based.
  step: stepField(),
};

/** Number of patches, m. */
export const patchCount = (state: HermiteState) => state.points.length - 1;

/** One gradient per point: a link with too few gets Catmull-Rom's, too many are dropped. */
export function normalize(state: HermiteState): { state: HermiteState; issues: string[] } {
  const issues: string[] = [];
  const { points: p, handGradients: given } = state;
  let handGradients = given;
  if (given.length !== p.length) {
    const fill = catmullRomTangents(p);
    handGradients = p.map((_, i) => given[i] ?? fill[i]);
    issues.push(
      `d: ${given.length} gradients for ${p.length} points; ${handGradients.length > given.length ? 'the missing ones come from the neighbours' : 'the extra ones are dropped'}`,
    );
  }
  const patch = Math.min(state.patch, p.length - 2);
  if (patch !== state.patch)
    issues.push(
      `patch: there is no patch ${state.patch + 1} among ${p.length - 1}, so it shows patch ${patch + 1}`,
    );
  return { state: { ...state, handGradients, patch }, issues };
}
