import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { drawState } from '../../kit/scriptChecks';
import {
  type Point,
  bezierDerivative,
  bezierFrenetFrame,
  bezierPoint,
  catmullRomSegments,
  cubicSplineC2,
  dot,
  helixFrame,
  uniformBSplineSegments,
} from '../../math';
import lesson from './lesson';
import type { CurvatureModel } from './model';
import { SCENES } from './scenes';
import { type CurvatureState, HELIX_TURNS, TWISTED_CUBIC, schema } from './state';

// Every caption of every scene, walked step by step through the lesson's
// script, against the maths worked here on its own: the pieces of each
// source from src/math, κ's sign from x′y″ − y′x″ of their derivatives, the
// helix's frame from its closed forms.

const defaults = defaultsOf(schema) as CurvatureState;
const derive = (s: CurvatureState) => lesson.derive(s) as CurvatureModel;
const steps = lesson.steps!;
const scene = (id: string) => SCENES.find((s) => s.id === id)!.setup(defaults);
/** Every step of a state's script: its name (what it reveals), caption and formula. */
const walk = (s: CurvatureState) =>
  Array.from({ length: steps.count(s) + 1 }, (_, k) => {
    const at = { ...s, step: k };
    const model = derive(at);
    return {
      k,
      name: model.shown.name,
      caption: steps.describe(at, k),
      formula: steps.formula!(model, at) ?? '',
      model,
    };
  });

/** The plane curve's pieces as each source makes them, straight from src/math. */
function pieces(s: CurvatureState): Point[][] {
  switch (s.source) {
    case 'natural':
      return cubicSplineC2(s.points);
    case 'catmull-rom':
      return catmullRomSegments(s.points, 0);
    case 'b-spline':
      return uniformBSplineSegments(s.points);
    default:
      return [s.points];
  }
}

/** κ at the cursor t of the whole curve: piece i = ⌊m·t⌋ at local u = m·t − i; null where P′ = 0. */
function kappaAt(s: CurvatureState): { kappa: number | null; tangent: Point | null } {
  const segments = pieces(s);
  const m = segments.length;
  const i = Math.min(Math.floor(m * s.t), m - 1);
  const u = m * s.t - i;
  const first = bezierDerivative(segments[i]);
  const [x1, y1] = bezierPoint(first, u);
  const [x2, y2] = first.length > 1 ? bezierPoint(bezierDerivative(first), u) : [0, 0];
  const speed = Math.hypot(x1, y1);
  if (speed < 1e-9) return { kappa: null, tangent: null };
  return { kappa: (x1 * y2 - y1 * x2) / speed ** 3, tangent: [x1 / speed, y1 / speed] };
}

/** The way the curve turns, as the maths says: κ's sign, 0 within rounding of the curve's size. */
function turn(s: CurvatureState): 'left' | 'right' | 'straight' | 'stopped' {
  const { kappa } = kappaAt(s);
  if (kappa === null) return 'stopped';
  const size = Math.max(
    ...s.points.flatMap((p) => s.points.map((q) => Math.hypot(p[0] - q[0], p[1] - q[1]))),
  );
  if (Math.abs(kappa) * size <= 1e-9) return 'straight';
  return kappa > 0 ? 'left' : 'right';
}

const planeScenes = SCENES.filter((s) => s.setup(defaults).part === 'plane').map((s) => s.id);
/** The cursor across the curve, and where each scene puts it. */
const cursors = [...Array.from({ length: 41 }, (_, i) => i / 40), 0.3, 0.45];

