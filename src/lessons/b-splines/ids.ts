import { MAX_KNOTS, MAX_POINTS } from './state';

/**
 * Ids of one kind of mark (`u0`, `u1`, …), made once for as many as the
 * lesson allows, with a map back to the index: an id is looked up, never parsed.
 */
export interface IdFamily {
  id(index: number): string;
  /** The index of a mark of this kind, else null (another kind, or nothing). */
  index(id: string | null): number | null;
}

function idFamily(prefix: string, size: number): IdFamily {
  const ids = Array.from({ length: size }, (_, i) => `${prefix}${i}`);
  const indices = new Map(ids.map((id, i) => [id, i]));
  return {
    id: (index) => ids[index],
    index: (id) => (id === null ? null : (indices.get(id) ?? null)),
  };
}

/** The knots on the strip: figure handles, each held on its line. */
export const knotIds = idFamily('u', MAX_KNOTS);
/** The weight halos around the control points, grabbed on their ring. */
export const haloIds = idFamily('w', MAX_POINTS);
/** The curve's segments, hovered in the figure or from the panel's buttons (closed: one per point). */
export const segmentIds = idFamily('seg', MAX_POINTS);
