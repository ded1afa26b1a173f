import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { bezierCurvature, cubicSplineC2 } from '../../math';
import lesson from './lesson';
import type { CurvatureModel } from './model';
import { cuspParameters } from './planeModel';
import { type CurvatureState, schema } from './state';

const defaults = defaultsOf(schema) as CurvatureState;
/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: CurvatureState) => lesson.derive(s) as CurvatureModel;
const scene = (id: string) => lesson.scenes!.find((s) => s.id === id)!.apply(defaults);

describe('the plane cubic', () => {
  it('has the frame, κ and circle derived by hand at t = 1/2 of the lecture cubic', () => {
    // P(1/2) = (2, 1.5); P′ = 3(¼(1,2) + ½(2,0) + ¼(1,−2)) = (4.5, 0);
    // P″ = 6(½(1,−2) + ½(−1,−2)) = (0, −12); κ = 4.5·(−12)/4.5³ = −16/27, R = 27/16,
    // the curve turns clockwise, so N = (0, −1) and the centre is (2, 1.5 − 27/16).
    const at = derive({ ...defaults, t: 0.5 }).plane!.at;
    expect(at.point).toEqual([2, 1.5]);
    expect(at.velocity).toEqual([4.5, 0]);
    expect(at.acceleration).toEqual([0, -12]);
    expect(at.curvature).toBeCloseTo(-16 / 27, 14);
    expect(at.tangent).toEqual([1, 0]);
    expect(at.normal!.map((v) => v + 0)).toEqual([0, -1]);
    expect(at.circle!.radius).toBeCloseTo(27 / 16, 14);
    expect(at.circle!.centre[1]).toBeCloseTo(1.5 - 27 / 16, 14);
    expect(at.why).toBeNull();
  });

  it('draws the comb on the outside of the bend', () => {
    const m = derive({ ...defaults, t: 0.5 }).plane!;
    const middle = m.comb.flat().find(([base]) => Math.abs(base[0] - 2) < 1e-12)!;
    // The lecture cubic bends down (centre below), so the tooth at its top points up.
    expect(middle[1][1]).toBeGreaterThan(middle[0][1]);
  });

  it('says why N is undefined at the inflection of the S curve', () => {
    const state = scene('inflection');
    expect(state.t).toBeCloseTo(0.5, 12);
    const m = derive(state).plane!;
    expect(m.at.normal).toBeNull();
    expect(m.at.tangent).not.toBeNull();
    expect(m.at.why).toMatch(/Inflection: κ = 0/);
    expect(m.inflections).toHaveLength(1);
  });

  it('finds the cusp where P2 − P1 = P0 − P3, and says why T is undefined there', () => {
    const state = scene('cusp');
    expect(cuspParameters(state.points)).toEqual([0.5]);
    expect(cuspParameters(defaults.points)).toEqual([]);
    const m = derive(state).plane!;
    expect(m.at.speed).toBe(0);
    expect(m.at.tangent).toBeNull();
    expect(m.at.why).toMatch(/Cusp: P′\(t\) = 0/);
    // The cusp is not an inflection, and no comb tooth is drawn through it.
    expect(m.inflections).toEqual([]);
    expect(m.comb.length).toBe(2);
  });
});

describe('the space curve', () => {
  it('gives the helix κ = a/(a² + b²) and τ = b/(a² + b²) from the general formulas', () => {
    // a = 1, b = 1/4: a² + b² = 17/16, κ = 16/17, τ = 4/17.
    const m = derive({ ...scene('helix'), t: 0.37 }).space;
    expect(Math.abs(m.at.curvature! - 16 / 17)).toBeLessThan(1e-12);
    expect(Math.abs(m.at.torsion! - 4 / 17)).toBeLessThan(1e-12);
    expect(m.closed).toEqual({ curvature: 16 / 17, torsion: 4 / 17 });
    expect(m.flips).toEqual([]);
  });

  it('finds one flip of the twisted cubic near its middle, where κ is smallest', () => {
    const m = derive(scene('twisted')).space;
    expect(m.flips).toHaveLength(1);
    expect(m.flips[0]).toBeCloseTo(0.5, 2);
  });

  it('lifts the plane curve into z = 0 with B = ±e_z', () => {
    const m = derive({ ...defaults, t: 0.5 }).space;
    // κ < 0 (clockwise): T = (1, 0, 0), N = (0, −1, 0), B = T × N = (0, 0, −1).
    expect(m.at.binormal!.map((v) => v + 0)).toEqual([0, 0, -1]);
    expect(m.at.torsion).toBe(0);
  });
});

