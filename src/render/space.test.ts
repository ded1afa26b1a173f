import { describe, expect, it } from 'vitest';
import { OrbitCamera } from './orbitCamera';
import { Painter } from './painter';
import { boundsOf } from './projection';
import { SpaceScene, shade } from './space';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';

function scene(yaw: number, pitch: number) {
  const camera = new OrbitCamera({ yaw, pitch, perspective: false });
  camera.resize(400, 300);
  camera.fit(
    boundsOf([
      [-1, -1, -1],
      [1, 1, 1],
    ]),
    20,
  );
  const svg = new SvgContext();
  const painter = new Painter(svg, camera, makeTheme(false, false));
  return { camera, svg, space: new SpaceScene(painter, camera) };
}

const square = (z: number) => [
  [-1, -1, z],
  [1, -1, z],
  [1, 1, z],
  [-1, 1, z],
];

describe('SpaceScene: drawing in space far to near', () => {
  it('draws the farther of two squares first, whichever order they were given in', () => {
    for (const [pitch, first] of [
      [60, '#ff0000'], // looking down: the low (red) square is farther
      [-60, '#0000ff'], // looking up: the high (blue) one is
    ] as const) {
      const { svg, space } = scene(-30, pitch);
      space.quad(square(1), '#0000ff');
      space.quad(square(-1), '#ff0000');
      space.flush();
      const fills = svg.elements
        .map((e) => /fill="(#[0-9a-f]{6})"/i.exec(e)?.[1])
        .filter((f): f is string => !!f && f !== '#ffffff');
      // Shading darkens each colour but keeps its hue: the first drawn is the far one.
      const hue = (f: string) => (f.slice(1, 3) !== '00' ? '#ff0000' : '#0000ff');
      expect(hue(fills[0])).toBe(first);
    }
  });

  it('lights a face turned to the light more than one edge-on, never to black', () => {
    const { space, svg } = scene(0, 89);
    // Seen from straight above, the flat square faces both the viewer and (mostly) the light.
    space.quad(square(0), '#808080');
    space.flush();
    const fill = /fill="(#[0-9a-f]{6})"/i.exec(
      svg.elements.find((e) => e.includes('fill="#') && !e.includes('#ffffff'))!,
    )![1];
    const level = parseInt(fill.slice(1, 3), 16);
    expect(level).toBeGreaterThan(0x80 * 0.7);
    expect(level).toBeLessThanOrEqual(0x80);
    expect(shade('#808080', 0)).toBe('#000000');
  });
});

describe('SpaceScene: one stroke per run of lines in one style', () => {
  const strokes = (svg: SvgContext) => svg.elements.filter((e) => e.includes('stroke="'));

  it('strokes a sampled curve, cut into depth-sorted pieces, as one path', () => {
    const { space, svg } = scene(-30, 40);
    const style = { color: '#333333', width: 2 };
    const arc = Array.from({ length: 33 }, (_, i) => [Math.cos(i / 10), Math.sin(i / 10), 0]);
    space.polyline(arc, style);
    space.flush();
    expect(strokes(svg)).toHaveLength(1);
  });

  it('keeps a line behind a square drawn before it and one in front after it', () => {
    const { space, svg } = scene(-30, 60);
    const style = { color: '#00aa00', width: 2 };
    // Looking down, z = −1 is behind the square at z = 0 and z = 1 in front of it.
    space.line([-1, 0, 1], [1, 0, 1], style);
    space.quad(square(0), '#808080');
    space.line([-1, 0, -1], [1, 0, -1], style);
    space.flush();
    const order = svg.elements
      .filter((e) => e.includes('#00aa00') || /fill="#[0-7][0-9a-f]/i.test(e))
      .map((e) => (e.includes('#00aa00') ? 'line' : 'quad'));
    expect(order).toEqual(['line', 'quad', 'line']);
  });
});

describe('OrbitCamera: angles alone in the link (turned, then fitted)', () => {
  const start = { yaw: -60, pitch: 25, perspective: false };

  it('says nothing while the camera looks from where it started', () => {
    expect(new OrbitCamera(start).encodeAngles(start)).toBeNull();
  });

  it('gives back exactly the angles and projection it was turned to', () => {
    const camera = new OrbitCamera(start);
    camera.orbit(37, -12);
    camera.perspective = true;
    const text = camera.encodeAngles(start);
    expect(text).toBe('-23,13,1');
    const other = new OrbitCamera(start);
    expect(other.decodeAngles(text!)).toBe(true);
    expect(other.yaw).toBeCloseTo((-23 * Math.PI) / 180, 14);
    expect(other.pitch).toBeCloseTo((13 * Math.PI) / 180, 14);
    expect(other.perspective).toBe(true);
  });

  it('refuses what is not three numbers in range', () => {
    const camera = new OrbitCamera(start);
    for (const text of ['1,2', '1,2,3', '1,95,0', 'a,b,c', '1,2,0,4,5,6,7'])
      expect(camera.decodeAngles(text), text).toBe(false);
  });
});
