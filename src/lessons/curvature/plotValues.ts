import type { CursorValues } from '../../kit/valueRows';
import { COLOURS } from './marks';
import type { CurvatureModel } from './model';
import { CATMULL_COLOUR, CATMULL_KAPPA } from './joinsMarks';
import type { CurvatureState } from './state';

// The values the curvature plot writes at its cursor, and the room the fit
// keeps for them above the plot (plotFigure.ts draws them).

/** The names each part plots at once at most (series), for the room their values take. */
const PLOTTED: Record<CurvatureState['part'], readonly string[]> = {
  plane: ['|P′|'],
  joins: ['κ', CATMULL_KAPPA],
  space: ['κ', 'τ'],
  arc: ['s'],
};

/** As many values as the part plots at once, the widest its longest name with a two-digit negative. */
export function valuesRoom(part: CurvatureState['part']): CursorValues {
  const names = PLOTTED[part];
  const longest = names.reduce((a, b) => (b.length > a.length ? b : a));
  return { count: names.length, widest: `${longest} = −00.000` };
}

/** Each value the part has at the cursor t: its name, its value and its colour. */
export function cursorValues(m: CurvatureModel): { name: string; y: number; colour: number }[] {
  const { part } = m.state;
  if (part === 'plane' || part === 'joins') {
    const at = m.plane!.at;
    const out = [{ name: '|P′|', y: at.speed, colour: 4 }];
    if (at.curvature !== null) out.push({ name: 'κ', y: at.curvature, colour: COLOURS.curvature });
    // The dashed curve's value too, in its colour: with κ's, the plot's key.
    if (m.catmullKappa !== null)
      out.push({ name: CATMULL_KAPPA, y: m.catmullKappa, colour: CATMULL_COLOUR });
    return out;
  }
  if (part === 'space') {
    const at = m.space.at;
    const out = [];
    if (at.curvature !== null) out.push({ name: 'κ', y: at.curvature, colour: COLOURS.curvature });
    if (at.torsion !== null) out.push({ name: 'τ', y: at.torsion, colour: COLOURS.torsion });
    return out;
  }
  return [{ name: 's', y: m.arc!.sAtT, colour: 3 }];
}
