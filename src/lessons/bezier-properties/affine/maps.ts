import { multiplyPlaneMatrices, translationMatrix } from '../../../math';
import type { MapKind } from '../state';

/** The centre the maps act about, and how far right the image is drawn (the frame of the arch cubic (0, 0), (1, 2), (3, 2), (4, 0)). */
export const CENTRE: readonly [number, number] = [2, 1];
export const SHIFT = 6;

/** Each map about the origin, as a 3×3 matrix on [x, y, 1]. */
export const LINEAR: Record<MapKind, number[][]> = {
  rotate: [
    [Math.cos(0.6), -Math.sin(0.6), 0],
    [Math.sin(0.6), Math.cos(0.6), 0],
    [0, 0, 1],
  ],
  scale: [
    [1.4, 0, 0],
    [0, 0.6, 0],
    [0, 0, 1],
  ],
  shear: [
    [1, 0.8, 0],
    [0, 1, 0],
    [0, 0, 1],
  ],
  // A perspective map: the last row makes w depend on the point.
  perspective: [
    [1, 0, 0],
    [0, 1, 0],
    [0.22, 0.12, 1],
  ],
};

/** The matrix of the map: about the centre, then shifted right so both figures show. */
export function mapMatrix(kind: MapKind): number[][] {
  return multiplyPlaneMatrices(
    translationMatrix(SHIFT + CENTRE[0], CENTRE[1]),
    multiplyPlaneMatrices(LINEAR[kind], translationMatrix(-CENTRE[0], -CENTRE[1])),
  );
}
