import type { Script } from '../../kit/script';
import type { BlendingModel } from './model';
import type { BlendingState } from './state';

// The names of what the blending lesson's steps reveal, over all its scripts,
// and the type each of those scripts has.

/** What the steps reveal, by name: the figures and the panel ask for these (through `drawn`). */
export type Reveal =
  // Bernstein's weights one by one
  | 'points'
  | 'weight'
  | 'point'
  | 'curve'
  // a comparison, starting from the whole Bézier picture
  | 'bezier'
  | 'data'
  | 'tangents'
  | 'basis'
  | 'ends'
  | 'spline'
  | 'hull'
  | 'atMu'
  // the symmetry μ → 1 − μ
  | 'functions'
  | 'mirror'
  | 'pair'
  | 'reversed'
  // interpolating or approximating: each curve, then which points it passes through
  | 'lagrangeCurve'
  | 'interpolating'
  | 'bezierCurve'
  | 'approximating';

/** A script of the blending lesson: its state, its model, and these names. */
export type BlendingScript = Script<BlendingState, BlendingModel, Reveal>;
