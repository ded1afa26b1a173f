import { h, setHidden } from '../../app/dom';
import type { Point } from '../../app/lesson';
import type { Source } from './sources';
import { MAX_POINTS, schema } from './state';

/** What another lesson hands over: its curve's source, points, and (Hermite) gradients and cursor t ∈ [0, 1]. */
export interface CurvatureOf {
  src: Source;
  p: readonly Point[];
  d?: readonly Point[];
  t?: number;
}

/**
 * The link that opens the curvature lesson on this curve, with κ and the
 * osculating circle shown (step 4); null when the curve has more points than
 * the lesson takes. Each value is written by the curvature lesson's own field.
 */
export function curvatureHref({ src, p, d = [], t }: CurvatureOf): string | null {
  if (p.length < 2 || p.length > MAX_POINTS || d.length > MAX_POINTS) return null;
  const parts = [`part=plane`, `src=${schema.src.encode(src)}`, `p=${schema.p.encode([...p])}`];
  if (d.length) parts.push(`d=${schema.d.encode([...d])}`);
  if (t !== undefined) parts.push(`t=${schema.t.encode(Math.min(1, Math.max(0, t)))}`);
  parts.push('step=4');
  return `#/curvature?${parts.join('&')}`;
}

/**
 * A small "Curvature of this curve →" link for another lesson's panel: make it
 * once, and `update` it with the lesson's curve on each new state (hidden
 * where there is none to hand over).
 */
export function curvatureLink(): {
  element: HTMLElement;
  update(curve: CurvatureOf | null): void;
} {
  const anchor = h('a', { href: '#/curvature' }, 'Curvature of this curve →');
  const element = h('p', { class: 'note' }, anchor);
  return {
    element,
    update(curve) {
      const href = curve && curvatureHref(curve);
      if (href && anchor.getAttribute('href') !== href) anchor.setAttribute('href', href);
      setHidden(element, !href);
    },
  };
}
