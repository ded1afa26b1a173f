import { distanceToSegment } from '../../interact/editPoints';
import { trimmed } from '../../kit/format';
import {
  centripetalMu,
  chordLengthMu,
  distance,
  parametricQuadratic,
  parametricQuadraticPoint,
  type Point,
} from '../../math';
import type { Revealed } from '../../kit/script';
import type { Reveal } from './script';

// The parametric quadratic P(μ) = a2μ² + a1μ + a0 through P0
// (μ = 0), P1 (μ = μ1) and P2 (μ = 1), its family, and the rules for μ1.

/** Segments each drawn curve is sampled with: a multiple of 10, so the tenths of μ are samples. */
const SEGMENTS = 100;

/**
 * The members of the family drawn in Figure 2 of the notes: four curves, the
 * first at μ1 = ½ as the notes' text says (its boxes' other values are not
 * in the text, so these are three more across the range).
 */
export const FAMILY = [0.2, 0.35, 0.5, 0.8] as const;

export interface MuRule {
  id: 'uniform' | 'chord' | 'centripetal';
  name: string;
  /** μ1 chosen by the rule; 0 or 1 when P1 coincides with an end point. */
  mu: number;
  /** The rule's μ1 lies in the slider's range, so its curve exists and can be drawn. */
  usable: boolean;
}

/** One drawn quadratic: the slider's, a member of the family, or a rule's. */
export interface Member {
  mu: number;
  /** Index into the figure's palette; null for the slider's own curve (ink). */
  colour: number | null;
  /** Its label on the figure (`μ_1` is written with a subscript). */
  text: string;
  /** The curve, sampled at μ = 0, 1/100, …, 1. */
  curve: Point[];
  /** Points at μ = 0, 0.1, …, 1 (equal steps of the parameter). */
  ticks: Point[];
  /**
   * Where its label may go, best first: points of the curve by how far they
   * stray from the polygon P0 P1 P2 (where the members differ most).
   */
  readonly labelSpots: Point[];
}

/** The three rules of the notes for choosing μ1 from the points. */
export function muRules(p: readonly Point[]): MuRule[] {
  const rules: Omit<MuRule, 'usable'>[] = [
    { id: 'uniform', name: 'Uniform', mu: 0.5 },
    { id: 'chord', name: 'Chord length', mu: chordLengthMu(p[0], p[1], p[2]) },
    { id: 'centripetal', name: 'Centripetal', mu: centripetalMu(p[0], p[1], p[2]) },
  ];
  return rules.map((rule) => ({ ...rule, usable: rule.mu > 0 && rule.mu < 1 }));
}

const fmtMu = (mu: number) => trimmed(mu, 2);

function member(p: readonly Point[], mu: number, colour: number | null, text: string): Member {
  const curve = Array.from({ length: SEGMENTS + 1 }, (_, k) =>
    parametricQuadraticPoint(p[0], p[1], p[2], mu, k / SEGMENTS),
  );
  const ticks = Array.from({ length: 11 }, (_, k) => curve[(k * SEGMENTS) / 10]);
  // Ranked when a label is first placed: most members are unlabelled at most
  // steps, and ranking all ten on every drag frame was a third of its garbage.
  let spots: Point[] | undefined;
  return {
    mu,
    colour,
    text,
    curve,
    ticks,
    get labelSpots() {
      return (spots ??= rankedSpots(p, curve));
    },
  };
}

/** The curve's points by how far they stray from the polygon P0 P1 P2, furthest first. */
function rankedSpots(p: readonly Point[], curve: readonly Point[]): Point[] {
  const away = (q: Point) =>
    Math.min(distanceToSegment(q, p[0], p[1]), distanceToSegment(q, p[1], p[2]));
  return curve
    .slice(4, -4)
    .map((point) => ({ point, away: away(point) }))
    .sort((a, b) => b.away - a.away)
    .map((spot) => spot.point);
}

/** Figure 2's family, without the slider's own curve (drawn on top anyway). */
const family = (p: readonly Point[], mu: number): Member[] =>
  FAMILY.map((value, k) => ({ value, k }))
    .filter(({ value }) => Math.abs(value - mu) > 1e-9)
    .map(({ value, k }) => member(p, value, k, `μ_1 = ${fmtMu(value)}`));

/** The curves of the rules' choices of μ1 (those that exist). */
const ruleMembers = (p: readonly Point[], rules: readonly MuRule[]): Member[] =>
  rules
    .map((rule, k) => ({ rule, k }))
    .filter(({ rule }) => rule.usable)
    .map(({ rule, k }) => member(p, rule.mu, k, `${rule.name}: μ_1 = ${fmtMu(rule.mu)}`));

/** Every curve of the construction, from the points and μ1 alone: no step changes them. */
export interface ParametricCurves {
  /** a0, a1, a2 of equation 3. */
  coefficients: [Point, Point, Point];
  /** P(μ1) from the coefficients' curve, as a check that it is P1. */
  atMu: Point;
  rules: MuRule[];
  /** |P1 − P0| and |P2 − P1|, the lengths the rules use. */
  d0: number;
  d1: number;
  /** The slider's curve. */
  slider: Member;
  /** Figure 2's family (without the slider's μ1), and the rules' curves. */
  family: Member[];
  chosen: Member[];
  /** Every curve some step of the construction draws: the view is fitted to them all at once. */
  all: Point[][];
}

export function parametricCurves(p: readonly Point[], mu: number): ParametricCurves {
  const rules = muRules(p);
  const slider = member(p, mu, null, `μ_1 = ${fmtMu(mu)}`);
  const families = family(p, mu);
  const chosen = ruleMembers(p, rules);
  return {
    coefficients: parametricQuadratic(p[0], p[1], p[2], mu),
    atMu: parametricQuadraticPoint(p[0], p[1], p[2], mu, mu),
    rules,
    d0: distance(p[0], p[1]),
    d1: distance(p[1], p[2]),
    slider,
    family: families,
    chosen,
    all: [slider, ...families, ...chosen].map((m) => m.curve),
  };
}

export interface Parametric extends Omit<ParametricCurves, 'slider' | 'family' | 'chosen'> {
  /** The slider's curve, once the parametric quadratic is shown (null before). */
  current: Member | null;
  /** The curves drawn beneath it: the family at its step, the rules' at theirs. */
  members: Member[];
}

/** The curves the steps so far show, from the curves of the whole construction. */
export function shownCurves(curves: ParametricCurves, shown: Revealed<Reveal>): Parametric {
  const { slider, family: families, chosen, ...rest } = curves;
  const members = shown.is('family') ? families : shown.is('rules') ? chosen : [];
  // Among other curves, the slider's says whose it is: the μ1 we chose, as
  // the notes put it ("slider" named a control presenter view hides).
  const current = members.length
    ? { ...slider, text: `chosen: μ_1 = ${fmtMu(slider.mu)}` }
    : slider;
  return { ...rest, current: shown.has('parametric') ? current : null, members };
}
