import type { Point } from '../../app/lesson';
import type { ScriptedScene } from '../../kit/lesson';
import type { SurfaceModel } from './model';
import { BUMP_NET, FLAT_NET, JOIN_NEXT_C0, SADDLE_NET, TWISTED_NET, WAVE_NET } from './presets';
import { PRESET_SCRIPTS, type Preset, type Reveal, SCRIPTS, type SurfaceScript } from './scripts';
import {
  JOIN_NET,
  JOIN_NEXT_C1,
  LEANING_HILL_NET,
  type SurfaceMode,
  type SurfaceState,
} from './state';

// The lesson's scenes in teaching order: the construction scenes on the
// leaning hill, then the nets worth seeing (flat, saddle, bump, wave, not
// planar), each with steps of its own idea, then two patches joined C⁰ and C¹.

/** A scene: what it teaches (its steps), and the net and settings it opens with. */
export interface SurfaceScene extends ScriptedScene<SurfaceState, SurfaceModel, Reveal> {
  mode: SurfaceMode;
  /** The net the scene opens with, if it sets one. */
  net?: Point[][];
}

const scene = (
  id: string,
  label: string,
  mode: SurfaceMode,
  net?: Point[][],
  extra: Partial<SurfaceState> = {},
  script: SurfaceScript = SCRIPTS[mode],
): SurfaceScene => ({
  id,
  label,
  mode,
  net,
  script,
  setup: (current) => ({ ...current, mode, step: 0, ...(net ? { net } : {}), ...extra }),
});

/**
 * A net worth seeing: its own steps, and its own u, v and look whatever scene
 * came before (so it opens as its link does).
 */
const preset = (
  id: Preset,
  label: string,
  net: Point[][],
  view: Pick<SurfaceState, 'u' | 'v' | 'look'> = { u: 0.3, v: 0.6, look: 'shaded' },
): SurfaceScene => scene(id, label, 'patch', net, view, PRESET_SCRIPTS[id]);

export const SCENES: SurfaceScene[] = [
  scene('patch', 'The patch', 'patch', LEANING_HILL_NET, { u: 0.3, v: 0.6, look: 'shaded' }),
  scene('rows', 'Choose v, then u', 'rows'),
  scene('casteljau', 'de Casteljau both ways', 'casteljau'),
  scene('matrix', 'Matrix form', 'matrix'),
  scene('weights', 'The 16 weights', 'weights'),
  scene('normal', 'Tangents and normal', 'normal'),
  preset('flat', 'Flat', FLAT_NET),
  // The saddle's iso-curves are straight lines (it is bilinear): shown as lines.
  preset('saddle', 'Saddle', SADDLE_NET, { u: 0.3, v: 0.6, look: 'lines' }),
  preset('bump', 'Bump', BUMP_NET, { u: 0.5, v: 0.5, look: 'shaded' }),
  preset('wave', 'Wave', WAVE_NET),
  preset('twisted', 'Not planar', TWISTED_NET),
  scene('c0', 'Two patches, C⁰', 'join', JOIN_NET, { secondNet: JOIN_NEXT_C0 }),
  scene('c1', 'Two patches, C¹', 'join', JOIN_NET, { secondNet: JOIN_NEXT_C1 }),
];

const sameNet = (a: readonly (readonly Point[])[], b: readonly (readonly Point[])[]) =>
  a.length === b.length &&
  a.every((row, m) => row.every((p, n) => p.every((value, d) => value === b[m]?.[n]?.[d])));

/**
 * The scene whose steps a state walks. The nets worth seeing share the patch's
 * mode (their links say `s=patch`), so their net tells them apart: a net
 * edited away from its scene's is a patch like any other, and the patch's
 * steps describe it (a flat scene's words would no longer be true of it).
 * The other modes have one script each: the first scene of the mode.
 */
export function sceneOf(state: SurfaceState): string {
  if (state.mode === 'patch') {
    const found = SCENES.find(
      (s) => s.mode === 'patch' && s.id !== 'patch' && s.net && sameNet(s.net, state.net),
    );
    if (found) return found.id;
  }
  return SCENES.find((s) => s.mode === state.mode)?.id ?? SCENES[0].id;
}

/** The script a state walks. */
export const scriptOf = (state: SurfaceState): SurfaceScript =>
  SCENES.find((s) => s.id === sceneOf(state))?.script ?? SCRIPTS[state.mode];

/** What the steps so far reveal in this state. */
export const shownIn = (state: SurfaceState) => scriptOf(state).shown(state, state.step);
