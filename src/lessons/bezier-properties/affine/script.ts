import { texResidue, words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { MapKind, PropertiesState } from '../state';

export type AffineReveal =
  'points' | 'curve' | 'mappedPoints' | 'curveOfMapped' | 'mappedCurve' | 'point';

const MAP_NAMES: Record<MapKind, string> = {
  rotate: 'a rotation',
  scale: 'a scaling',
  shear: 'a shear',
  perspective: 'a perspective map',
};

/** How far apart the two images are, once both are drawn (none without images). */
const deviation = ({ model: { images } }: { model: ModelOf<'affine'> }) =>
  images.ok
    ? `\\max_t |\\text{map of } P(t) - \\text{curve of mapped points}| = ${texResidue(images.distance)}`
    : null;

/** Property 7: mapping the points maps the curve, for affine maps and not for perspective. */
export const affineScript = script<PropertiesState, ModelOf<'affine'>, AffineReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('curve', 'The curve and its polygon'),
  step('mappedPoints', ({ state }) => `The control points mapped by ${MAP_NAMES[state.map]}`),
  step('curveOfMapped', 'The Bézier curve of the mapped points'),
  step(
    'mappedCurve',
    ({ state }) =>
      state.map !== 'perspective'
        ? 'The map of the curve itself, dashed: the very same curve'
        : 'The map of the curve itself, dashed: not the same curve',
    deviation,
  ),
  step(
    'point',
    ({ state }) => `P(t) at t = ${words(state.t)}, and where each image has it`,
    deviation,
  ),
);
