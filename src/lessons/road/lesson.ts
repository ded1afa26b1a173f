import { sweepTables } from './tables';
import { exercises } from './exercises';
import type { FigureSpec } from '../../app/lesson';
import { defineLesson } from '../../kit/lesson';
import { mapFigure } from './figure';
import { type RoadModel, derive } from './model';
import { roadPanel } from './panel';
import { sceneOf, scenes } from './scenes';
import { roadScript } from './script';
import { type RoadState, normalize, schema } from './state';

const lesson = defineLesson({
  slug: 'road',
  schema,
  step: 'step',
  script: roadScript,
  // The derivation and the global view walk steps of their own; the other scenes share the road's.
  sceneOf,
  derive,
  figures: [mapFigure],
  normalize,
  scenes,
  panel: roadPanel,
  tables: sweepTables,
  exercises,
});

/**
 * The kit lists a figure's point lists first; the road has always drawn its
 * gradient handles and the marker under the villages, and Tab reached them
 * first: kept (the villages are the first `villages.length` of the kit's).
 */
const villagesLast = (figure: FigureSpec<RoadState, RoadModel>) => ({
  ...figure,
  handles: (m: RoadModel) => {
    const all = figure.handles?.(m) ?? [];
    const villages = m.state.villages.length;
    return [...all.slice(villages), ...all.slice(0, villages)];
  },
});

export default { ...lesson, figures: lesson.figures.map(villagesLast) };
