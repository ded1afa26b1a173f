import { SCRIPTS } from './scripts';
import type { ExperimentId, PropertiesState } from './state';

// The state every exercise of the lesson opens on and is worked in: one
// experiment's figure at a step of its script.

/** The experiment's figure as it opens at `step` (a step name of its script). */
export function opened(
  defaults: PropertiesState,
  experiment: ExperimentId,
  changes: Partial<PropertiesState>,
  step: 'last' | ((s: PropertiesState) => number),
): PropertiesState {
  const s: PropertiesState = { ...defaults, experiment, before: [], repeated: 1, ...changes };
  const script = SCRIPTS[experiment];
  return { ...s, step: step === 'last' ? script.lastStep(s) : step(s) };
}
