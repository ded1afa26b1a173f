import { h, setHidden } from '../app/dom';
import { choice, number, points } from '../app/fields';
import type { Point } from '../app/lesson';
import { pointerHeld, whenReleased } from '../render/unseen';

// Links from one lesson into another, carrying the curve on screen. What a
// link carries is agreed here, in the kit, so a lesson that links never
// imports the lesson it links to: the curvature lesson reads its link with
// these same sources and limits (its schema uses them).

/** Where the curvature lesson's plane curve comes from: one Bézier curve, or another lesson's spline. */
export type CurveSource = 'bezier' | 'chain' | 'natural' | 'hermite' | 'catmull-rom' | 'b-spline';
export const CURVE_SOURCES: readonly CurveSource[] = [
  'bezier',
  'chain',
  'natural',
  'hermite',
  'catmull-rom',
  'b-spline',
];

/** The most points of the plane curve a link to the curvature lesson carries. */
export const MAX_LINKED_POINTS = 40;

/** What another lesson hands over: its curve's source, points, and (Hermite) gradients and cursor t ∈ [0, 1]. */
export interface CurvatureOf {
  src: CurveSource;
  p: readonly Point[];
  d?: readonly Point[];
  t?: number;
}

// The field kinds the curvature lesson's schema uses for these keys: a
// value is written here exactly as that lesson writes it (its link test
// reads these links back through its schema).
const linked = {
  src: choice<CurveSource>({ default: 'bezier', values: CURVE_SOURCES }),
  p: points({ default: [], min: 2, max: MAX_LINKED_POINTS }),
  d: points({ default: [], min: 0, max: MAX_LINKED_POINTS }),
  t: number({ default: 0, min: 0, max: 1 }),
};

/**
 * The link that opens the curvature lesson on this curve, with κ and the
 * osculating circle shown (step 4); null when the curve has more points than
 * the lesson takes.
 */
export function curvatureHref({ src, p, d = [], t }: CurvatureOf): string | null {
  if (p.length < 2 || p.length > MAX_LINKED_POINTS || d.length > MAX_LINKED_POINTS) return null;
  const parts = [`part=plane`, `src=${linked.src.encode(src)}`, `p=${linked.p.encode([...p])}`];
  if (d.length) parts.push(`d=${linked.d.encode([...d])}`);
  if (t !== undefined) parts.push(`t=${linked.t.encode(Math.min(1, Math.max(0, t)))}`);
  parts.push('step=4');
  return `#/curvature?${parts.join('&')}`;
}

/**
 * A small "Curvature of this curve →" link for another lesson's panel: make it
 * once, and `update` it with the lesson's curve on each new state (hidden
 * where there is none to hand over). While a point or a slider is held, no
 * one can follow the link: it is written once, on release, not on every
 * frame of the drag.
 */
export function curvatureLink(): {
  element: HTMLElement;
  update(curve: CurvatureOf | null): void;
} {
  const anchor = h('a', { href: '#/curvature' }, 'Curvature of this curve →');
  const element = h('p', { class: 'note' }, anchor);
  let latest: CurvatureOf | null = null;
  const write = () => {
    const href = latest && curvatureHref(latest);
    if (href && anchor.getAttribute('href') !== href) anchor.setAttribute('href', href);
    setHidden(element, !href);
  };
  return {
    element,
    update(curve) {
      latest = curve;
      if (pointerHeld()) whenReleased(write);
      else write();
    },
  };
}
