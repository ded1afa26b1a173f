import type { DrawInfo } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/projection';
import { drawAffine } from './affine/draw';
import { drawClosed } from './closed/draw';
import { drawCubic } from './cubic/draw';
import { drawElevate } from './elevate/draw';
import { drawEnds } from './ends/draw';
import { drawHermite } from './hermite/draw';
import { drawHodograph } from './hodograph/draw';
import { drawHull } from './hull/draw';
import { drawLocal } from './local/draw';
import type { ModelOf, PropertiesModel } from './model';
import { controlPoints } from './points';
import { drawRepeat } from './repeat/draw';
import { drawSplit } from './split/draw';
import type { ExperimentId, PropertiesState } from './state';

type Drawings = {
  [X in ExperimentId]: (painter: Painter, m: ModelOf<X>, info: DrawInfo) => void;
};

/** Each experiment's drawing, reading that experiment's model. */
const DRAWINGS: Drawings = {
  ends: drawEnds,
  hull: drawHull,
  local: drawLocal,
  repeat: drawRepeat,
  closed: drawClosed,
  elevate: drawElevate,
  split: drawSplit,
  affine: drawAffine,
  cubic: drawCubic,
  hermite: drawHermite,
  hodograph: drawHodograph,
};

function drawExperiment<X extends ExperimentId>(
  painter: Painter,
  kind: X,
  m: ModelOf<X>,
  info: DrawInfo,
): void {
  DRAWINGS[kind](painter, m, info);
}

/** The point P(t) the figure shows at this step, for presenter view's trail; null before it. */
function movingPoint(m: PropertiesModel): Point | null {
  switch (m.kind) {
    case 'ends':
    case 'hull':
    case 'closed':
    case 'affine':
    case 'cubic':
    case 'hermite':
      return m.shown.has('point') ? m.point : null;
    case 'hodograph':
      return m.shown.has('tangent') ? m.point : null;
    // Where the curve is split, and the point the copies pull: shown with the curve.
    case 'repeat':
    case 'split':
      return m.shown.has('curve') ? m.point : null;
    default:
      return null;
  }
}

export const propertiesFigure: KitFigure<PropertiesState, PropertiesModel> = {
  id: 'experiment',
  title: 'Bézier curve set up for the experiment',
  kind: 'geometry',
  bounds: (m) => boundsOf(m.extent),
  draw: (painter, m, info) => drawExperiment(painter, m.kind, m, info),
  points: [controlPoints],
  addTo: controlPoints,
  trail: movingPoint,
};
