import { afterEach, describe, expect, it } from 'vitest';
import { labelLines, labelWidth } from './labelWidth';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

/** A screen canvas's context, as far as measuring goes: bold text is wider, and each measure is counted. */
class ScreenContext extends SvgContext {
  measured = 0;
  override measureText(text: string): { width: number } {
    this.measured++;
    const size = Number(/(\d+(?:\.\d+)?)px/.exec(this.font)![1]);
    return { width: text.length * size * (this.font.startsWith('bold') ? 0.7 : 0.5) };
  }
}

const globals = globalThis as { CanvasRenderingContext2D?: unknown };
afterEach(() => {
  delete globals.CanvasRenderingContext2D;
});

describe('label widths on screen canvases', () => {
  it('are measured once per font and text, and told apart by font and text', () => {
    globals.CanvasRenderingContext2D = ScreenContext;
    const theme = makeTheme(false, false);
    const size = theme.sizes.label;
    const screen = new ScreenContext();
    const painter = new Painter(screen, new Viewport(), theme);
    // "P" at the label's size, "1,0" as a subscript at 0.78 of it (rounded).
    const sub = Math.round(size * 0.78);
    const plain = 0.5 * (size + 3 * sub);
    const bold = 0.7 * (size + 3 * sub);
    expect(labelWidth(painter, 'P_{1,0}')).toBeCloseTo(plain, 9);
    expect(labelWidth(painter, 'P_{1,0}', { bold: true })).toBeCloseTo(bold, 9);
    expect(labelWidth(painter, 'Q_{12,0}')).toBeCloseTo(0.5 * (size + 4 * sub), 9);
    const once = screen.measured;
    // Another canvas, the same labels: nothing measured again, the same widths.
    const other = new ScreenContext();
    const again = new Painter(other, new Viewport(), theme);
    expect(labelWidth(again, 'P_{1,0}')).toBeCloseTo(plain, 9);
    expect(labelWidth(again, 'P_{1,0}', { bold: true })).toBeCloseTo(bold, 9);
    expect(other.measured + screen.measured).toBe(once);
    // The font it measured in is not left on the context.
    expect(other.font).toBe(new SvgContext().font);
  });

  it('are measured every time on a surface that is not a screen canvas (an SVG export)', () => {
    const svg = new ScreenContext();
    const painter = new Painter(svg, new Viewport(), makeTheme(false, false));
    labelWidth(painter, 'P_{1,0}');
    labelWidth(painter, 'P_{1,0}');
    expect(svg.measured).toBe(4);
  });
});

describe('a label too wide for its figure, on lines', () => {
  // Every character 0.5 of the size wide (ScreenContext): at 20 px, 10 px a character.
  const painter = () => new Painter(new ScreenContext(), new Viewport(), makeTheme(false, false));
  const style = { size: 20 };
  it('breaks after a phrase when each phrase fits, not inside an equation', () => {
    // "A plane curve:" is 14 characters (140 px), "B = T × N = −e_z, τ = 0" 21 (e_z: e with a
    // 16 px subscript z: 8 px): 200 + 8 = 208 px. Together 358 px: too wide for 300.
    expect(labelLines(painter(), 'A plane curve: B = T × N = −e_z, τ = 0', style, 300)).toEqual([
      'A plane curve:',
      'B = T × N = −e_z, τ = 0',
    ]);
  });
  it('otherwise breaks between words into lines as even as their number allows', () => {
    // 19 characters, 190 px, in 150: greedily "aaaa bbbb cccc" (140) over "dddd" (40);
    // as even as two lines allow, 90 over 90.
    expect(labelLines(painter(), 'aaaa bbbb cccc dddd', style, 150)).toEqual([
      'aaaa bbbb',
      'cccc dddd',
    ]);
    // One word wider than the room stands alone.
    expect(labelLines(painter(), 'abcdefghijklmnopqrstuvwxyz', style, 100)).toEqual([
      'abcdefghijklmnopqrstuvwxyz',
    ]);
  });
});
