import { describe, expect, it } from 'vitest';
import { normalizeState } from '../../app/lessonState';
import { decodeState, defaultsOf, encodeState } from '../../app/urlState';
import { checkScript, drawState, sceneStates } from '../../kit/scriptChecks';
import { curveFigure } from './curveFigure';
import { knotFigure } from './knotFigure';
import lesson from './lesson';
import type { BSplineModel } from './model';
import { controlPoints } from './points';
import { SCENES } from './scenes';
import { partScript } from './scripts';
import { CLOSED_SLIP, NOTES_SYMBOLS } from './notes';
import { type BSplineState, isUniformPart, normalize, schema } from './state';
import { TEXTS } from './texts';
import { facts } from './facts';
import { basisFigure } from './basisFigure';
import { drawHeadless } from '../../app/headless';
import { makeTheme } from '../../render/theme';

const derive = (s: BSplineState) => lesson.derive(s) as BSplineModel;
const defaults = normalize(defaultsOf(schema)).state;
const sceneState = (id: string, changes: Partial<BSplineState> = {}): BSplineState =>
  normalize({ ...SCENES.find((s) => s.id === id)!.setup(defaults), ...changes }).state;
/** What each step of a scene reveals: the step's name (and which repeat). */
const names = (id: string) => {
  const s = sceneState(id);
  return Array.from({ length: lesson.steps!.count(s) + 1 }, (_, step) => {
    const { shown } = derive({ ...s, step });
    return shown.index > 0 ? `${shown.name} ${shown.index}` : shown.name;
  });
};

