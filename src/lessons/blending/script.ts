import { Script as KitScript } from '../../kit/script';
import { blendingScript } from './bernsteinScript';
import { bsplineScript, hermiteScript, lagrangeScript } from './compareScripts';
import type { BlendingModel } from './model';
import { passesScript } from './passesScript';
import type { BlendingScript, Reveal } from './reveals';
import type { BlendingState } from './state';
import { symmetryScript } from './symmetryScript';

// The lesson's scripts put together: the one its Bernstein scenes walk
// (Bernstein's, or the symmetry's when the mirror is chosen), the one each
// state walks, and where a state lands when its script changes.

/**
 * Bernstein's script, or the symmetry's when the mirror is chosen: the
 * lesson's script for every state no Compare scene's script covers. (The
 * symmetry would be a scene of its own, but the recorded links pin the list
 * of scenes; the kit picks a scene's script only for a declared scene.)
 */
class BernsteinOrSymmetry extends KitScript<BlendingState, BlendingModel, Reveal> {
  constructor() {
    super([]);
  }
  private of = (state: BlendingState) =>
    state.comparison === 'mirror' ? symmetryScript : blendingScript;
  override lastStep(state: BlendingState) {
    return this.of(state).lastStep(state);
  }
  override shown(state: BlendingState, k: number) {
    return this.of(state).shown(state, k);
  }
  override caption(state: BlendingState, model: BlendingModel, k: number) {
    return this.of(state).caption(state, model, k);
  }
  override formula(state: BlendingState, model: BlendingModel, k: number) {
    return this.of(state).formula(state, model, k);
  }
  override stepOf(state: BlendingState, name: Reveal, index = 1) {
    return this.of(state).stepOf(state, name, index);
  }
}

export const lessonScript: BlendingScript = new BernsteinOrSymmetry();

/** The script a state walks: one per comparison, Bernstein's alone without one. */
export function scriptOf(state: BlendingState): BlendingScript {
  switch (state.comparison) {
    case 'none':
      return blendingScript;
    case 'hermite':
      return hermiteScript;
    case 'bspline':
      return bsplineScript;
    case 'lagrange':
      return lagrangeScript;
    case 'mirror':
      return symmetryScript;
    case 'interpolating':
      return passesScript;
  }
}

/** After an edit that changes the script or its length: shown to its end, it stays at the end. */
export function keepShownToEnd(before: BlendingState, after: BlendingState): BlendingState {
  const lastBefore = scriptOf(before).lastStep(before);
  const lastAfter = scriptOf(after).lastStep(after);
  const step = before.step >= lastBefore ? lastAfter : Math.min(before.step, lastAfter);
  return { ...after, step };
}
