/**
 * Property tests run with one seed in `npm test`, so a run is reproducible and
 * CI cannot fail on a case a later run would not meet again. Set FC_SEED to
 * explore other cases (a failure prints its seed and path to replay it).
 */
import fc from 'fast-check';

fc.configureGlobal({ seed: Number(process.env.FC_SEED ?? 20261122) });
