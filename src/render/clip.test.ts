import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type ClipRect, clipCubic, clipPolygon, clipPolyline, clipSegment } from './clip';

const rect: ClipRect = { minX: 0, minY: 0, maxX: 100, maxY: 50 };

/** Records the path calls a clip makes. */
function recorder() {
  const calls: { op: string; xy: number[] }[] = [];
  return {
    calls,
    moveTo: (x: number, y: number) => calls.push({ op: 'M', xy: [x, y] }),
    lineTo: (x: number, y: number) => calls.push({ op: 'L', xy: [x, y] }),
    bezierCurveTo: (...xy: number[]) => calls.push({ op: 'C', xy }),
  };
}

describe('clipSegment (Liang–Barsky)', () => {
  it('cuts a segment crossing the rectangle where it enters and leaves', () => {
    // From (−50, 25) to (150, 25): enters at x = 0 (t = ¼), leaves at x = 100 (t = ¾).
    expect(clipSegment(-50, 25, 150, 25, rect)).toEqual([0.25, 0.75]);
    expect(clipSegment(10, 10, 20, 20, rect)).toEqual([0, 1]);
    expect(clipSegment(-10, -10, -20, 60, rect)).toBeNull();
  });
});

describe('clipPolyline', () => {
  it('emits only points inside the rectangle, and nothing for a line wholly outside', () => {
    const xy = [-1000, -1000, 50, 25, 1e9, 30, 60, 40];
    const sink = recorder();
    clipPolyline(xy, rect, sink);
    for (const call of sink.calls) {
      expect(call.xy[0]).toBeGreaterThanOrEqual(0);
      expect(call.xy[0]).toBeLessThanOrEqual(100);
    }
    const outside = recorder();
    expect(clipPolyline([-5, -5, -10, 60, -1, 200], rect, outside)).toBe(0);
  });

  it('costs what the screen shows: a million-unit zoom of a sampled curve stays small', () => {
    // 10 000 vertices of a circle of radius 1e8 px around a point far off: only the few near the screen count.
    const xy: number[] = [];
    for (let i = 0; i <= 10_000; i++) {
      const a = (2 * Math.PI * i) / 10_000;
      xy.push(50 + 1e8 * Math.cos(a), 1e8 + 25 - 1e8 * Math.sin(a) - 1e8);
    }
    const sink = recorder();
    clipPolyline(xy, rect, sink);
    expect(sink.calls.length).toBeLessThan(10);
  });

  it('keeps a visible polyline joined (drops vertices closer than the tolerance, never the ends)', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: 1, max: 49, noNaN: true }), { minLength: 4, maxLength: 40 }),
        (ys) => {
          const xy = ys.flatMap((y, i) => [1 + (i * 98) / (ys.length - 1), y]);
          const sink = recorder();
          clipPolyline(xy, rect, sink);
          expect(sink.calls.filter((c) => c.op === 'M')).toHaveLength(1);
          expect(sink.calls[sink.calls.length - 1].xy).toEqual(xy.slice(-2));
        },
      ),
    );
  });
});

describe('clipCubic', () => {
  it('culls a cubic far off screen and draws a screen-sized one natively', () => {
    const off = recorder();
    expect(clipCubic([200, 200, 300, 200, 300, 300, 400, 300], rect, off, null)).toBeNull();
    expect(off.calls).toHaveLength(0);
    const on = recorder();
    clipCubic([0, 0, 30, 50, 70, 50, 100, 0], rect, on, null);
    expect(on.calls.map((c) => c.op)).toEqual(['M', 'C']);
  });

  it('subdivides a cubic a million times larger than the screen into a few visible pieces', () => {
    // A curve through the screen whose control points are 1e7 px away.
    const q = [-1e7, 25, -1e7 / 3, 25 + 1e6, 1e7 / 3, 25 - 1e6, 1e7, 25];
    const sink = recorder();
    clipCubic(q, rect, sink, null);
    const curves = sink.calls.filter((c) => c.op === 'C');
    expect(curves.length).toBeGreaterThan(0);
    expect(curves.length).toBeLessThan(40);
  });
});

describe('clipPolygon (Sutherland–Hodgman)', () => {
  it('cuts a triangle to the rectangle', () => {
    const cut = clipPolygon(
      [
        [-50, 0],
        [50, 100],
        [150, 0],
      ],
      rect,
    );
    for (const [x, y] of cut) {
      expect(x).toBeGreaterThanOrEqual(-1e-9);
      expect(x).toBeLessThanOrEqual(100 + 1e-9);
      expect(y).toBeGreaterThanOrEqual(-1e-9);
      expect(y).toBeLessThanOrEqual(50 + 1e-9);
    }
    expect(cut.length).toBeGreaterThanOrEqual(4);
  });
});
