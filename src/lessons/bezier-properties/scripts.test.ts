import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { elevateDegree } from '../../math';
import { sampleCurve } from './curve';
import { endsScript } from './ends/script';
import lesson from './lesson';
import type { ModelOf, PropertiesModel } from './model';
import { SCENES, sceneOf } from './scenes';
import { SCRIPTS } from './scripts';
import { EXPERIMENT_IDS, type PropertiesState, schema } from './state';

const derive = (s: PropertiesState) => lesson.derive(s) as PropertiesModel;
const opened = (id: string, step: number): PropertiesState => ({
  ...SCENES.find((s) => s.id === id)!.setup(defaultsOf(schema)),
  step,
});
/** The names of a script's presses, in order. */
const names = (s: PropertiesState) =>
  Array.from({ length: SCRIPTS[s.experiment].lastStep(s) + 1 }, (_, k) =>
    SCRIPTS[s.experiment].shown(s, k),
  ).map((shown) => (shown.index ? `${shown.name} ${shown.index}` : shown.name));

describe('the scripts of the nine experiments', () => {
  it('name each press after what it reveals, in teaching order', () => {
    expect(names(opened('ends', 0))).toEqual([
      'points',
      'polygon',
      'curve',
      'ends',
      'tangents',
      'point',
    ]);
    expect(names(opened('hull', 0))).toEqual(['points', 'polygon', 'hull', 'curve', 'point']);
    expect(names(opened('local', 0))).toEqual(['points', 'before', 'moved', 'curve', 'largest']);
    expect(names(opened('closed', 0))).toEqual(['points', 'polygon', 'curve', 'tangents', 'point']);
    expect(names(opened('affine', 0))).toEqual([
      'points',
      'curve',
      'mappedPoints',
      'curveOfMapped',
      'mappedCurve',
      'point',
    ]);
    expect(names(opened('loop', 0))).toEqual([
      'points',
      'polygon',
      'curve',
      'turning',
      'marks',
      'point',
    ]);
    expect(names(opened('hodograph', 0))).toEqual([
      'points',
      'curve',
      'differences',
      'times',
      'hodograph',
      'derivative',
      'tangent',
    ]);
    expect(names(opened('hermite', 0))).toEqual([
      'points',
      'curve',
      'tangents',
      'hermite',
      'point',
    ]);
    // One press per copy, split or elevation, up to the most the lesson shows.
    expect(names(opened('repeat', 0))).toEqual([
      'points',
      'curve',
      'copy 1',
      'copy 2',
      'copy 3',
      'copy 4',
      'copy 5',
    ]);
    expect(names(opened('split', 0))).toHaveLength(7);
    expect(names(opened('elevate', 0))).toHaveLength(14);
  });

  it('opens the lesson on the first experiment at step 0, and finds every experiment its scene', () => {
    const defaults = defaultsOf(schema);
    expect(defaults.step).toBe(0);
    expect(endsScript.lastStep(defaults)).toBe(5);
    for (const experiment of EXPERIMENT_IDS) {
      const scene = SCENES.find((s) => s.id === sceneOf({ ...defaults, experiment }))!;
      expect(scene.experiment).toBe(experiment);
      expect(scene.script).toBe(SCRIPTS[experiment]);
    }
    // The maps and the cubics share their experiment's steps.
    expect(sceneOf({ ...defaults, experiment: 'cubic' })).toBe('inflection');
  });

  it('counts copies, splits and elevations from the steps shown', () => {
    // Step 3: the curve, then two copies more: P1 listed three times.
    const repeat = derive(opened('repeat', 3)) as ModelOf<'repeat'>;
    expect(repeat.copies).toBe(3);
    expect(repeat.controls).toHaveLength(6);
    expect((derive(opened('split', 1)) as ModelOf<'split'>).levels).toHaveLength(1);
    expect((derive(opened('split', 6)) as ModelOf<'split'>).levels).toHaveLength(6);
    const elevate = derive(opened('elevate', 4)) as ModelOf<'elevate'>;
    const thrice = elevateDegree(elevateDegree(elevateDegree(opened('elevate', 0).points)));
    expect(elevate.controls).toEqual(thrice);
    expect(Array.from(elevate.curve)).toEqual(Array.from(sampleCurve(thrice)));
  });

  it('keeps the geometry while only the step changes', () => {
    const ends = [2, 5].map((step) => derive(opened('ends', step)) as ModelOf<'ends'>);
    expect(ends[0].curve).toBe(ends[1].curve);
    expect(ends[0].shown.has('point')).toBe(false);
    expect(ends[1].shown.has('point')).toBe(true);
    // Back to two elevations after four: the same polygons and curve, not made again.
    const two = derive(opened('elevate', 3)) as ModelOf<'elevate'>;
    derive(opened('elevate', 5));
    const again = derive(opened('elevate', 3)) as ModelOf<'elevate'>;
    expect(again.curve).toBe(two.curve);
    expect(again.polygons[2]).toBe(two.polygons[2]);
  });
});
