import { defineLesson } from '../../app/lesson';
import { spaceFigure } from './figure';
import { type SurfaceModel, derive } from './model';
import { surfacePanel } from './panel';
import { SCENES } from './presets';
import { type SurfaceState, schema } from './state';
import { steps } from './steps';
import { weightsFigure } from './weightsFigure';

export default defineLesson<SurfaceState, SurfaceModel>({
  slug: 'surface',
  schema,
  derive,
  figures: [spaceFigure, weightsFigure],
  layout: { row: ['patch', 'weights'], weights: [2.4, 1] },
  parameter: { key: 'u', label: 'u', min: 0, max: 1, step: 0.01 },
  steps,
  scenes: SCENES,
  panel: surfacePanel,
});