describe('the scenes and their named steps', () => {
  // Its captions no longer name a matrix with a TeX subscript (G_Bez) and no
  // formula writes a residue 3.6e-16: the kit's checks hold for it whole.
  it('passes every check of the kit’s script', () => checkScript(lesson));

  it('each scene has its family’s steps, named after what they reveal', () => {
    const uniform = ['points', 'polygon', 'segment', 'segments', 'joints'];
    expect(names('uniform')).toEqual(uniform);
    expect(names('closed')).toEqual(uniform);
    expect(names('local')).toEqual(['points', 'curves', 'moved', 'basis']);
    expect(names('convert')).toEqual(['points', 'curve', 'bezier', 'beziers', 'back']);
    expect(names('properties')).toEqual(['points', 'curve', 'hulls', 'line', 'affine']);
    // One row of Cox–de Boor per press, rows 0 … p.
    const knots = ['points', 'knots', 'row 1', 'row 2', 'row 3', 'row 4', 'curve'];
    for (const id of ['knots', 'clamped', 'repeated']) expect(names(id)).toEqual(knots);
    expect(names('nurbs')).toEqual(['points', 'plain', 'weights', 'sum']);
    expect(names('circle')).toEqual(['points', 'weights', 'arcs', 'samples', 'plain']);
    expect(names('projective')).toEqual(['points', 'curve', 'map', 'oldWeights']);
  });

  it('a knot scene of degree p has p + 1 rows: the last step is p + 3', () => {
    for (const degree of [1, 2, 3, 4, 5])
      expect(lesson.steps!.count(sceneState('knots', { degree }))).toBe(degree + 3);
    expect(partScript('repeated').stepOf(sceneState('repeated'), 'curve')).toBe(6);
  });

  it('captions and formulas come from the step declared with them', () => {
    const s = sceneState('uniform');
    expect(lesson.steps!.describe(s, 2)).toBe(
      'Segment Q₄ blends P₁, P₂, P₃, P₄ with the four bases B₀(t) … B₃(t)',
    );
    const knots = sceneState('knots', { step: 2 });
    expect(lesson.steps!.describe(knots, 2)).toBe(
      'Row 0 of Cox–de Boor: Nᵢ,₀ = 1 on [uᵢ, uᵢ₊₁), else 0',
    );
    expect(lesson.steps!.describe(knots, 4)).toBe('Row 2: each Nᵢ,₂ blends Nᵢ,₁ and Nᵢ₊₁,₁');
    // The last row's formula says the row sums to 1.
    const last = { ...knots, step: 5 };
    expect(lesson.steps!.formula!(derive(last), last)).toMatch(/\\sum_i N_\{i,3\} = 1\.000$/);
    expect(lesson.steps!.formula!(derive(knots), knots)).not.toMatch(/sum/);
  });

  it('on clamped knots the last row’s sum is a Σ column of the triangle, not a line after it (#19)', () => {
    // Clamped knots 0,0,0,0, ¼, ½, ¾, 1,1,1,1 at u = 0.05 (span [u3, u4)), by hand:
    // row 1: N(2,1) = 0.2/0.25 = 0.8, N(3,1) = 0.05/0.25 = 0.2;
    // row 2: N(1,2) = 0.8·0.8 = 0.64, N(2,2) = 0.2·0.8 + (0.45/0.5)·0.2 = 0.34, N(3,2) = 0.1·0.2 = 0.02;
    // row 3: N(0,3) = 0.8·0.64 = 0.512, N(1,3) = 0.2·0.64 + 0.9·0.34 = 0.434,
    // N(2,3) = 0.1·0.34 + (0.7/0.75)·0.02 = 0.0527, N(3,3) = (0.05/0.75)·0.02 = 0.0013; sum 1.
    const clamped = sceneState('clamped');
    const formula = (step: number) =>
      lesson.steps!.formula!(derive({ ...clamped, step }), { ...clamped, step });
    expect(formula(5)).toBe(
      'u = 0.050:\\quad\\begin{array}{r|cccc|c} & i = 0 & i = 1 & i = 2 & i = 3 & \\sum_i \\\\ \\hline ' +
        'N_{i,0} & 0.000 & 0.000 & 0.000 & 1.000 &  \\\\ ' +
        'N_{i,1} & 0.000 & 0.000 & 0.800 & 0.200 &  \\\\ ' +
        'N_{i,2} & 0.000 & 0.640 & 0.340 & 0.020 &  \\\\ ' +
        'N_{i,3} & 0.512 & 0.434 & 0.053 & 0.001 & 1.000\\end{array}',
    );
    // The rows before the last have no Σ column.
    expect(formula(4)).toMatch(/\\begin\{array\}\{r\|cccc\}/);
    expect(formula(4)).not.toMatch(/sum/);
  });

  it('the panel gets a narrow layout of the wide formulas: the same equations and numbers, fewer a line', () => {
    const wideAndNarrow = (id: string, name: string) => {
      const s = sceneState(id);
      const script = partScript(s.part);
      const step = script.stepOf(s, name as never);
      const at = { ...s, step };
      return [false, true].map((narrowBox) => script.formula(at, derive(at), step, narrowBox)!);
    };
    // Back from Bézier: the four B-spline points of the segment again, one a line.
    const convert = sceneState('convert');
    const [wideBack, narrowBack] = wideAndNarrow('convert', 'back');
    const rows = narrowBack.replace(/^\\begin\{aligned\}|\\end\{aligned\}$/g, '').split('\\\\ ');
    expect(rows).toHaveLength(4);
    const segment = derive({ ...convert, step: 4 }).segment;
    rows.forEach((row, r) => {
      const [x, y] = convert.points[segment + r];
      expect(row).toContain(`= (${x.toFixed(2)},\\ ${y.toFixed(2)})`);
      expect(wideBack).toContain(row.replace(/^\s+/, ''));
    });
    // The weighted sum over its denominator: the same terms, as a factor 1/Σ in front.
    const [wideSum, narrowSum] = wideAndNarrow('nurbs', 'sum');
    const [, numerator, denominator] = /\\dfrac\{(.*)\}\{([\d.]+)\}/.exec(wideSum)!;
    expect(narrowSum).toContain(
      `\\tfrac{1}{${denominator}}\\bigl(${numerator
        .split(' + ')
        .map((term) => `{${term}}`)
        .join(' + ')}\\bigr)`,
    );
    expect(narrowSum).not.toContain('dfrac');
    // The derivatives either side of the knot on their side: a row each, = or ≠ between.
    const [wideJoin, narrowJoin] = wideAndNarrow('continuity', 'cubic');
    expect(narrowJoin).toMatch(
      /^\\begin\{array\}\{r\|ccc\} & u \\to [\d.]+\^- & & u \\to [\d.]+\^\+ /,
    );
    const points = (tex: string) => tex.match(/\(-?[\d.]+,\\ -?[\d.]+\)/g)!.sort();
    expect(points(narrowJoin)).toEqual(points(wideJoin));
    expect(narrowJoin.split('\\hline ')[1].split(' \\\\ ')).toHaveLength(4);
    expect(narrowJoin.slice(narrowJoin.indexOf('\\end{array}'))).toBe(
      wideJoin.slice(wideJoin.indexOf('\\end{array}')),
    );
  });

  it('the state says which scene it is in', () => {
    for (const scene of SCENES) expect(sceneState(scene.id).part).toBe(scene.id);
    expect(lesson.scenes!.map((scene) => scene.id)).toEqual(SCENES.map((scene) => scene.id));
  });
});

