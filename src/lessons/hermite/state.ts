import { bool, choice, int, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { catmullRomTangents } from '../../math';

export type GradientMode = 'hand' | 'catmull-rom';

/** Everything the Hermite lesson shows, and all of it goes in the link. */
export interface HermiteState {
  /** The points P0 … Pm joined by cubic patches. */
  p: Point[];
  /** The gradients D0 … Dm set by hand (one per point). */
  d: Point[];
  /** Gradients by hand, or from the neighbours (Catmull-Rom). */
  mode: GradientMode;
  /** The local parameter on the chosen patch. */
  mu: number;
  /** Which patch the matrix, the basis and P(μ) are about: 0 … m − 1. */
  patch: number;
  /** Draw each patch's Bézier control polygon. */
  bezier: boolean;
}

export const MAX_POINTS = 10;

/** The lecture's one patch: P0 = (0, 0) to P1 = (4, 0), leaving up and arriving down. */
export const ONE_PATCH: Point[] = [
  [0, 0],
  [4, 0],
];
export const ONE_PATCH_GRADIENTS: Point[] = [
  [3, 4.5],
  [3, -4.5],
];

export const schema: Schema<HermiteState> = {
  p: points({ default: ONE_PATCH, min: 2, max: MAX_POINTS }),
  d: points({ default: ONE_PATCH_GRADIENTS, min: 2, max: MAX_POINTS }),
  mode: choice<GradientMode>({ default: 'hand', values: ['hand', 'catmull-rom'] }),
  mu: number({ default: 0.3, min: 0, max: 1 }),
  patch: int({ default: 0, min: 0, max: MAX_POINTS - 2 }),
  bezier: bool({ default: false }),
};

/** Number of patches, m. */
export const patchCount = (state: HermiteState) => state.p.length - 1;

/** One gradient per point: a link with too few gets Catmull-Rom's, too many are dropped. */
export function normalize(state: HermiteState): { state: HermiteState; issues: string[] } {
  const issues: string[] = [];
  let d = state.d;
  if (d.length !== state.p.length) {
    const fill = catmullRomTangents(state.p);
    d = state.p.map((_, i) => d[i] ?? fill[i]);
    issues.push(
      `d: ${state.d.length} gradients for ${state.p.length} points; ${d.length > state.d.length ? 'the missing ones come from the neighbours' : 'the extra ones are dropped'}`,
    );
  }
  const patch = Math.min(state.patch, state.p.length - 2);
  return { state: { ...state, d, patch }, issues };
}
