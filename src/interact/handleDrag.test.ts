import { describe, expect, it } from 'vitest';
import { OrbitCamera } from '../render/orbitCamera';
import { boundsOf } from '../render/projection';
import { Viewport } from '../render/viewport';
import { HandleDrag, keyStep, nearestHandle } from './handleDrag';

function plane() {
  const view = new Viewport(400, 400);
  view.fit({ minX: -2, minY: -2, maxX: 2, maxY: 2 }, 0);
  return view;
}

describe('dragging a movable point', () => {
  it('picks the nearest handle within reach, the later one on a tie', () => {
    const view = plane();
    const handles = [
      { id: 'a', position: [0, 0] },
      { id: 'b', position: [0, 0] },
      { id: 'c', position: [1, 0] },
    ];
    const [x, y] = view.toScreen([0, 0]);
    expect(nearestHandle(handles, view, [x + 3, y], 10)).toBe('b');
    expect(nearestHandle(handles, view, [x + 50, y], 10)).toBeNull();
  });

  it('lets the drag direction pick from a stack: right takes the last, left the first', () => {
    const view = plane();
    const stack = [
      { id: 'p0', position: [0, 0] },
      { id: 'p1', position: [0, 0] },
    ];
    const at = view.toScreen([0, 0]);
    for (const [dx, id] of [
      [20, 'p1'],
      [-20, 'p0'],
    ] as const) {
      const drag = new HandleDrag(view, stack, 'p1', at);
      expect(drag.move([at[0] + 1, at[1]], false)).toBeNull();
      const moved = drag.move([at[0] + dx, at[1]], false)!;
      expect(moved.id).toBe(id);
      expect(moved.to[0]).toBeCloseTo(view.toWorld([at[0] + dx, at[1]])[0], 12);
    }
  });

  it('follows each handle’s pull where the lesson gives one (repeated knots)', () => {
    const view = plane();
    const knots = [
      { id: 'k1', position: [1, 0], pull: [-1, 0] },
      { id: 'k2', position: [1, 0], pull: [1, 0] },
      { id: 'k3', position: [1, 0], pull: [0, 1] },
    ];
    const at = view.toScreen([1, 0]);
    expect(new HandleDrag(view, knots, 'k1', at).move([at[0] + 30, at[1]], false)!.id).toBe('k2');
    expect(new HandleDrag(view, knots, 'k2', at).move([at[0] - 30, at[1]], false)!.id).toBe('k1');
    expect(new HandleDrag(view, knots, 'k1', at).move([at[0], at[1] - 30], false)!.id).toBe('k3');
  });

  it('in space, Shift moves a point along the one axis nearest the motion, the rest unchanged', () => {
    const camera = new OrbitCamera({ yaw: -60, pitch: 25, perspective: false });
    camera.resize(600, 400);
    camera.fit(
      boundsOf([
        [-1, -1, -1],
        [1, 1, 1],
      ]),
      10,
    );
    const p = [0.2, -0.3, 0.4];
    const at = camera.toScreen(p);
    const drag = new HandleDrag(camera, [{ id: 'x', position: p }], 'x', at);
    // Straight up on screen is (nearly) the z axis with the camera above the scene.
    const moved = drag.move([at[0], at[1] - 60], true)!;
    expect(moved.to[0]).toBe(p[0]);
    expect(moved.to[1]).toBe(p[1]);
    expect(moved.to[2]).toBeGreaterThan(p[2]);
  });

  it('moves about 8 pixels a key press, on a nice step, on each axis’s own scale', () => {
    const view = new Viewport(400, 400);
    view.scaleX = 100; // 8 px = 0.08 units → step 0.1
    view.scaleY = 10; // 8 px = 0.8 units → step 1
    expect(keyStep(view, [0.33, 2.5], [1, 0], 'normal')).toEqual([0.4, 2.5]);
    expect(keyStep(view, [0.33, 2.5], [0, -1], 'normal')).toEqual([0.33, 2]);
    expect(keyStep(view, [0.33, 2.5], [1, 0], 'big')).toEqual([1, 2.5]);
  });
});
