import { plainLabel } from '../render/handles';
import { fmtPoint } from './dom';
import type { Handle } from './lesson';

/**
 * What a screen reader hears for each handle: "P1 at (1.00, 2.00)". Names
 * change with the model only, not with a pan or a zoom; and of 500 villages
 * one is dragged: the others keep the name they had (no new strings for them).
 */
export class SpokenNames {
  private named = new Map<string, string>();

  of(handles: readonly Handle[]): string[] {
    const before = this.named;
    this.named = new Map();
    return handles.map((handle) => {
      const key = `${handle.label}@${handle.position.join(',')}`;
      const name = before.get(key) ?? `${plainLabel(handle.label)} at ${fmtPoint(handle.position)}`;
      this.named.set(key, name);
      return name;
    });
  }
}
