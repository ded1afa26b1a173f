import { texNumber } from '../../render/formula';
import { type FormulaParts, joined, live, livePoint, tex } from '../../render/formulaParts';
import type { RoadModel } from './model';

/** The method's defining formula, with the current numbers where it has some. */
export function methodFormula(model: RoadModel): FormulaParts {
  const { state } = model;
  const m = state.villages.length - 1;
  switch (state.road) {
    case 'roman':
      return tex`P(\bar p) = (1-p)\,P_i + p\,P_{i+1},\quad i = \lfloor \bar p \rfloor,\ p = \bar p - i`;
    case 'quadratic': {
      const road = model.road;
      const controls = road.kind === 'pieces' ? road.pieces.map((piece) => piece[1]) : [];
      const lines = [
        tex`D_0 &= ${livePoint(state.quadraticGradient)}`,
        tex`B_0 &= P_0 + \tfrac12 D_0 = ${livePoint(model.quadraticControl)}`,
        ...controls
          .slice(1, 3)
          .map((b, k) => tex`B_{${k + 1}} &= 2P_{${k + 1}} - B_{${k}} = ${livePoint(b)}`),
      ];
      return tex`\begin{aligned}${joined(lines, '\\\\ ')}${controls.length > 3 ? '\\\\ &\\ \\vdots' : ''}\end{aligned}`;
    }
    case 'hermite': {
      const [start, end] = state.ends
        ? [livePoint(state.startGradient), livePoint(state.endGradient)]
        : ['0', '0'];
      return tex`D_i = \tfrac12\,(P_{i+1} - P_{i-1}),\qquad D_0 = ${start},\ D_{${m}} = ${end}`;
    }
    case 'natural':
      return tex`\begin{aligned}P''(0) = 0:&\quad 2D_0 + D_1 = 3(P_1 - P_0)\\ P''(${m}) = 0:&\quad D_{${m - 1}} + 2D_{${m}} = 3(P_{${m}} - P_{${m - 1}})\end{aligned}`;
    case 'clamped':
      return tex`D_0 = ${livePoint(state.startGradient)},\quad D_{${m}} = ${livePoint(state.endGradient)}`;
    case 'ring':
      if (model.ringRhs === null) return tex`\text{needs at least three villages}`;
      return tex`D_{${m}} + 4D_0 + D_1 = 3(P_1 - P_{${m}}),\quad \text{for } x:\ ${live(texNumber(model.ringRhs, 2))}`;
  }
}
