import {
  type Point,
  cubicSplinePoint,
  cubicSplineSegments,
  distance,
  naturalCubicTangents,
} from '../../math';
import { boundsOf } from '../../render/projection';
import { roundCoordinate } from './state';

// The global scene: the natural spline is global (move one village and every
// gradient changes) and affine-invariant (map the villages by an affine map
// and the road through them is the mapped road). Both are computed here from
// the villages on the map, with src/math's solve; nothing is assumed.

/** The natural road through some villages: its gradients D0 … Dm and its Bézier pieces. */
export interface NaturalRoad {
  villages: Point[];
  gradients: Point[];
  pieces: Point[][];
}

export interface MovedVillage {
  /** Which village moves: the middle one, P⌊m/2⌋. */
  index: number;
  /** By how much: up by an eighth of the map, to 0.01. */
  shift: Point;
  /** The road after the move. */
  road: NaturalRoad;
  /** |Di after − Di before| for every village. */
  changes: number[];
  /** How many gradients changed (beyond rounding). */
  changed: number;
}

export interface AffineMap {
  /** x ↦ A x + t: A row by row. */
  matrix: [Point, Point];
  shift: Point;
  /** The angle A turns by (degrees) and the factor it scales by. */
  turn: number;
  scale: number;
}

export interface MappedRoad {
  map: AffineMap;
  /** The road's Bézier pieces, mapped (a Bézier piece maps by its control points). */
  mappedRoad: Point[][];
  /** The natural road through the mapped villages. */
  road: NaturalRoad;
  /** The largest distance between the two at `samples` values of p̄. */
  gap: number;
  samples: number;
}

export interface GlobalChange {
  road: NaturalRoad;
  moved: MovedVillage;
  mapped: MappedRoad;
}

/** Samples per segment where the mapped road and the road of the mapped villages are compared. */
const SAMPLES_PER_SEGMENT = 20;
/** The affine map of the scene: turn by 30°, scale by ¾, then shift beside the villages. */
const TURN = 30;
const SCALE = 0.75;

export function naturalRoad(villages: Point[]): NaturalRoad {
  const gradients = naturalCubicTangents(villages);
  return { villages, gradients, pieces: cubicSplineSegments(villages, gradients) };
}

/** A gradient changed when it moved by more than rounding: a millionth of the map's size. */
const changedBeyondRounding = (change: number, span: number) => change > 1e-9 * Math.max(1, span);

export function globalChange(villages: Point[]): GlobalChange {
  const road = naturalRoad(villages);
  const box = boundsOf(villages);
  const span = Math.max(box.maxX - box.minX, box.maxY - box.minY);
  return { road, moved: moveOne(road, span), mapped: mapAll(road, box, span) };
}

function moveOne(before: NaturalRoad, span: number): MovedVillage {
  const v = before.villages;
  const index = Math.floor((v.length - 1) / 2);
  const shift: Point = [0, Math.max(0.01, roundCoordinate(span / 8))];
  const moved = v.map((p, i) => (i === index ? [p[0] + shift[0], p[1] + shift[1]] : p));
  const road = naturalRoad(moved);
  const changes = road.gradients.map((d, i) => distance(d, before.gradients[i]));
  return {
    index,
    shift,
    road,
    changes,
    changed: changes.filter((c) => changedBeyondRounding(c, span)).length,
  };
}

/** x ↦ A x + t. */
export const applyMap = (map: AffineMap, p: Point): Point => [
  map.matrix[0][0] * p[0] + map.matrix[0][1] * p[1] + map.shift[0],
  map.matrix[1][0] * p[0] + map.matrix[1][1] * p[1] + map.shift[1],
];

/** The scene's map: turned and scaled, then shifted to stand beside the villages, a little apart. */
function sceneMap(box: ReturnType<typeof boundsOf>, villages: readonly Point[], span: number) {
  const angle = (TURN * Math.PI) / 180;
  const [c, s] = [SCALE * Math.cos(angle), SCALE * Math.sin(angle)];
  const linear: AffineMap = {
    matrix: [
      [c, -s],
      [s, c],
    ],
    shift: [0, 0],
    turn: TURN,
    scale: SCALE,
  };
  const turned = boundsOf(villages.map((p) => applyMap(linear, p)));
  const shift: Point = [
    roundCoordinate(box.maxX + 0.2 * span - turned.minX),
    roundCoordinate((box.minY + box.maxY) / 2 - (turned.minY + turned.maxY) / 2),
  ];
  return { ...linear, shift };
}

function mapAll(road: NaturalRoad, box: ReturnType<typeof boundsOf>, span: number): MappedRoad {
  const map = sceneMap(box, road.villages, span);
  const mapped = naturalRoad(road.villages.map((p) => applyMap(map, p)));
  // The same p̄ on both: the road of the mapped villages against the map of the road.
  const m = road.villages.length - 1;
  const samples = m * SAMPLES_PER_SEGMENT + 1;
  let gap = 0;
  for (let k = 0; k < samples; k++) {
    const pBar = k / SAMPLES_PER_SEGMENT;
    const ofMapped = cubicSplinePoint(mapped.villages, mapped.gradients, pBar);
    const mappedOf = applyMap(map, cubicSplinePoint(road.villages, road.gradients, pBar));
    gap = Math.max(gap, distance(ofMapped, mappedOf));
  }
  return {
    map,
    mappedRoad: road.pieces.map((piece) => piece.map((p) => applyMap(map, p))),
    road: mapped,
    gap,
    samples,
  };
}
