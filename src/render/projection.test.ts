import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { OrbitCamera } from './orbitCamera';
import { boundsOf } from './projection';
import { Viewport } from './viewport';

const coordinate = fc.double({ min: -1e3, max: 1e3, noNaN: true });
const point3 = fc.tuple(coordinate, coordinate, coordinate);
const close = (a: readonly number[], b: readonly number[], tolerance: number) =>
  a.every((v, i) => Math.abs(v - b[i]) <= tolerance * Math.max(1, Math.abs(b[i])));

describe('Viewport (the plane)', () => {
  it('world → screen → world is the identity', () => {
    fc.assert(
      fc.property(
        coordinate,
        coordinate,
        fc.double({ min: 1e-3, max: 1e4, noNaN: true }),
        (x, y, scale) => {
          const view = new Viewport(800, 600);
          view.scaleX = view.scaleY = scale;
          view.centerX = 3;
          view.centerY = -2;
          expect(close(view.toWorld(view.toScreen([x, y])), [x, y], 1e-9)).toBe(true);
        },
      ),
    );
  });

  it('puts y up: a point above the centre is drawn above it', () => {
    const view = new Viewport(100, 100);
    view.fit({ minX: -1, minY: -1, maxX: 1, maxY: 1 }, 0);
    expect(view.toScreen([0, 1])[1]).toBeLessThan(view.toScreen([0, 0])[1]);
    expect(view.toScreen([0, 0])).toEqual([50, 50]);
  });

  it('writes its view for a link and reads it back', () => {
    const view = new Viewport(640, 480);
    view.centerX = 1.25;
    view.centerY = -3.5;
    view.scaleX = view.scaleY = 87.5;
    const copy = new Viewport(640, 480);
    expect(copy.decode(view.encode())).toBe(true);
    expect([copy.centerX, copy.centerY, copy.scaleX, copy.scaleY]).toEqual([
      1.25, -3.5, 87.5, 87.5,
    ]);
    for (const bad of ['', '1,2', '1,2,0', '1,2,-5', 'a,b,c', '1,2,1e99', 'NaN,1,1'])
      expect(new Viewport().decode(bad)).toBe(false);
  });
});

describe('OrbitCamera (space)', () => {
  for (const perspective of [false, true]) {
    const name = perspective ? 'perspective' : 'orthographic';
    it(`${name}: a point maps back onto itself on its own drag plane`, () => {
      fc.assert(
        fc.property(
          point3,
          fc.double({ min: -180, max: 180, noNaN: true }),
          fc.double({ min: -80, max: 80, noNaN: true }),
          (p, yaw, pitch) => {
            const camera = new OrbitCamera({ yaw, pitch, perspective });
            camera.resize(800, 600);
            camera.fit({ minX: -1e3, minY: -1e3, maxX: 1e3, maxY: 1e3, minZ: -1e3, maxZ: 1e3 }, 20);
            expect(close(camera.toWorld(camera.toScreen(p), p), p, 1e-7)).toBe(true);
          },
        ),
      );
    });

    it(`${name}: the drag plane faces the viewer (moving on it keeps the depth)`, () => {
      const camera = new OrbitCamera({ yaw: -60, pitch: 25, perspective });
      camera.resize(800, 600);
      camera.fit(
        boundsOf([
          [-1, -1, -1],
          [1, 1, 1],
        ]),
        20,
      );
      const anchor = [0.3, -0.2, 0.5];
      const [sx, sy] = camera.toScreen(anchor);
      const moved = camera.toWorld([sx + 70, sy - 40], anchor);
      expect(camera.depth(moved)).toBeCloseTo(camera.depth(anchor), 9);
    });
  }

  it('z is up: with the camera above, a higher point is drawn higher', () => {
    const camera = new OrbitCamera({ yaw: -60, pitch: 25, perspective: false });
    camera.resize(400, 400);
    camera.fit(
      boundsOf([
        [-1, -1, -1],
        [1, 1, 1],
      ]),
      20,
    );
    expect(camera.toScreen([0, 0, 1])[1]).toBeLessThan(camera.toScreen([0, 0, 0])[1]);
  });

  it('a point dragged along an axis changes only that coordinate', () => {
    const camera = new OrbitCamera({ yaw: -50, pitch: 30, perspective: true });
    camera.resize(800, 600);
    camera.fit(
      boundsOf([
        [-2, -2, -2],
        [2, 2, 2],
      ]),
      20,
    );
    const anchor = [0.5, 1, -0.25];
    const [sx, sy] = camera.toScreen(anchor);
    for (const axis of [
      [1, 0, 0],
      [0, 1, 0],
      [0, 0, 1],
    ]) {
      const to = camera.closestOnAxis([sx + 35, sy - 60], anchor, axis);
      const k = axis.indexOf(1);
      to.forEach((v, i) => {
        if (i !== k) expect(v).toBe(anchor[i]);
      });
    }
    // Along z, the pointer straight above the point lifts it.
    const up = camera.closestOnAxis([sx, sy - 80], anchor, [0, 0, 1]);
    expect(up[2]).toBeGreaterThan(anchor[2]);
  });

  it('orbiting keeps the pitch within ±89° and the view reads back from its link text', () => {
    const camera = new OrbitCamera();
    camera.dragBy(0, 1e6);
    expect(camera.pitch).toBeCloseTo((89 * Math.PI) / 180, 12);
    camera.orbit(30, -10);
    const copy = new OrbitCamera();
    expect(copy.decode(camera.encode())).toBe(true);
    expect(copy.yaw).toBeCloseTo(camera.yaw, 9);
    expect(copy.pitch).toBeCloseTo(camera.pitch, 9);
    for (const bad of ['', '1,2,3', '0,95,1,0,0,0,0', '0,0,1,0,0,0,2', '0,0,0,0,0,0,0'])
      expect(new OrbitCamera().decode(bad)).toBe(false);
  });
});