describe('what a step draws, by name', () => {
  it('step 0 of every scene shows the points alone: no curve, no trail', () => {
    for (const scene of SCENES) {
      const m = derive(sceneState(scene.id));
      expect(m.shown.is('points')).toBe(true);
      expect(curveFigure.trail!(m)).toBeNull();
      expect(curveFigure.trail!(derive({ ...m.state, step: 1 }))).toEqual(m.point);
    }
  });

  it('the knots become handles once the knot vector is shown, never in the uniform cubic', () => {
    const knots = sceneState('knots');
    expect(knotFigure.handles!(derive(knots))).toEqual([]);
    const handles = knotFigure.handles!(derive({ ...knots, step: 1 }));
    expect(handles.map((h) => h.id)).toEqual(knots.knots.map((_, j) => `u${j}`));
    expect(knotFigure.handles!(derive({ ...sceneState('uniform'), step: 4 }))).toEqual([]);
  });

  it('the line’s square handles come with the line’s step', () => {
    const s = sceneState('properties', { step: 2 });
    const ids = (step: number) =>
      lesson.figures[0].handles!(derive({ ...s, step })).map((h) => h.id);
    expect(ids(2)).toEqual(['p0', 'p1', 'p2', 'p3', 'p4', 'p5', 'p6']);
    expect(ids(3).slice(-2)).toEqual(['l0', 'l1']);
    const moved = curveFigure.moveHandle!(s, 'l1', [10, 5], derive(s));
    expect(moved.line).toEqual([s.line[0], [10, 5]]);
  });

  it('every control point keeps its own label, even two on one spot (the circle’s P₀ and P₈)', () => {
    const handles = controlPoints.handles(sceneState('circle'));
    expect(handles.map((h) => [h.label, h.showLabel])).toEqual(
      handles.map((_, i) => [`P_{${i}}`, true]),
    );
  });

  it('draws the same for a step as the step’s name says: more at each step of the uniform cubic', () => {
    const s = sceneState('uniform');
    const sizes = [0, 1, 3, 4].map((step) => drawState(lesson, { ...s, step }).elements);
    expect(sizes).toEqual([...sizes].sort((a, b) => a - b));
  });
});

