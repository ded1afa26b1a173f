import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { type Point, cubicSplinePoint, distance, naturalCubicTangents } from '../../math';
import { type AffineMap, applyMap, globalChange, naturalRoad } from './globalChange';
import { mapFormula } from './globalPanel';
import lesson from './lesson';
import { filled } from '../../render/formula';
import type { RoadModel } from './model';
import { scenes } from './scenes';
import { type RoadState, SIX_VILLAGES, normalize, schema } from './state';

const derive = (s: RoadState) => lesson.derive(s) as RoadModel;
const steps = lesson.steps!;
const opened = normalize(scenes.find((s) => s.id === 'global')!.setup(defaultsOf(schema))).state;
const at = (k: number): RoadState => ({ ...opened, step: k });

// P2 = (42, 10) moves up by an eighth of the map, 92/8 = 11.5, to (42, 21.5). In y the
// right-hand side changes only where y2 appears: row 1, 3(y2 − y0), by +34.5, and row 3,
// 3(y4 − y2), by −34.5 (row 2, 3(y3 − y1), does not contain y2). So the change of the
// gradients solves [2 1; 1 4 1; …; 1 2] ΔD = (0, 34.5, 0, −34.5, 0, 0), by hand:
//   ΔDy·418 = −2070, 4140, −69, −3864, 1104, −552, checked row by row:
//     2(−2070) + 4140 = 0;  −2070 + 4·4140 − 69 = 14421 = 34.5·418;  4140 − 4·69 − 3864 = 0;
//     −69 − 4·3864 + 1104 = −14421;  −3864 + 4·1104 − 552 = 0;  1104 − 2·552 = 0.
// x does not change at all (ΔDx = 0). Every one of the six changes; the far ends by
// |ΔD0| = 2070/418 ≈ 4.952 and |ΔD5| = 552/418 ≈ 1.321.
const DELTA_Y = [-2070, 4140, -69, -3864, 1104, -552].map((v) => v / 418);

describe('the global scene: one village moved', () => {
  const change = globalChange(SIX_VILLAGES);

  it('moves the middle village an eighth of the map up', () => {
    expect(change.moved.index).toBe(2);
    expect(change.moved.shift).toEqual([0, 11.5]);
    expect(change.moved.road.villages[2]).toEqual([42, 21.5]);
  });

  it('changes every gradient, as worked by hand and as src/math solves it', () => {
    const before = naturalCubicTangents(SIX_VILLAGES);
    const after = naturalCubicTangents(change.moved.road.villages);
    after.forEach((d, i) => {
      expect(d[0] - before[i][0]).toBeCloseTo(0, 12);
      expect(d[1] - before[i][1]).toBeCloseTo(DELTA_Y[i], 12);
      expect(change.moved.changes[i]).toBeCloseTo(Math.abs(DELTA_Y[i]), 12);
    });
    expect(change.moved.changed).toBe(6);
  });

  it('says so in the caption, with the far ends’ change', () => {
    expect(steps.describe(at(3), 3)).toBe(
      'All 6 gradients change, even D₀ and D₅ at the far ends (by 4.952 and 1.321): the natural spline is global, where Bézier pieces and B-splines have local control',
    );
    expect(steps.describe(at(2), 2)).toBe(
      'P₂ moves 11.5 up, from (42, 10) to (42, 21.5), and the system is solved again',
    );
  });

  it('two villages: a straight road, both gradients move with P₀', () => {
    // D0 = D1 = P1 − P0 (2D0 + D1 = D0 + 2D1 = 3(P1 − P0)). The map is 1 wide, so P0 moves up
    // 1/8 = 0.125, kept to 0.13: both gradients become (1, −0.13), each changed by 0.13.
    const two = globalChange([
      [0, 0],
      [1, 0],
    ]);
    expect(two.moved.index).toBe(0);
    expect(two.moved.shift).toEqual([0, 0.13]);
    two.moved.road.gradients.forEach((d) => {
      expect(d[0]).toBeCloseTo(1, 12);
      expect(d[1]).toBeCloseTo(-0.13, 12);
    });
    expect(two.moved.changed).toBe(2);
  });
});

describe('the global scene: an affine map', () => {
  it('maps the villages and the road to the road through the mapped villages', () => {
    const { mapped } = globalChange(SIX_VILLAGES);
    // A turns by 30° and scales by ¾: A = ¾ [cos 30°, −sin 30°; sin 30°, cos 30°].
    expect(mapped.map.matrix[0][0]).toBeCloseTo(0.75 * Math.cos(Math.PI / 6), 14);
    expect(mapped.map.matrix[1][0]).toBeCloseTo(0.375, 14);
    expect(mapped.gap).toBeLessThan(1e-12);
    expect(mapped.samples).toBe(101);
    expect(steps.formula!(derive(at(5)), at(5))).toMatch(/= 0$/);
    // The panel's copy too: the residue reads 0, not 0.000000.
    expect(filled(mapFormula(derive(at(5)).globalChange!, true))).toMatch(/\| = 0$/);
    expect(steps.describe(at(5), 5)).toBe(
      'The natural road through the mapped villages is the mapped road: at 101 values of p̄ the two are 0.000 apart, rounding aside',
    );
  });

  it('holds for any affine map, shears too: the road is parametric, each coordinate solved alone', () => {
    const coordinate = fc.integer({ min: -100, max: 100 });
    const villages = fc.array(fc.tuple(coordinate, coordinate), { minLength: 2, maxLength: 9 });
    const entry = fc.double({ min: -3, max: 3, noNaN: true });
    fc.assert(
      fc.property(
        villages,
        entry,
        entry,
        entry,
        entry,
        coordinate,
        coordinate,
        (v, a, b, c, d, tx, ty) => {
          const map: AffineMap = {
            matrix: [
              [a, b],
              [c, d],
            ],
            shift: [tx, ty],
            turn: 0,
            scale: 1,
          };
          const road = naturalRoad(v as Point[]);
          const image = naturalRoad(road.villages.map((p) => applyMap(map, p)));
          const m = v.length - 1;
          for (let k = 0; k <= 4 * m; k++) {
            const pBar = k / 4;
            const gap = distance(
              cubicSplinePoint(image.villages, image.gradients, pBar),
              applyMap(map, cubicSplinePoint(road.villages, road.gradients, pBar)),
            );
            // Coordinates of a few hundred at most: rounding is about 1e-13.
            expect(gap).toBeLessThan(1e-6);
          }
        },
      ),
    );
  });

  it('would not hold for a graph y(x): turned a quarter, the villages’ x no longer increase', () => {
    const quarter: AffineMap = {
      matrix: [
        [0, -1],
        [1, 0],
      ],
      shift: [0, 0],
      turn: 90,
      scale: 1,
    };
    const xs = SIX_VILLAGES.map((p) => applyMap(quarter, p)[0]);
    // x = −y: 0, −16, −10, −30, −26, −44.
    expect(xs.map((x) => x + 0)).toEqual([0, -16, -10, -30, -26, -44]);
    expect(xs.every((x, i) => i === 0 || x > xs[i - 1])).toBe(false);
  });
});

describe('the global scene’s steps', () => {
  it('the road and its gradients, the move, every change, the map, the mapped road', () => {
    const names = Array.from(
      { length: steps.count(opened) + 1 },
      (_, k) => derive(at(k)).shown.name,
    );
    expect(names).toEqual(['villages', 'gradients', 'move', 'changes', 'map', 'mapped']);
  });
});
