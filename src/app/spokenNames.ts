import { plainLabel } from '../render/handles';
import { fmtPoint } from './dom';
import type { Handle } from './lesson';

/** The same coordinates, one by one (a point of the new model may be a new array). */
const samePlace = (a: readonly number[], b: readonly number[]): boolean =>
  a.length === b.length && a.every((v, d) => v === b[d]);

/**
 * What a screen reader hears for each handle: "P1 at (1.00, 2.00)". Names
 * change with the model only, not with a pan or a zoom; and of 500 villages
 * one is dragged: the others keep the name they had. A handle is matched
 * with the one at its place in the list before, by label and coordinates,
 * so a drag frame builds no string, key or map entry for the handles it did
 * not move (500 villages: 150 KB of garbage a frame when each had a key).
 */
export class SpokenNames {
  private labels: string[] = [];
  private places: (readonly number[])[] = [];
  private names: string[] = [];

  of(handles: readonly Handle[]): string[] {
    const names = handles.map((handle, i) =>
      this.labels[i] === handle.label && samePlace(this.places[i], handle.position)
        ? this.names[i]
        : `${plainLabel(handle.label)} at ${fmtPoint(handle.position)}`,
    );
    this.labels = handles.map((handle) => handle.label);
    this.places = handles.map((handle) => handle.position);
    this.names = names;
    return names;
  }
}