describe('a point edit takes its weight and its “before” point along', () => {
  it('adds a weight of 1 where the point goes, and refits the knots', () => {
    const s = sceneState('nurbs');
    const added = controlPoints.add(s, [3.5, 3.2])!;
    expect(added.points).toHaveLength(8);
    const at = added.points.findIndex((p) => p[0] === 3.5 && p[1] === 3.2);
    expect(at).toBe(3);
    expect(added.weights).toEqual([1, 1, 4, 1, 1, 1, 0.25, 1]);
    expect(added.before[at]).toEqual([3.5, 3.2]);
    expect(added.knots).toHaveLength(8 + 3 + 1);
    const removed = controlPoints.remove(s, 2)!;
    expect(removed.weights).toEqual([1, 1, 1, 1, 0.25, 1]);
  });

  it('keeps p + 1 points for degree p, and at least four', () => {
    const four = sceneState('knots', {
      points: [
        [0, 0],
        [1, 1],
        [2, 0],
        [3, 1],
      ],
    });
    expect(controlPoints.remove(four, 0)).toBeNull();
    const five = { ...four, points: [...four.points, [4, 0]], degree: 4 };
    expect(controlPoints.remove(normalize(five).state, 0)).toBeNull();
  });
});

describe('derive once, and less per step', () => {
  it('a step or a new t keeps the curve; new points make a new one', () => {
    for (const id of ['uniform', 'knots', 'circle']) {
      const s = sceneState(id);
      const m = derive(s);
      expect(derive({ ...s, step: 2 }).segments).toBe(m.segments);
      expect(derive({ ...s, t: 0.9 }).segments).toBe(m.segments);
      const points = s.points.map((p) => [p[0], p[1] + 1]);
      expect(derive({ ...s, points }).segments).not.toBe(m.segments);
    }
  });
});

describe('the link', () => {
  it('keeps its one-letter keys in their order: x p q t k d u w l', () => {
    const query = encodeState(schema, sceneState('knots'));
    expect(query.split('&').map((part) => part.split('=')[0])).toEqual([
      'x',
      'p',
      'q',
      't',
      'k',
      'd',
      'u',
      'w',
      'l',
    ]);
  });

  it('an old link opens the same state', () => {
    const link = 'x=repeated&k=6&d=3&u=0,0,0,0,1,1,1,2,2,2,2&t=0.3&w=1,1,1,1,1,1,1';
    const state = normalizeState(lesson, decodeState(schema, link).state).state;
    expect(state).toMatchObject({
      part: 'repeated',
      step: 6,
      degree: 3,
      knots: [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2],
      t: 0.3,
    });
    expect(decodeState(schema, link).issues).toEqual([]);
  });
});

/** Every caption of every scene, at every step. */
const allCaptions = () =>
  SCENES.flatMap((scene) => {
    const s = sceneState(scene.id);
    return Array.from({ length: lesson.steps!.count(s) + 1 }, (_, k) =>
      lesson.steps!.describe({ ...s, step: k }, k),
    );
  });

