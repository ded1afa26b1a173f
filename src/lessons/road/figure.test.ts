import { describe, expect, it } from 'vitest';
import { defaultsOf } from '../../app/urlState';
import { bezierPoint, type Point } from '../../math';
import { Painter } from '../../render/painter';
import { SvgContext } from '../../render/svgContext';
import { makeTheme } from '../../render/theme';
import { Viewport } from '../../render/viewport';
import { mapFigure } from './figure';
import lesson from './lesson';
import type { RoadModel } from './model';
import { type RoadState, SIX_VILLAGES, normalize, schema } from './state';

/** The model as the shell gets it from the kit: derived once per state, with what the step reveals. */
const derive = (s: RoadState) => lesson.derive(s) as RoadModel;
const stepCount = (s: RoadState) => lesson.steps!.count(s);
/** The map as the shell hosts it: its villages from the kit's point list. */
const map = lesson.figures[0];

function state(change: Partial<RoadState>): RoadState {
  // The whole road (the last step) unless a step is asked for.
  const next = { ...defaultsOf(schema), ...change };
  return normalize({ ...next, step: change.step ?? stepCount(next) }).state;
}

/** Draws the map of `s` to a recording context, as the shell does (without the handles). */
function drawn(s: RoadState, hover: string | null = null): SvgContext {
  const m = derive(s);
  const view = new Viewport(800, 500);
  view.fit(mapFigure.bounds(m), 20);
  const svg = new SvgContext();
  const painter = new Painter(svg, view, makeTheme(false, false));
  mapFigure.draw(painter, m, { hover, thumbnail: false });
  mapFigure.drawOver?.(painter, m, { hover, thumbnail: false });
  return svg;
}

describe('the map', () => {
  const lecture = state({});
  const m = derive(lecture);

  it('knows the segment under the pointer, within twice the tolerance of the road', () => {
    const onSegment2 = bezierPoint(m.visible!.pieces[2], 0.5);
    expect(mapFigure.hoverAt!(m, onSegment2, 0.5)).toBe('seg2');
    expect(mapFigure.hoverAt!(m, [onSegment2[0], onSegment2[1] + 0.9], 0.5)).toBe('seg2');
    expect(mapFigure.hoverAt!(m, [onSegment2[0], onSegment2[1] + 30], 0.5)).toBeNull();
    expect(mapFigure.hoverAt!(derive(state({ view: 'compare' })), onSegment2, 0.5)).toBeNull();
  });

  it('moves the marker p̄ to the road point nearest the pointer, to 0.01', () => {
    const at: Point = bezierPoint(m.visible!.pieces[3], 0.25);
    const next = map.moveHandle!(lecture, 's', [at[0], at[1] + 0.01], m);
    expect(next.pBar).toBe(3.25);
  });

  it('keeps villages to 0.01 and gradients as the vector to their handle', () => {
    expect(map.moveHandle!(lecture, 'p2', [40.123, 11.987], m).villages[2]).toEqual([40.12, 11.99]);
    const clamped = state({ road: 'clamped' });
    // D0/3 ends at the handle: a handle at P0 + (10, −5) is the gradient (30, −15).
    expect(map.moveHandle!(clamped, 'a', [10, -5], derive(clamped)).startGradient).toEqual([
      30, -15,
    ]);
  });

  it('draws the marker label and, over a segment, highlights it', () => {
    const plain = drawn(lecture);
    expect(plain.texts).toContain('p̄ = 2.40: segment 2, p = 0.40');
    const hovered = drawn(lecture, 'seg2');
    expect(hovered.elements.length).toBe(plain.elements.length + 1);
  });

  it('says on the map why the ring through two villages is missing', () => {
    const svg = drawn(
      state({
        villages: [
          [0, 0],
          [60, 25],
        ],
        road: 'ring',
      }),
    );
    expect(svg.texts.join(' ')).toMatch(/A ring road needs at least three villages/);
  });

  it('draws 500 villages without a label for each', () => {
    const villages: Point[] = Array.from({ length: 500 }, (_, i) => [i, Math.sin(i / 10) * 20]);
    const svg = drawn(state({ villages: villages }));
    expect(svg.texts).toEqual(['p̄ = 2.40: segment 2, p = 0.40']);
  });

  it('reaches out to the quadratic’s corners B, but not without end', () => {
    // Quadratics swing: B0 = P0 + D0/2 = (5, 20), then Bᵢ = 2Pᵢ − Bᵢ₋₁, worked by hand:
    // (35, 12), (49, 8), (63, 52), (93, 0). B3 is above the villages and B4 right of them.
    const swing: Partial<RoadState> = {
      villages: SIX_VILLAGES,
      road: 'quadratic',
      quadraticGradient: [10, 40],
    };
    const box = mapFigure.bounds(derive(state(swing)));
    for (const [x, y] of [
      [5, 20],
      [35, 12],
      [49, 8],
      [63, 52],
      [93, 0],
    ]) {
      expect(x).toBeGreaterThanOrEqual(box.minX);
      expect(x).toBeLessThanOrEqual(box.maxX);
      expect(y).toBeGreaterThanOrEqual(box.minY);
      expect(y).toBeLessThanOrEqual(box.maxY);
    }
    // D0 = (10, 400): B0 = (5, 200) is a handle, in the box; the villages and it span
    // x 0…92, y 0…200. B1 = (35, −168) is farther below than 0.3 × 200 = 60: the map
    // stops at y = −60; B4 = (93, 180) is within reach and in.
    const wild = mapFigure.bounds(derive(state({ ...swing, quadraticGradient: [10, 400] })));
    expect(wild).toEqual({ minX: 0, minY: -60, maxX: 93, maxY: 200 });
  });
});

describe('the map’s frame', () => {
  it('holds the arrows D/3 of the back substitution, the last of which points out past the road', () => {
    // Six villages inland: D₅/3 from P₅ ran off the top of the presenter's map.
    for (let step = 0; step <= stepCount(state({})); step++) {
      const m = derive(state({ step }));
      const b = mapFigure.bounds(m);
      const tips = m.state.villages.map((p, i) => [
        p[0] + m.gradients![i][0] / 3,
        p[1] + m.gradients![i][1] / 3,
      ]);
      for (const [x, y] of tips) {
        expect(x, `step ${step}`).toBeGreaterThanOrEqual(b.minX);
        expect(x, `step ${step}`).toBeLessThanOrEqual(b.maxX);
        expect(y, `step ${step}`).toBeGreaterThanOrEqual(b.minY);
        expect(y, `step ${step}`).toBeLessThanOrEqual(b.maxY);
      }
    }
  });
});

describe('the back substitution on the map', () => {
  it('names the arrow of the gradient the step fixes, as its caption does', () => {
    // Six villages inland: step 8 fixes D₅, step 12 fixes D₁ (the captions, read on the page).
    for (const [step, i] of [
      [8, '5'],
      [12, '1'],
    ] as const) {
      const { texts } = drawn(state({ step }));
      const at = texts.indexOf('⅓D');
      expect(at, `step ${step}: ${texts.join(' | ')}`).toBeGreaterThanOrEqual(0);
      expect(texts[at + 1], `step ${step}`).toBe(i);
      expect(
        texts.filter((t) => t === '⅓D'),
        `step ${step}: one arrow named`,
      ).toHaveLength(1);
    }
  });
});
