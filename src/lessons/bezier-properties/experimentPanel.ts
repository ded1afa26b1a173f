import type { LessonApi } from '../../app/lesson';
import { SLOT, texNumber } from '../../render/formula';
import type { PropertiesModel } from './model';
import type { PropertiesState } from './state';

export type PanelApi = LessonApi<PropertiesState, PropertiesModel>;

/** An experiment's part of the side panel: its elements are made once, then updated in place. */
export interface Details<M> {
  /** Shows the model; returns the nodes to show, the same array until what is shown changes. */
  update(m: M): readonly Node[];
}

/** What the panel says about one experiment, and its live details. */
export interface ExperimentPanel<M> {
  /** The number of the property (1 … 9), as the notes list them. */
  number: number;
  /** Short name, as in the list of properties. */
  title: string;
  /** The one sentence of explanation. */
  sentence: string;
  /** Builds the details, once, the first time the experiment is shown. */
  build(api: PanelApi): Details<M>;
}

/**
 * The TeX shape of a point with live coordinates, `(\val,\ {}\val)`. The
 * empty group keeps KaTeX's MathML from merging the space into the text of
 * the second number, where LiveFormula would no longer find it to update
 * (the shell's `slotPoint()` has that flaw: screen readers hear the marker).
 */
export const slotPoint = () => `(${SLOT},\\ {}${SLOT})`;

/** The coordinates of a point for `slotPoint()`. */
export const coords = (p: readonly number[], digits = 2) => p.map((v) => texNumber(v, digits));

/**
 * The nodes shown for each arrangement of the details (say "one point moved"
 * or "several"): made when the arrangement first appears, and the same array
 * while it lasts, so the panel replaces its children only when it changes.
 */
export function arrangements(): (key: string, nodes: () => readonly Node[]) => readonly Node[] {
  const made = new Map<string, readonly Node[]>();
  return (key, nodes) => {
    let shown = made.get(key);
    if (!shown) made.set(key, (shown = nodes()));
    return shown;
  };
}
