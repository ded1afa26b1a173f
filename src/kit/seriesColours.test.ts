import { describe, expect, it } from 'vitest';
import { makeTheme } from '../render/theme';
import { seriesColour } from './seriesColours';

// Colour difference CIEDE2000 (Sharma, Wu and Dalal 2005), written here from
// the paper, apart from the app: sRGB → linear → XYZ (D65) → CIELAB → ΔE00.
const linear = (c: number) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
const encode = (c: number) => {
  const v = Math.min(1, Math.max(0, c));
  return v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055;
};
const rgb = (hex: string) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);

function lab([r, g, b]: number[]): number[] {
  const [R, G, B] = [r, g, b].map(linear);
  const x = (0.4124564 * R + 0.3575761 * G + 0.1804375 * B) / 0.95047;
  const y = 0.2126729 * R + 0.7151522 * G + 0.072175 * B;
  const z = (0.0193339 * R + 0.119192 * G + 0.9503041 * B) / 1.08883;
  const f = (t: number) => (t > 216 / 24389 ? Math.cbrt(t) : ((24389 / 27) * t + 16) / 116);
  return [116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))];
}

function deltaE00([L1, a1, b1]: number[], [L2, a2, b2]: number[]): number {
  const deg = Math.PI / 180;
  const Cbar = (Math.hypot(a1, b1) + Math.hypot(a2, b2)) / 2;
  const G = 0.5 * (1 - Math.sqrt(Cbar ** 7 / (Cbar ** 7 + 25 ** 7)));
  const [A1, A2] = [(1 + G) * a1, (1 + G) * a2];
  const [C1, C2] = [Math.hypot(A1, b1), Math.hypot(A2, b2)];
  const hue = (b: number, a: number) =>
    a === 0 && b === 0 ? 0 : (Math.atan2(b, a) / deg + 360) % 360;
  const [h1, h2] = [hue(b1, A1), hue(b2, A2)];
  let dh = C1 * C2 === 0 ? 0 : h2 - h1;
  if (dh > 180) dh -= 360;
  else if (dh < -180) dh += 360;
  const dH = 2 * Math.sqrt(C1 * C2) * Math.sin((dh / 2) * deg);
  const Lbar = (L1 + L2) / 2;
  const Cb = (C1 + C2) / 2;
  let hbar = h1 + h2;
  if (C1 * C2 !== 0)
    hbar = Math.abs(h1 - h2) > 180 ? (h1 + h2 + (h1 + h2 < 360 ? 360 : -360)) / 2 : (h1 + h2) / 2;
  const T =
    1 -
    0.17 * Math.cos((hbar - 30) * deg) +
    0.24 * Math.cos(2 * hbar * deg) +
    0.32 * Math.cos((3 * hbar + 6) * deg) -
    0.2 * Math.cos((4 * hbar - 63) * deg);
  const dTheta = 30 * Math.exp(-(((hbar - 275) / 25) ** 2));
  const RC = 2 * Math.sqrt(Cb ** 7 / (Cb ** 7 + 25 ** 7));
  const SL = 1 + (0.015 * (Lbar - 50) ** 2) / Math.sqrt(20 + (Lbar - 50) ** 2);
  const SC = 1 + 0.045 * Cb;
  const SH = 1 + 0.015 * Cb * T;
  const RT = -Math.sin(2 * dTheta * deg) * RC;
  const [l, c, h] = [(L2 - L1) / SL, (C2 - C1) / SC, dH / SH];
  return Math.sqrt(l * l + c * c + h * h + RT * c * h);
}

/** Deuteranopia (severity 1), Machado, Oliveira and Fernandes 2009, on linear RGB. */
const DEUTERANOPIA = [
  [0.367322, 0.860646, -0.227968],
  [0.280085, 0.672501, 0.047413],
  [-0.01182, 0.04294, 0.968881],
];
const deuteranope = (c: number[]) => {
  const l = c.map(linear);
  return DEUTERANOPIA.map((row) => encode(row[0] * l[0] + row[1] * l[1] + row[2] * l[2]));
};
/** A washed-out projector: every colour a third of the way to the screen's background. */
const washed = (c: number[], back: number[]) => c.map((v, i) => v * 0.65 + back[i] * 0.35);

describe('series colours', () => {
  it('CIEDE2000 gives the published test pairs (Sharma et al. 2005, table 1)', () => {
    expect(deltaE00([50, 2.6772, -79.7751], [50, 0, -82.7485])).toBeCloseTo(2.0425, 4);
    expect(deltaE00([50, -1.3802, -84.2814], [50, 0, -82.7485])).toBeCloseTo(1.0, 4);
    expect(deltaE00([60.2574, -34.0099, 36.2677], [60.4626, -34.1751, 39.4387])).toBeCloseTo(
      1.2644,
      4,
    );
    expect(deltaE00([22.7233, 20.0904, -46.694], [23.0331, 14.973, -42.5619])).toBeCloseTo(
      2.0373,
      4,
    );
  });

  // The first four series are drawn side by side (a construction's levels,
  // a quadratic's μ₁ family): told apart at a glance (ΔE00 ≥ 25), still on a
  // washed-out projector (≥ 20), and by a deuteranope (≥ 10), in every theme.
  for (const dark of [false, true])
    for (const projector of [false, true])
      it(`the first four are distinct (${dark ? 'dark' : 'light'}${projector ? ', projector' : ''})`, () => {
        const theme = makeTheme(dark, projector);
        const back = rgb(theme.background);
        const colours = [0, 1, 2, 3].map((k) => rgb(seriesColour(theme.palette, k)));
        const views = {
          seen: (c: number[]) => c,
          washed: (c: number[]) => washed(c, back),
          deuteranope: (c: number[]) => deuteranope(c),
        };
        const floor = { seen: 25, washed: 20, deuteranope: 10 };
        for (const [view, see] of Object.entries(views) as [
          keyof typeof views,
          (c: number[]) => number[],
        ][])
          for (let i = 0; i < 4; i++)
            for (let j = i + 1; j < 4; j++) {
              const d = deltaE00(lab(see(colours[i])), lab(see(colours[j])));
              expect(d, `${view}: series ${i} and ${j}`).toBeGreaterThanOrEqual(floor[view]);
            }
      });
});
