import { type Field, quote } from '../../app/fields';

/**
 * What the map is about: one road built by its method (`road`), several
 * answers side by side (`compare`), the natural spline's system derived at one
 * join (`derivation`), or the natural spline moved and mapped (`global`).
 */
export type RoadView = 'road' | 'compare' | 'derivation' | 'global';

/**
 * The view in the link, under its old key `overlay`: the road alone and the
 * comparison keep their `0` and `1` (so every earlier link opens the same
 * picture), the two newer views are written out.
 */
const IN_LINK: Record<RoadView, string> = {
  road: '0',
  compare: '1',
  derivation: 'derivation',
  global: 'global',
};

export function viewField(): Field<RoadView> {
  const views = Object.keys(IN_LINK) as RoadView[];
  return {
    default: 'road',
    encode: (view) => IN_LINK[view],
    decode(raw) {
      // The overlay was a yes/no field, read as `true` and `false` too.
      const view =
        raw === 'true'
          ? 'compare'
          : raw === 'false'
            ? 'road'
            : views.find((v) => IN_LINK[v] === raw);
      return view
        ? { ok: true, value: view }
        : { ok: false, why: `${quote(raw)} is not 0, 1, derivation or global` };
    },
  };
}

/** Several answers side by side (the overlay). */
export const compared = (state: { view: RoadView }) => state.view === 'compare';

/** The views that dissect the natural spline: its derivation, and its global change. */
export const dissects = (state: { view: RoadView }) =>
  state.view === 'derivation' || state.view === 'global';
