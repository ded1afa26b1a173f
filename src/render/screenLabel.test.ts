import { describe, expect, it } from 'vitest';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

const SENTENCE = 'A plane curve: B = T × N = −e_z, τ = 0';

/**
 * A figure too narrow for the sentence on one line (presenter type, 28 px
 * small): the sentence is set on its two phrases, "A plane curve:" and
 * "B = T × N = …", at the figure's foot, lines stacked upwards.
 */
function figure(width: number, height: number) {
  const view = new Viewport(width, height);
  view.fit({ minX: 0, minY: 0, maxX: width, maxY: height }, 0);
  const svg = new SvgContext();
  const painter = new Painter(svg, view, makeTheme(false, true));
  return { painter, svg };
}

/** The labels placed, top to bottom. */
const byRow = (painter: Painter) => [...painter.labels].sort((a, b) => a.y - b.y);
const drawn = (painter: Painter) => byRow(painter).map((l) => l.text);

describe('a label wider than its figure, set on lines', () => {
  it('keeps its lines together, in order, one under another', () => {
    const { painter } = figure(420, 300);
    painter.screenLabel(SENTENCE, 12, 288, { size: 28 });
    const [first, second] = byRow(painter);
    expect(painter.labels).toHaveLength(2);
    expect(first.text).toBe('A plane curve:');
    expect(second.text.startsWith('B = T × N')).toBe(true);
    // One line's pitch apart, the first above, both at the same left edge.
    expect(second.y - first.y).toBeCloseTo(28 * 1.45, 6);
    expect(second.x).toBeCloseTo(first.x, 6);
  });

  it('moves whole off a stroke that crosses one of its lines, rather than leaving that line out', () => {
    const { painter } = figure(420, 300);
    // A stroke across the foot where the lower line would go (kept inside,
    // its middle at 300 − 0.7 · 28 − 2 = 278.4): screen y 276, world y 300 − 276 (y is up).
    painter.segment([0, 24], [420, 24], { width: 3 });
    painter.screenLabel(SENTENCE, 12, 288, { size: 28 });
    const texts = drawn(painter);
    expect(texts).toHaveLength(2);
    expect(texts[0]).toBe('A plane curve:');
    // Both lines stand clear of the stroke, above it, and still one block:
    // a pitch apart at one left edge (moved a line at a time, the lower one
    // went up beside or onto the other).
    const [first, second] = byRow(painter);
    for (const label of [first, second]) expect(label.y + label.height).toBeLessThan(276 - 1.5);
    expect(second.y - first.y).toBeCloseTo(28 * 1.45, 6);
    expect(second.x).toBeCloseTo(first.x, 6);
  });

  it('is left out whole where it is optional and no place is clear', () => {
    const { painter } = figure(420, 300);
    for (let y = 4; y < 300; y += 10) painter.segment([0, y], [420, y], { width: 2 });
    painter.screenLabel(SENTENCE, 12, 288, { size: 28, optional: true });
    expect(drawn(painter)).toEqual([]);
  });
});