describe('the plane curve’s captions say what the maths and the figure show', () => {
  it('names N’s quarter turn by the sign of κ at the cursor, in every scene and at every t', () => {
    const seen = new Set<string>();
    for (const id of planeScenes) {
      for (const t of [scene(id).t, ...cursors]) {
        const s = { ...scene(id), t };
        const expected = turn(s);
        seen.add(expected);
        for (const { name, caption, formula, model } of walk(s)) {
          if (name !== 'normal') continue;
          const where = `${id} at t = ${t}: ${caption}`;
          if (expected === 'left') {
            expect(caption, where).toMatch(/quarter turn anticlockwise, to the left/);
            expect(formula, where).toMatch(/^\\text\{turning left: \}/);
          } else if (expected === 'right') {
            expect(caption, where).toMatch(/quarter turn clockwise, to the right/);
            expect(caption, where).not.toMatch(/anticlockwise/);
            expect(formula, where).toMatch(/^\\text\{turning right: \}/);
          } else {
            expect(caption, where).toMatch(/N is undefined here/);
            expect(caption, where).toContain(expected === 'stopped' ? 'P′ = 0' : 'κ = 0');
          }
          // The arrow drawn is the N the caption names: T turned that way.
          const { tangent } = kappaAt(s);
          const n = model.plane!.at.normal;
          if (expected === 'left' || expected === 'right') {
            const side = expected === 'left' ? 1 : -1;
            const [tx, ty] = tangent!;
            expect(n![0], where).toBeCloseTo(-side * ty, 9);
            expect(n![1], where).toBeCloseTo(side * tx, 9);
          } else expect(n, where).toBeNull();
        }
      }
    }
    // The scenes show N both ways, and where it is undefined both ways.
    expect([...seen].sort()).toEqual(['left', 'right', 'stopped', 'straight']);
  });

  it('draws the osculating circle where the caption says there is one', () => {
    for (const id of planeScenes) {
      for (const t of cursors) {
        const s = { ...scene(id), t };
        const expected = turn(s);
        const step = walk(s).find((w) => w.name === 'curvature')!;
        const where = `${id} at t = ${t}: ${step.caption}`;
        const circle = step.model.plane!.at.circle;
        if (expected === 'left' || expected === 'right') {
          expect(step.caption, where).toBe(
            'The curvature κ and the osculating circle of radius 1/|κ|',
          );
          expect(circle!.radius, where).toBeCloseTo(1 / Math.abs(kappaAt(s).kappa!), 6);
        } else {
          expect(step.caption, where).toMatch(expected === 'stopped' ? /is undefined/ : /κ = 0/);
          expect(circle, where).toBeNull();
        }
      }
    }
  });

  it('says at its first step which curve it is: a natural spline, a Catmull-Rom spline, a Bézier curve of its degree', () => {
    const first = (s: CurvatureState) => walk(s)[0].caption;
    const points = scene('natural').points;
    const count = points.length;
    expect(first(scene('natural'))).toBe(
      `The natural cubic spline through the ${count} points (${cubicSplineC2(points).length} pieces) and the point P(t)`,
    );
    expect(first(scene('catmull'))).toBe(
      `The Catmull-Rom spline through the ${count} points (${catmullRomSegments(points, 0).length} pieces) and the point P(t)`,
    );
    for (const id of ['plane', 'inflection', 'cusp'])
      expect(first(scene(id)), id).toBe('The cubic Bézier curve and the point P(t)');
    // A quartic from de Casteljau's link, a quadratic, and a B-spline of the same points.
    expect(first({ ...defaults, points })).toMatch(/^The Bézier curve of degree 4 and/);
    expect(first({ ...defaults, points: points.slice(0, 3) })).toMatch(
      /^The quadratic Bézier curve/,
    );
    expect(first({ ...defaults, source: 'b-spline', points })).toBe(
      `The uniform cubic B-spline of the ${count} control points (${uniformBSplineSegments(points).length} pieces) and the point P(t)`,
    );
  });

  it('gives inflections and cusps on the parameter the plot runs over, ends exactly 0 and m', () => {
    // The natural spline ends straight (P″ = 0): κ = 0 at p̄ = 0 and p̄ = 4, and one inflection between.
    const natural = walk(scene('natural')).find((w) => w.name === 'inflections')!;
    expect(natural.formula).toMatch(
      /^\\kappa = 0\\ \\text\{at\}\\ \\bar p = 0\.00,\\ 2\.\d\d,\\ 4\.00$/,
    );
    // One Bézier curve: on t, whose values lie in [0, 1].
    const s = walk(scene('inflection')).find((w) => w.name === 'inflections')!;
    expect(s.formula).toBe('\\kappa = 0\\ \\text{at}\\ t = 0.50');
    // The figure names the natural spline's ends as ends, not as inflections.
    const texts = drawState(lesson, { ...scene('natural'), step: 6 }).texts;
    expect(texts.filter((x) => x === 'κ = 0 at the end')).toHaveLength(2);
    expect(texts.filter((x) => x === 'inflection: κ = 0')).toHaveLength(1);
    // With the cursor at an end, the page says why N is undefined there: the curve ends straight.
    expect(derive({ ...scene('natural'), t: 0 }).plane!.at.why).toMatch(/^κ = 0 at the end/);
    expect(derive({ ...scene('natural'), t: 1 }).plane!.at.why).toMatch(/^κ = 0 at the end/);
  });
});

