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
  /** Step of the script: points, gradients, the basis, each patch solved, P(μ), the Bézier view. */
  step: number;
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
  step: int({ default: 0, min: 0, max: MAX_POINTS + 4 }),
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
  if (patch !== state.patch)
    issues.push(
      `patch: there is no patch ${state.patch + 1} among ${state.p.length - 1}, so it shows patch ${patch + 1}`,
    );
  return { state: { ...state, d, patch }, issues };
}

/**
 * Steps of the script: 0 the points; 1 their gradients; 2 the basis
 * functions H0, H1 that weight the points; 3 H2, H3 that weight the
 * gradients; then each patch solved and drawn in turn; then P(μ) on the
 * chosen patch; then, in the Bézier scene, its control points.
 */
export const stepCount = (state: HermiteState) => 4 + patchCount(state) + (state.bezier ? 1 : 0);

/** What step `step` shows. */
export interface Revealed {
  gradients: boolean;
  /** H0 … H(basis − 1) in the plot. */
  basis: number;
  /** Patches 0 … patches − 1 are drawn. */
  patches: number;
  /** The patch solved at this step, while the patches are being built; else null. */
  building: number | null;
  point: boolean;
  bezier: boolean;
}

export function revealed(state: HermiteState): Revealed {
  const k = state.step;
  const m = patchCount(state);
  const patches = Math.max(0, Math.min(k - 3, m));
  return {
    gradients: k >= 1,
    basis: k >= 3 ? 4 : k >= 2 ? 2 : 0,
    patches,
    building: k >= 4 && k < 4 + m ? k - 4 : null,
    point: k >= 4 + m,
    bezier: state.bezier && k >= 5 + m,
  };
}