describe('arc length', () => {
  it('on a line with doubled ends s(t) = 9t² − 6t³, so equal s are not equal t', () => {
    const p = [
      [0, 0],
      [0, 0],
      [3, 0],
      [3, 0],
    ];
    const arc = derive({ ...scene('arc'), points: p, equalSteps: 4 }).arc!;
    expect(arc.length).toBeCloseTo(3, 12);
    // s(1/4) = 9/16 − 6/64 = 0.46875; s(1/2) = 1.5.
    expect(arc.table[1].s).toBeCloseTo(0.46875, 12);
    expect(arc.table[2].s).toBeCloseTo(1.5, 12);
    // s = 1.5 at t = 1/2 by symmetry; s = 0.75 at t with 9t² − 6t³ = 0.75.
    expect(arc.equal[2].t).toBeCloseTo(0.5, 12);
    const t1 = arc.equal[1].t;
    expect(9 * t1 ** 2 - 6 * t1 ** 3).toBeCloseTo(0.75, 10);
  });

  it('every scene opens at a step the clicker can walk from', () => {
    for (const s of lesson.scenes!) {
      const state = s.apply(defaults);
      expect(lesson.steps!.count(state)).toBeGreaterThanOrEqual(5);
      expect(lesson.steps!.describe(state, 0)).not.toBe('');
    }
  });
});

describe('the plane curve from another lesson’s spline', () => {
  const through = scene('natural').points;

  it('puts the cursor on piece i at local u = m·t − i, with κ of that piece', () => {
    // Four pieces, t = 0.6: s = 2.4, piece 2, u = 0.4.
    const m = derive({ ...scene('natural'), t: 0.6 }).plane!;
    const segments = cubicSplineC2(through);
    expect(m.pieces.segments).toEqual(segments);
    expect(m.at.piece).toBe(2);
    expect(m.at.u).toBeCloseTo(0.4, 14);
    expect(m.at.curvature).toBeCloseTo(bezierCurvature(segments[2], 0.4), 12);
    // The plot runs over s ∈ [0, 4], cut at every join.
    expect(m.kappa[0][0]).toBe(0);
    expect(m.kappa.at(-1)!.at(-2)).toBe(4);
    expect(m.kappa.length).toBeGreaterThanOrEqual(4);
  });

  it('names the natural spline’s joins C² with κ equal on both sides, the Catmull-Rom’s C¹ with a jump', () => {
    const natural = derive(scene('natural')).plane!.pieces.joins;
    expect(natural.map((j) => j.continuity)).toEqual(['C2', 'C2', 'C2']);
    for (const j of natural) expect(j.after!).toBeCloseTo(j.before!, 10);
    const catmull = derive(scene('catmull')).plane!.pieces.joins;
    expect(catmull.map((j) => j.continuity)).toEqual(['C1', 'C1', 'C1']);
    expect(Math.max(...catmull.map((j) => Math.abs(j.after! - j.before!)))).toBeGreaterThan(0.1);
  });

  it('falls back to the Bézier curve of too few B-spline points, and says so', () => {
    const three = through.slice(0, 3);
    const m = derive({ ...defaults, source: 'b-spline', points: three }).plane!;
    expect(m.pieces.segments).toEqual([three]);
    expect(m.pieces.notice).toMatch(/at least 4 control points/);
    const b = derive({ ...defaults, source: 'b-spline', points: through }).plane!;
    expect(b.pieces.notice).toBeNull();
    expect(b.pieces.segments).toHaveLength(2);
  });

  it('takes a repeated point of a spline through points once, and a chain’s extra points not at all', () => {
    const repeated = [through[0], through[1], through[1], through[2]];
    const m = derive({ ...defaults, source: 'catmull-rom', points: repeated }).plane!;
    expect(m.pieces.segments).toHaveLength(2);
    expect(m.pieces.notice).toMatch(/repeats the one before/);
    const chain = derive({ ...defaults, source: 'chain', points: through }).plane!;
    expect(chain.pieces.segments).toEqual([through.slice(0, 4)]);
    expect(chain.pieces.notice).toMatch(/the last 1 of 5/);
  });

  it('gives a Hermite spline one gradient per point, Catmull-Rom’s where the link has none', () => {
    const { state, issues } = lesson.normalize!({
      ...scene('natural'),
      source: 'hermite',
      gradients: [[1, 0]],
    });
    expect(state.gradients).toHaveLength(through.length);
    expect(state.gradients[0]).toEqual([1, 0]);
    expect(state.gradients[2]).toEqual([
      (through[3][0] - through[1][0]) / 2,
      (through[3][1] - through[1][1]) / 2,
    ]);
    expect(issues[0]).toMatch(/1 gradients for 5 points/);
    expect(lesson.normalize!({ ...scene('arc'), source: 'natural' }).state.source).toBe('bezier');
  });

  it('a line (two control points) is straight: κ = 0 and the page says why N is undefined', () => {
    const m = derive({
      ...defaults,
      points: [
        [0, 0],
        [2, 1],
      ],
    }).plane!;
    expect(m.at.curvature).toBe(0);
    expect(m.at.why).toMatch(/Inflection/);
  });
});