describe('the space curve’s last caption says what its Frenet frame does', () => {
  /** The largest angle B turns through within Δt = ±0.15 anywhere along the curve, in degrees. */
  function largestTurn(binormal: (t: number) => Point | null): number {
    let largest = 0;
    for (let i = 0; i <= 200; i++) {
      const t = i / 200;
      const [a, b] = [binormal(Math.max(0, t - 0.15)), binormal(Math.min(1, t + 0.15))];
      if (a && b)
        largest = Math.max(
          largest,
          (Math.acos(Math.max(-1, Math.min(1, dot(a, b)))) * 180) / Math.PI,
        );
    }
    return largest;
  }
  const last = (s: CurvatureState) => walk(s).find((w) => w.name === 'flips')!;

  it('never flips on a helix: κ = a/(a² + b²) is the same everywhere, and B turns at one steady rate', () => {
    for (const [radius, rise] of [
      [1, 0.25],
      [2, 1],
      [1, -0.5],
      [0.5, 0],
      [1, 3],
    ]) {
      const s = { ...scene('helix'), radius, rise };
      const theta = (t: number) => 2 * Math.PI * HELIX_TURNS * t;
      const frames = Array.from({ length: 201 }, (_, i) =>
        helixFrame(radius, rise, theta(i / 200)),
      );
      // κ never comes near 0: it does not change at all.
      const kappas = frames.map((f) => f.curvature);
      expect(Math.min(...kappas)).toBeGreaterThan(0);
      expect(Math.max(...kappas) - Math.min(...kappas)).toBeLessThan(1e-12);
      // B turns by the same angle at every step of t: steadily, never over all at once.
      const turns = frames.slice(1).map((f, i) => dot(f.binormal, frames[i].binormal));
      expect(Math.max(...turns) - Math.min(...turns)).toBeLessThan(1e-12);
      const { caption, formula } = last(s);
      const where = `a = ${radius}, b = ${rise}: ${caption}`;
      expect(caption, where).toBe(
        'κ = a/(a² + b²) never falls to 0: the frame turns steadily and never flips',
      );
      expect(formula, where).toMatch(/never flips\}$/);
      // N = −(cos θ, sin θ, 0) points at the axis, at any t.
      const m = derive({ ...s, t: 0.37, step: 6 }).space.at;
      const c = [Math.cos(theta(0.37)), Math.sin(theta(0.37)), 0];
      m.normal!.forEach((v, d) => expect(v + 0, where).toBeCloseTo(-c[d], 12));
    }
  });

  it('flips on the twisted cubic, where κ nearly vanishes and B turns over', () => {
    const binormal = (t: number) => {
      try {
        return bezierFrenetFrame(TWISTED_CUBIC, t).binormal ?? null;
      } catch {
        return null;
      }
    };
    expect(largestTurn(binormal)).toBeGreaterThan(90);
    const { caption, formula } = last(scene('twisted'));
    expect(caption).toBe(
      'Where κ → 0 the frame flips: N and B swing round fast (at κ = 0 they would jump)',
    );
    expect(formula).toMatch(/t = 0\.5\d:/);
  });

  it('does not flip on a space cubic whose κ stays away from 0', () => {
    const gentle = [
      [0, 0, 0],
      [1, 0, 0],
      [1, 1, 0],
      [1, 1, 1],
    ];
    const binormal = (t: number) => bezierFrenetFrame(gentle, t).binormal ?? null;
    expect(largestTurn(binormal)).toBeLessThan(90);
    const s = { ...scene('twisted'), spacePoints: gentle };
    const { caption, formula } = last(s);
    expect(caption).toBe('κ stays above 0 all along, so the frame never flips: it turns smoothly');
    const least = Math.min(
      ...Array.from({ length: 241 }, (_, i) => bezierFrenetFrame(gentle, i / 240).curvature),
    );
    expect(formula).toBe(
      `\\min_t \\kappa = ${least.toFixed(3)} > 0:\\ \\text{the frame never flips}`,
    );
  });
});

describe('numbers on screen', () => {
  it('are written to at most four decimals, never as a power of ten, in every caption, formula and figure', () => {
    for (const { id } of SCENES) {
      const s = scene(id);
      for (const { k, caption, formula } of walk(s)) {
        for (const text of [caption, formula, ...drawState(lesson, { ...s, step: k }).texts]) {
          expect(text, `${id} step ${k}`).not.toMatch(/\d\.\d{5,}|\d[eE][-+]?\d|times 10/);
        }
      }
    }
  });
});