describe('one notation, the app’s: m + 1 control points P₀ … Pm (the slides’ x0 … xm)', () => {
  it('every scene counts its seven points as m + 1 = 7, the knot scenes too', () => {
    expect(lesson.steps!.describe(sceneState('uniform'), 0)).toBe(
      'The m + 1 = 7 control points P₀ … P₆',
    );
    for (const id of ['knots', 'clamped', 'repeated']) {
      const s = sceneState(id);
      expect(lesson.steps!.describe(s, 0)).toMatch(/^The m \+ 1 = 7 control points P₀ … P₆/);
      expect(lesson.steps!.describe({ ...s, step: 1 }, 1)).toBe(
        'The knot vector u0 … u10: m + p + 2 = 11 knots on the strip',
      );
    }
  });

  it('no caption or panel text counts the points as n', () => {
    const texts = [...allCaptions(), ...Object.values(TEXTS).map((t) => t.text)];
    for (const text of texts) expect(text).not.toMatch(/\bn = \d|\bn \+ p|\(n\+p\)|\bun\]|N\(n−1/);
    expect(TEXTS.knots.text).toMatch(/m \+ 1 control points P0 … Pm/);
    expect(TEXTS.knots.text).toMatch(/uₘ₊ₚ₊₁ of m \+ p \+ 2 numbers/);
  });

  // The app writes control points P0 … Pm and the curve P(u) (P(s) in the uniform cubic),
  // as every other lesson does; the notes' x0 … xm and C(u) appear only inside quotation marks.
  const notesLetters = /(?<!\p{L})(?:x(?:[0-9ᵢₘ₀-₉(]|_\{|[im](?!\p{L}))|C(?:\(|\)|_\{|['′″‴⁽]))/u;
  const unquoted = (text: string) => text.replace(/“[^”]*”/g, '“…”');

  it('the notes’ letters, x0 … xm and C(u), are caught where they are written', () => {
    for (const text of [
      'x0 … xm',
      'x(m+1) = x0',
      'xᵢ',
      'x₀',
      '\\,x_{2}',
      'C(u)',
      'H(C)',
      "C'",
      'C′',
      'C_{Hx}',
    ])
      expect(text).toMatch(notesLetters);
    for (const text of [
      'P₀ … Pm',
      'P(u)',
      'C²',
      'C^{2}',
      'the matrix',
      'max_u',
      'h_{20}x_i',
      '“xi(p̄i)”',
    ])
      expect(unquoted(text)).not.toMatch(notesLetters);
  });

  it('writes P₀ … Pm and P(u) in every caption, formula, figure label, handle, fact and panel text', () => {
    const found: string[] = [];
    const check = (where: string, text: string) => {
      if (notesLetters.test(unquoted(text))) found.push(`${where}: ${text}`);
    };
    for (const { id, count, at } of sceneStates(lesson))
      for (let k = 0; k <= count; k++) {
        const state = at(k) as unknown as BSplineState;
        const m = derive(state);
        check(`${id} step ${k} caption`, lesson.steps!.describe(state, k));
        check(`${id} step ${k} formula`, lesson.steps!.formula!(m, state) ?? '');
        for (const text of drawState(lesson, state).texts) check(`${id} step ${k} label`, text);
        for (const row of facts(m))
          for (const cell of row.cells)
            check(`${id} step ${k} fact`, typeof cell === 'string' ? cell : cell.text);
        for (const handle of controlPoints.handles(state)) check(`${id} handle`, handle.label);
      }
    for (const { title, text } of Object.values(TEXTS)) check(title, text);
    for (const [here] of NOTES_SYMBOLS) check('key', here);
    check('closed slip', CLOSED_SLIP.correct);
    expect(found).toEqual([]);
    // The key says how the notes write what the app writes P: points, segments, the curve.
    expect(NOTES_SYMBOLS.map(([here]) => here)).toEqual(
      expect.arrayContaining([
        'P0 … Pm: m + 1 control points, m ≥ 3',
        'P(u): the whole curve (P(s) in the uniform cubic)',
      ]),
    );
    const there = new Map(NOTES_SYMBOLS);
    expect(there.get('P0 … Pm: m + 1 control points, m ≥ 3')).toMatch(
      /^x0 … xm in the lecture slides/,
    );
  });

  it('says once what order means: degree p, order p + 1', () => {
    const saying = Object.values(TEXTS).filter((t) => /\border\b/.test(t.text));
    expect(saying.map((t) => t.title)).toEqual([TEXTS.knots.title]);
    expect(TEXTS.knots.text).toMatch(
      /degree p — of order p \+ 1: the cubic has degree 3 and order 4/,
    );
    expect(allCaptions().filter((c) => /\border\b/.test(c))).toEqual([]);
  });

  it('keys its symbols to the notes’: B(k,n), cᵢ, “knots”, order', () => {
    const notes = NOTES_SYMBOLS.map(([, there]) => there).join(' | ');
    expect(notes).toMatch(/B\(k,n\) of the “Splines” slides is a Bézier/);
    expect(notes).toMatch(/cᵢ in the lecture slides \(c3 … cm\)/);
    expect(notes).toMatch(/say “knots” for the control points themselves/);
    expect(notes).toMatch(/degree is n, and order is n \+ 1/);
  });

  it('names its data after what it shows, not after a lecture that gives no numbers', () => {
    const { issues } = normalize({
      ...defaults,
      points: [
        [0, 0],
        [1, 1],
        [2, 0],
      ],
    });
    expect(issues[0]).toMatch(/the seven default points are shown$/);
    const texts = [...allCaptions(), ...Object.values(TEXTS).map((t) => t.text), ...issues];
    for (const text of texts) expect(text).not.toMatch(/lecture(’|')s/);
  });
});

describe('the basis plot shows what its step shows', () => {
  const basisTexts = (s: BSplineState) => {
    const { texts } = drawState({ ...lesson, figures: [lesson.figures[1]] }, s);
    return texts;
  };

  it('never writes a placeholder: before its step the plot is its axes alone', () => {
    for (const scene of SCENES) {
      const s = sceneState(scene.id);
      for (let k = 0; k <= lesson.steps!.count(s); k++) {
        for (const text of basisTexts({ ...s, step: k }))
          expect(text, `${scene.id} step ${k}`).not.toMatch(/appear|as the steps go on/);
      }
    }
    expect(basisFigure.id).toBe('basis');
  });

  it('at the segment’s step: the four bases of that segment, B₀(t) … B₃(t), with their values', () => {
    const s = { ...sceneState('uniform'), step: 2 };
    const m = derive(s);
    const texts = basisTexts(s);
    // Labels are written in parts (base, subscript): B, 0, (t) = 0.036.
    const written = texts.join('');
    [0, 1, 2, 3].forEach((k) =>
      expect(written).toContain(`B${k}(t) = ${m.basis[m.segment + k].toFixed(3)}`),
    );
    // One step earlier, nothing but the axes' numbers.
    expect(basisTexts({ ...s, step: 1 }).join('')).not.toMatch(/B\d\(t\)/);
  });
});

describe('the uniform cubic bases, written out and derived', () => {
  const numberAfter = (tex: string, head: string) => {
    const at = tex.indexOf(head);
    expect(at, head).toBeGreaterThanOrEqual(0);
    const rest = tex.slice(at + head.length);
    return Number(/= (-?[\d.]+)(?=\s*(?:&|\\\\|\\end|$))/.exec(rest)![1]);
  };

  it('the segment’s step writes B₀(t) … B₃(t) as the notes do, with their values at the local t', () => {
    const s = { ...sceneState('uniform'), step: 2 };
    const m = derive(s);
    const tex = lesson.steps!.formula!(m, s)!;
    const heads = [
      'B_0(t) &= \\tfrac{1}{6}(1 - t)^{3}',
      'B_1(t) &= \\tfrac{1}{6}(3t^{3} - 6t^{2} + 4)',
      'B_2(t) &= \\tfrac{1}{6}(-3t^{3} + 3t^{2} + 3t + 1)',
      'B_3(t) &= \\tfrac{1}{6}t^{3}',
    ];
    heads.forEach((head, k) =>
      expect(numberAfter(tex, head)).toBeCloseTo(m.basis[m.segment + k], 3),
    );
  });

  it('the knot scene derives them row by row on its equally spaced knots, each value the triangle’s', () => {
    const s = sceneState('knots');
    for (let r = 0; r <= 3; r++) {
      const at = { ...s, step: 2 + r };
      const m = derive(at);
      const tex = lesson.steps!.formula!(m, at)!;
      // u = 4.6 in the span [u4, u5): t = 0.6.
      expect(tex, `row ${r}`).toContain('t = u - u_{4} = 0.600');
      for (let k = 0; k <= r && r > 0; k++) {
        const i = 4 - r + k;
        const value = numberAfter(tex, `N_{${i},${r}} &= `);
        expect(value, `N(${i},${r})`).toBeCloseTo(m.table[r][i], 3);
      }
    }
    const last = { ...s, step: 5 };
    expect(lesson.steps!.describe(last, 5)).toBe(
      'Row 3 on equal knots: its pieces are the cubic bases B₀(t) … B₃(t)',
    );
    const tex = lesson.steps!.formula!(derive(last), last)!;
    expect(tex).toContain('N_{1,3} &= \\tfrac{1}{6}(1 - t)^{3} = 0.011');
    expect(tex).toContain('N_{4,3} &= \\tfrac{1}{6}t^{3} = 0.036');
  });

  it('on knots not equally spaced the rows stay the triangle of numbers', () => {
    const s = { ...sceneState('clamped'), step: 5 };
    const tex = lesson.steps!.formula!(derive(s), s)!;
    expect(tex).toMatch(/\\begin\{array\}/);
    expect(tex).not.toMatch(/tfrac/);
    expect(lesson.steps!.describe(s, 5)).toBe('Row 3: each Nᵢ,₃ blends Nᵢ,₂ and Nᵢ₊₁,₂');
  });
});

describe('the closed uniform B-spline needs three points wrapped', () => {
  it('says so in its caption, and the slides’ x₀ = xₘ kindly beside it', () => {
    const s = sceneState('closed');
    expect(lesson.steps!.describe({ ...s, step: 1 }, 1)).toBe(
      'Closed: after P₅ come P₀, P₁, P₂ again (P₆ = P₀, P₇ = P₁, P₈ = P₂)',
    );
    expect(CLOSED_SLIP.written).toMatch(/x₀ = xₘ/);
    expect(CLOSED_SLIP.correct).toMatch(/P\(m\+1\) = P0, P\(m\+2\) = P1 and P\(m\+3\) = P2/);
    expect(TEXTS.closed.text).toMatch(/P\(m\+1\) = P0, P\(m\+2\) = P1, P\(m\+3\) = P2/);
  });

  it('the curve closes with three points wrapped, and not with the last point on the first alone', () => {
    const closed = derive(sceneState('closed'));
    expect(closed.control.slice(-3)).toEqual(closed.control.slice(0, 3));
    expect(
      Math.hypot(closed.start[0] - closed.end[0], closed.start[1] - closed.end[1]),
    ).toBeLessThan(1e-12);
    // The slides' x0 = xm (P0 = Pm here) read as an open curve whose last point is its first: the ends do not meet.
    const points = sceneState('closed').points;
    const open = derive({ ...sceneState('uniform'), points: [...points, points[0]] });
    expect(isUniformPart(open.state.part)).toBe(true);
    expect(Math.hypot(open.start[0] - open.end[0], open.start[1] - open.end[1])).toBeGreaterThan(1);
  });
});

describe('the knot strip', () => {
  it('names each knot at its knot, wherever the cursor is: u₆ is never moved beside u₇', () => {
    // As the projector and a laptop draw the strip: the cursor at every knot
    // and between, over every step of every scene.
    for (const projector of [false, true]) {
      const theme = makeTheme(false, projector);
      const height = Math.round(
        (knotFigure.height ?? 64) * (projector ? (theme.sizes.strip ?? 1) : 1),
      );
      for (const { id, count, at } of sceneStates(lesson))
        for (let k = 0; k <= count; k++)
          for (const t of [0, 0.3, 0.45, 0.5, 0.62, 1]) {
            const state = normalize({ ...(at(k) as unknown as BSplineState), t }).state;
            const m = derive(state);
            const { painter, view } = drawHeadless(knotFigure, m, { width: 620, height, theme });
            for (const label of painter.labels) {
              // u_{6} names knot 6; u_{4…6} ×3 names the run from knot 4.
              const j = /^u_\{(\d+)/.exec(label.text);
              if (!j) continue;
              const [x] = view.toScreen([m.knots[Number(j[1])], 0]);
              expect(
                Math.abs(label.x + label.width / 2 - x),
                `${id} step ${k}, t = ${t}: “${label.text}” is ${(label.x + label.width / 2 - x).toFixed(0)} px from its knot`,
              ).toBeLessThan(1);
            }
          }
    }
  });
});
