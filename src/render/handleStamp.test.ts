import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type HandleLook, HandleStamper } from './handleStamp';

// A screen canvas and OffscreenCanvas as far as the stamper uses them, so its
// cache can be watched in Node: each bitmap knows whether it was closed, and
// each copy says which bitmap it drew.
class FakeBitmap {
  closed = false;
  constructor(
    readonly width: number,
    readonly height: number,
  ) {}
  close(): void {
    this.closed = true;
  }
}

class FakeContext {
  readonly drawn: FakeBitmap[] = [];
  getTransform() {
    return { a: 2, b: 0, c: 0, d: 2, e: 0, f: 0 };
  }
  drawImage(image: FakeBitmap): void {
    // What a closed ImageBitmap does in a browser.
    if (image.closed) throw new Error('InvalidStateError: the image is closed');
    this.drawn.push(image);
  }
}

class FakeOffscreen {
  constructor(
    readonly width: number,
    readonly height: number,
  ) {}
  getContext() {
    const nothing = () => undefined;
    return new Proxy({}, { get: () => nothing, set: () => true });
  }
  transferToImageBitmap() {
    return new FakeBitmap(this.width, this.height);
  }
}

const globals = globalThis as Record<string, unknown>;
beforeAll(() => {
  globals.CanvasRenderingContext2D = FakeContext;
  globals.OffscreenCanvas = FakeOffscreen;
});
afterAll(() => {
  delete globals.CanvasRenderingContext2D;
  delete globals.OffscreenCanvas;
});

const look = (r: number): HandleLook => ({
  fill: '#fff',
  stroke: '#000',
  width: 2,
  r,
  shape: 'circle',
});

describe('HandleStamper: one stamp per look, copied to every handle', () => {
  it('draws a look once and copies it to each handle', () => {
    const c = new FakeContext();
    const stamper = HandleStamper.for(c as unknown as CanvasRenderingContext2D)!;
    stamper.stamp(10, 10, look(7));
    stamper.stamp(20, 10, look(7));
    expect(c.drawn).toHaveLength(2);
    expect(c.drawn[0]).toBe(c.drawn[1]);
  });

  it('closes the bitmaps it lets go when full, and never copies a closed one', () => {
    const c = new FakeContext();
    const held = HandleStamper.for(c as unknown as CanvasRenderingContext2D)!;
    held.stamp(0, 0, look(1000));
    const first = c.drawn[0];
    // 256 more looks fill the cache past its size: it lets every stamp go.
    const other = HandleStamper.for(c as unknown as CanvasRenderingContext2D)!;
    for (let i = 0; i < 300; i++) other.stamp(0, 0, look(1001 + i));
    expect(first.closed).toBe(true);
    // The first stamper's last look again: a new stamp, not the closed one.
    held.stamp(5, 5, look(1000));
    const again = c.drawn[c.drawn.length - 1];
    expect(again).not.toBe(first);
    expect(again.closed).toBe(false);
  });
});
