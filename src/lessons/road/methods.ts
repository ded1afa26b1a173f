import type { RoadMethod } from './state';

// What each of the lecture's answers is called, what shape its pieces have,
// and how it is built, in the words of the panel.

/** Name in the method list and heading of its explanation. */
export const NAMES: Record<RoadMethod, string> = {
  roman: 'Roman road: straight segments',
  quadratic: 'Quadratic pieces, one chosen gradient',
  hermite: 'Cubic Hermite, parabola gradients',
  natural: 'Natural cubic spline',
  clamped: 'Clamped ends: joining other roads',
  ring: 'Ring road: a closed spline',
};

/** Degree and smoothness of each method, for the counting argument. */
export const SHAPE: Record<RoadMethod, { degree: number; continuity: number; closed: boolean }> = {
  roman: { degree: 1, continuity: 0, closed: false },
  quadratic: { degree: 2, continuity: 1, closed: false },
  hermite: { degree: 3, continuity: 1, closed: false },
  natural: { degree: 3, continuity: 2, closed: false },
  clamped: { degree: 3, continuity: 2, closed: false },
  ring: { degree: 3, continuity: 2, closed: true },
};

/** How the method builds the road, and why it looks as it does. */
export const TEXT: Record<RoadMethod, string> = {
  roman:
    'Each segment is a straight line from village to village. The road is continuous, but its direction jumps at every inner village: a traveller turns on the spot. Good enough for a legion, not for a carriage.',
  quadratic:
    'Fit one quadratic per segment. The first needs a gradient at P0: drag the square B0 = P0 + D0/2. Its gradient at P1 fixes the next quadratic, and so on: the whole road is fixed by that one choice. Each control point is the last one reflected in the village, B(i+1) = 2P(i+1) − Bi (dashed polygon), so a poor choice is handed on and the road swings from side to side. This is the C¹ quadratic Bézier spline with first control point B0.',
  hermite:
    'Cubic pieces with a gradient chosen at each village: the gradient at Pi of the parabola through P(i−1), Pi, P(i+1), which is half the chord between the neighbours (arrows). At the ends the notes take zero gradient; you can choose them instead. The joins are C¹: same position and gradient, but the curvature jumps (turn on the comb).',
  natural:
    'Ask for more: at every inner village the two cubics meet with the same position, gradient and second derivative (C²). Counting leaves two conditions free; the natural spline takes the second derivative zero at both ends. The gradients D0 … Dm then solve a tridiagonal system, once for x and once for y.',
  clamped:
    'The road must join existing roads at P0 and Pm at a given angle: drag the squares D0 and Dm (arrows show D/3). The gradients there are given instead of zero curvature, so the first and last rows of the system become [1 | D0] and [1 | Dm].',
  ring: 'A ring road through every village and back to P0: one more segment, from Pm to P0, and every village is an inner join with C² continuity. No ends, so no end conditions: every row is [1 4 1] and the rows wrap round (a cyclic system, still solved in O(m) by two tridiagonal solves).',
};