describe('the κ plot of a spline without a cusp', () => {
  it('draws every piece’s κ whole: one run per piece, no gap beside a C² join', () => {
    // The natural spline through the scene's five villages has no cusp (P′ ≠ 0
    // everywhere), so κ is finite and continuous: nothing of it may be cut.
    // (Catmull–Rom's ends stop, P′ = 0: a cusp, where κ is undefined.)
    for (const id of ['natural']) {
      const m = derive({ ...scene(id), step: 6 });
      const plane = m.plane!;
      expect(plane.cusps, id).toEqual([]);
      const pieces = new Set(plane.kappa.map((run) => Math.floor(run[0] + 1e-9)));
      expect(plane.kappa.length, id).toBe(pieces.size);
      // Each run spans its whole piece, p̄ = i … i + 1.
      for (const run of plane.kappa) {
        const i = Math.floor(run[0] + 1e-9);
        expect(run[0], id).toBeCloseTo(i, 9);
        expect(run[run.length - 2], id).toBeCloseTo(i + 1, 9);
      }
    }
  });
});

describe('the κ plot’s marks', () => {
  it('says κ = 0 once where the cursor stands on the inflection', async () => {
    const { drawHeadless } = await import('../../app/headless');
    const { makeTheme } = await import('../../render/theme');
    const { plotFigure } = await import('./plotFigure');
    const theme = makeTheme(false, true);
    const count = (t: number) => {
      const m = derive({ ...scene('inflection'), step: 6, t });
      const { painter } = drawHeadless(plotFigure, m, { width: 1900, height: 330, theme });
      return painter.labels.filter((l) => /^κ = 0$/.test(l.text.trim())).length;
    };
    // The S curve's inflection is at t = 1/2 (its control points are symmetric
    // about their centre): the value column says κ = 0 and the line goes unnamed.
    expect(count(0.5)).toBe(1);
    // Elsewhere the line is named and the column says the cursor's κ.
    expect(count(0.3)).toBe(1);
  });

  it('names each κ = 0 line beside it, inside the plot: the last one on its left', async () => {
    const { drawHeadless } = await import('../../app/headless');
    const { makeTheme } = await import('../../render/theme');
    const { plotFigure } = await import('./plotFigure');
    // Presenter view's plot strip, and a laptop's (measured on the page).
    for (const [width, height, projector] of [
      [1900, 330, true],
      [900, 220, false],
    ] as const) {
      const m = derive({ ...scene('natural'), step: 6 });
      const theme = makeTheme(false, projector);
      const { painter, view } = drawHeadless(plotFigure, m, { width, height, theme });
      const marks = painter.labels.filter((l) => l.text === 'κ = 0');
      // κ = 0 at p̄ = 0 and 4, the natural spline's straight ends, and at one inflection.
      expect(marks).toHaveLength(3);
      for (const t of [0, 4]) {
        const [x] = view.toScreen([t, 0]);
        const label = marks.reduce((a, b) =>
          Math.abs(a.x + a.width / 2 - x) < Math.abs(b.x + b.width / 2 - x) ? a : b,
        );
        const size = label.height / 1.3;
        const gap = t === 0 ? label.x - x : x - (label.x + label.width);
        // On the plot's side of its line, within half its size of it.
        expect(gap, `p̄ = ${t} at ${width} px`).toBeGreaterThanOrEqual(0);
        expect(gap, `p̄ = ${t} at ${width} px`).toBeLessThanOrEqual(size * 0.5);
      }
    }
  });
});
