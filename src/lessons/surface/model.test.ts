import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import lesson from './lesson';
import type { SurfaceModel } from './model';
import { BUMP_NET, JOIN_NEXT_C0, SADDLE_NET } from './presets';
import { SCENES } from './scenes';
import { JOIN_NET, JOIN_NEXT_C1, type SurfaceMode, type SurfaceState, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: SurfaceState) => lesson.derive(s) as SurfaceModel;
const steps = lesson.steps!;
/** The last step of each scene's construction. */
const STEP_COUNT: Record<SurfaceMode, number> = {
  patch: 5,
  rows: 5,
  casteljau: 6,
  matrix: 3,
  weights: 4,
  normal: 4,
  join: 3,
};

const defaults = defaultsOf(schema) as SurfaceState;
const at = (net: SurfaceState['net'], u: number, v: number, extra: Partial<SurfaceState> = {}) =>
  derive({ ...defaults, net, u, v, ...extra });

describe('the surface model, against values by hand', () => {
  it('puts the top of the bump at 2·(3/4)² = 9/8, where the tangent plane is level', () => {
    const m = at(BUMP_NET, 0.5, 0.5);
    expect(m.point).toEqual([1.5, 1.5, 1.125]);
    expect(m.du).toEqual([3, 0, 0]);
    expect(m.dv).toEqual([0, 3, 0]);
    expect(m.normal).toEqual([0, 0, 1]);
    expect(m.uThenV.point).toEqual(m.point);
    expect(m.vThenU.point).toEqual(m.point);
  });

  it('gives the saddle z = 9(u − ½)(v − ½)/2 and its slopes, also from the matrix form', () => {
    // u = ¼, v = 1: z = 9·(−¼)·(½)/2 = −9/16; ∂z/∂u = 9(v − ½)/2 = 9/4; ∂z/∂v = 9(u − ½)/2 = −9/8.
    const m = at(SADDLE_NET, 0.25, 1, { coordinate: 'z' });
    expect(m.point[2]).toBeCloseTo(-9 / 16, 14);
    expect(m.du[2]).toBeCloseTo(9 / 4, 14);
    expect(m.dv[2]).toBeCloseTo(-9 / 8, 14);
    expect(m.crossProduct).toEqual([
      expect.closeTo(-3 * (9 / 4), 13),
      expect.closeTo(-3 * (-9 / 8), 13),
      expect.closeTo(9, 13),
    ]);
    expect(m.matrix.value).toBeCloseTo(-9 / 16, 14);
    // U·M at u = ¼ is (f0, f1, f2, f3)(¼) = (27, 27, 9, 1)/64.
    expect(m.matrix.UM.map((f) => f * 64)).toEqual(
      [27, 27, 9, 1].map((f) => expect.closeTo(f, 12)),
    );
    expect(Math.abs(m.weightSum - 1)).toBeLessThan(1e-12);
  });

  it('reads the joined pairs as C¹ and C⁰, and a gap when the edge is moved', () => {
    const pair = (secondNet: SurfaceState['secondNet'], net = JOIN_NET) =>
      derive({ ...defaults, mode: 'join', net, secondNet }).join!;
    expect(pair(JOIN_NEXT_C1).weakest).toBe('C1');
    expect(pair(JOIN_NEXT_C0).weakest).toBe('C0');
    // The legs of columns 0 and 3 stay straight in the C⁰ preset.
    expect(pair(JOIN_NEXT_C0).columns.map((c) => c === 'C0')).toEqual([false, true, true, false]);
    const lifted = JOIN_NET.map((row, m) =>
      row.map((p, n) => (m === 3 && n === 1 ? [3, 1, 2] : p)),
    );
    expect(pair(JOIN_NEXT_C1, lifted).weakest).toBe('none');
    expect(derive(defaults).join).toBeNull();
  });
});

describe('the sampled patch', () => {
  it('lies on P(u, v) at every facet corner and iso-line point, sampled once per net', () => {
    const m = at(SADDLE_NET, 0.3, 0.6);
    // The saddle is (3u, 3v, 9(u − ½)(v − ½)/2).
    const saddle = (u: number, v: number) => [3 * u, 3 * v, (9 * (u - 0.5) * (v - 0.5)) / 2];
    m.patch.grid.forEach((row, i) =>
      row.forEach((p, j) =>
        p.forEach((value, d) => expect(value).toBeCloseTo(saddle(i / 16, j / 16)[d], 12)),
      ),
    );
    m.patch.vLines[2].forEach((p, j) =>
      p.forEach((value, d) => expect(value).toBeCloseTo(saddle(j / 32, 2 / 8)[d], 12)),
    );
    expect(derive({ ...m.state, u: 0.9 }).patch).toBe(m.patch);
  });
});

describe('the script', () => {
  it('opens with the defaults, and every scene and step has a caption and a finite formula', () => {
    expect(SCENES[0].setup(defaults)).toEqual(defaults);
    for (const scene of SCENES) {
      const state = scene.setup(defaults);
      expect(state.step).toBe(0);
      const count = steps.count(state);
      expect(count).toBe(STEP_COUNT[state.mode]);
      expect(count).toBeLessThanOrEqual(12);
      for (let k = 0; k <= count; k++) {
        const at = { ...state, step: k };
        expect(steps.describe(at, k), `${scene.id} step ${k}`).toMatch(/\w/);
        expect(steps.formula?.(derive(at), at) ?? '').not.toMatch(/NaN|Infinity|undefined/);
      }
    }
  });
});
