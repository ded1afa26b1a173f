import type { Point } from '../../app/lesson';
import type { ScriptedScene } from '../../kit/lesson';
import type { SurfaceModel } from './model';
import { BUMP_NET, FLAT_NET, JOIN_NEXT_C0, SADDLE_NET, TWISTED_NET, WAVE_NET } from './presets';
import { type Reveal, SCRIPTS } from './scripts';
import { JOIN_NET, JOIN_NEXT_C1, LECTURE_NET, type SurfaceMode, type SurfaceState } from './state';

// The lesson's scenes in teaching order: the construction scenes on the
// lecture's patch, then the nets worth seeing (flat, saddle, bump, wave, not
// planar), then two patches joined C⁰ and C¹.

/** A scene: what it teaches (its steps), and the net and settings it opens with. */
export interface SurfaceScene extends ScriptedScene<SurfaceState, SurfaceModel, Reveal> {
  mode: SurfaceMode;
}

const scene = (
  id: string,
  label: string,
  mode: SurfaceMode,
  net?: Point[][],
  extra: Partial<SurfaceState> = {},
): SurfaceScene => ({
  id,
  label,
  mode,
  script: SCRIPTS[mode],
  setup: (current) => ({ ...current, mode, step: 0, ...(net ? { net } : {}), ...extra }),
});

export const SCENES: SurfaceScene[] = [
  scene('patch', 'The patch', 'patch', LECTURE_NET, { u: 0.3, v: 0.6, look: 'shaded' }),
  scene('rows', 'Choose v, then u', 'rows'),
  scene('casteljau', 'de Casteljau both ways', 'casteljau'),
  scene('matrix', 'Matrix form', 'matrix'),
  scene('weights', 'The 16 weights', 'weights'),
  scene('normal', 'Tangents and normal', 'normal'),
  scene('flat', 'Flat', 'patch', FLAT_NET, { look: 'shaded' }),
  // The saddle's iso-curves are straight lines (it is bilinear): shown as lines.
  scene('saddle', 'Saddle', 'patch', SADDLE_NET, { look: 'lines' }),
  scene('bump', 'Bump', 'patch', BUMP_NET, { u: 0.5, v: 0.5, look: 'shaded' }),
  scene('wave', 'Wave', 'patch', WAVE_NET),
  scene('twisted', 'Not planar', 'patch', TWISTED_NET),
  scene('c0', 'Two patches, C⁰', 'join', JOIN_NET, { secondNet: JOIN_NEXT_C0 }),
  scene('c1', 'Two patches, C¹', 'join', JOIN_NET, { secondNet: JOIN_NEXT_C1 }),
];

/**
 * The scene whose steps a state walks: the first of its mode (the scenes of
 * one mode, the patch and the nets worth seeing, share their steps).
 */
export const sceneOf = (state: SurfaceState): string =>
  SCENES.find((scene) => scene.mode === state.mode)?.id ?? SCENES[0].id;
