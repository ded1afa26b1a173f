import { netTables } from './tables';
import { defineLesson } from '../../kit/lesson';
import { PATCH_WEIGHT, spaceFigure } from './figure';
import { exercises } from './exercises';
import { derive } from './model';
import { surfacePanel } from './panel';
import { SCENES, sceneOf } from './scenes';
import { schema } from './state';
import { weightsFigure } from './weightsFigure';

export default defineLesson({
  slug: 'surface',
  schema,
  step: 'step',
  // Each kind of scene has its own steps; the state's mode says which.
  sceneOf,
  derive,
  figures: [spaceFigure, weightsFigure],
  // The patch's box seen from the camera is about as tall as it is wide, and the
  // heat map is square. In presenter view's wide, low row a share of 2.4 left the
  // patch in the middle of a frame twice its width; 1.4 still leaves it its full
  // height in presenter view and at 1400 × 850, and gives the heat map room.
  layout: { row: ['patch', 'weights'], weights: [PATCH_WEIGHT, 1] },
  parameter: { key: 'u', label: 'u', min: 0, max: 1, step: 0.01 },
  scenes: SCENES,
  panel: surfacePanel,
  tables: netTables,
  exercises,
});
