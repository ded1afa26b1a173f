import { describe, expect, it } from 'vitest';
import { Painter } from './painter';
import { SvgContext } from './svgContext';
import { makeTheme } from './theme';
import { Viewport } from './viewport';

describe('SvgContext', () => {
  it('records paths with their style', () => {
    const c = new SvgContext();
    c.strokeStyle = '#123456';
    c.lineWidth = 3;
    c.setLineDash([4, 2]);
    c.beginPath();
    c.moveTo(0, 0);
    c.lineTo(10, 5);
    c.bezierCurveTo(1, 2, 3, 4, 5, 6);
    c.stroke();
    expect(c.elements).toEqual([
      '<path d="M0 0L10 5C1 2 3 4 5 6" fill="none" stroke="#123456" stroke-width="3" stroke-linecap="butt" stroke-linejoin="miter" stroke-dasharray="4 2"/>',
    ]);
  });

  it('escapes text so a label can never become markup', () => {
    const c = new SvgContext();
    c.fillText('<script>&"', 1, 2);
    expect(c.elements[0]).toContain('&lt;script&gt;&amp;&quot;');
    expect(c.texts).toEqual(['<script>&"']);
  });

  it('draws a full circle as two arcs and restores saved styles', () => {
    const c = new SvgContext();
    c.save();
    c.fillStyle = 'red';
    c.beginPath();
    c.arc(10, 10, 5, 0, Math.PI * 2);
    c.fill();
    c.restore();
    expect(c.fillStyle).toBe('#000');
    expect(c.elements[0]).toBe('<path d="M15 10A5 5 0 1 1 5 10A5 5 0 1 1 15 10" fill="red"/>');
  });

  it('serves as a recording context for what a painter draws', () => {
    const c = new SvgContext();
    const view = new Viewport(200, 100);
    view.fit({ minX: 0, minY: 0, maxX: 2, maxY: 1 }, 0);
    const painter = new Painter(c, view, makeTheme(false, false));
    painter.polyline(
      [
        [0, 0],
        [2, 1],
      ],
      { color: '#abcdef', width: 2 },
    );
    painter.label('P_{1,2}', [1, 1]);
    expect(c.elements[0]).toContain('d="M0 100L200 0"');
    expect(c.texts).toEqual(['P', '1,2']);
    expect(c.toSvg(200, 100)).toMatch(
      /^<svg xmlns="http:\/\/www.w3.org\/2000\/svg" width="200" height="100"/,
    );
  });
});
