import { h, setHidden, setText } from '../../app/dom';
import { notesSlip } from '../../kit/notes';
import { LiveFormula } from '../../render/formula';
import { type DerivationStep, derivationFormula } from './derivationFormulas';
import type { RoadModel } from './model';
import { solveProgress } from './solve';
import { systemTables } from './systemTable';

/** What each step of the derivation says in the panel, beside its formulas for y and x. */
const TEXT: Record<DerivationStep, string> = {
  villages:
    'The lecture slides work in y alone: x is worked out the same way, with its own a, b, c, d. The join worked at is the inner village nearest the marker p̄; move p̄ to choose another.',
  pieces:
    'Segment i runs from Pᵢ to Pᵢ₊₁. Each is a cubic of its own, four numbers a, b, c, d, so m segments have 4m unknowns.',
  parameter:
    'p = (p̄ − p̄ᵢ)/(p̄ᵢ₊₁ − p̄ᵢ) takes every segment to 0 … 1, however the p̄ᵢ are spaced. Here p̄ᵢ = i, so p = p̄ − i, and a derivative in p is the derivative in p̄. With unequal spacing a derivative in p is (p̄ᵢ₊₁ − p̄ᵢ) times the one in p̄, and the rows below would carry those lengths.',
  left: 'Put p = 0 and p = 1 into y and y′ = b + 2cp + 3dp²: y(0) = a = yᵢ, y′(0) = b = Dᵢ, y(1) = a + b + c + d = yᵢ₊₁, y′(1) = b + 2c + 3d = Dᵢ₊₁. Solved for c and d, with the numbers of the segment left of the join.',
  right: 'The segment right of the join, from the same four conditions at its own ends.',
  second:
    'Differentiate once more: y″ = 2c + 6dp. At the end of the left segment (p = 1) it is 2c + 6d.',
  equal:
    'C² asks the two pieces to bend alike where they meet: y″ at p = 1 of the left segment equals y″ at p = 0 of the right one, 2c.',
  substitute:
    'Write c and d in y and D on both sides: the heights are known, the three gradients at and beside the join are not.',
  row: 'Collect the D’s on the left and the heights on the right. Every inner village gives such a row: [1 4 1].',
  start:
    'The natural end: no bending where the road starts, y″ = 0 at p = 0 of segment 0, so c₀ = 0 and the first row is [2 1].',
  end: 'The other natural end: y″ = 0 at p = 1 of the last segment, 2c + 6d = 0, and the last row is [1 2].',
  system:
    'Every row together: a tridiagonal system for D₀ … Dₘ, one for x and one for y with the same matrix. The first scene solves it by the Thomas algorithm, step by step.',
};

/** Whether the system's table is shown: from the first row the steps derive. */
const TABLE_FROM: readonly DerivationStep[] = ['row', 'start', 'end', 'system'];

/** The derivation view's section: the step in words, its formula for y and for x, the system. */
export function derivationSection() {
  const title = h('h2', {});
  const text = h('p', {});
  const formulas = [new LiveFormula(true), new LiveFormula(true)];
  const labels = [
    h('p', { class: 'note' }, 'For x, the same way:'),
    h('p', { class: 'note' }, 'For y:'),
  ];
  const tables = systemTables();
  const element = h(
    'section',
    { 'aria-label': 'The system, derived' },
    title,
    text,
    labels[1],
    formulas[1].element,
    labels[0],
    formulas[0].element,
    tables.element,
    notesSlip(
      'slides',
      'the end condition as yₘ″(1) = 0, so 2cₘ + 6dₘ = 0',
      'The last segment is m − 1, from Pₘ₋₁ to Pₘ: y″ₘ₋₁(1) = 0, so 2cₘ₋₁ + 6dₘ₋₁ = 0, which gives the row Dₘ₋₁ + 2Dₘ = 3(yₘ − yₘ₋₁) they go on to write.',
    ),
  );

  return {
    element,
    update(m: RoadModel) {
      const work = m.derivation;
      setHidden(element, !work);
      if (!work || !m.solve) return;
      const name = m.shown.name as DerivationStep;
      setText(
        title,
        work.join === null
          ? 'The system, derived: two villages, no inner join'
          : `The system, derived at the join P${work.join}`,
      );
      setText(text, TEXT[name] ?? '');
      const marker = { pBar: m.state.pBar, ...m.along };
      formulas.forEach((formula, k) => {
        const parts = derivationFormula(name, work, k as 0 | 1, marker, true);
        setHidden(formula.element, !parts);
        setHidden(labels[k], !parts);
        if (parts) formula.set(parts);
      });
      const table = TABLE_FROM.includes(name);
      setHidden(tables.element, !table);
      // Every gradient known, the join's row marked: the system as the derivation ends it.
      if (table)
        tables.update(m.solve, { ...solveProgress(m.solve.n, 0, m.solve.n), row: work.join });
    },
  };
}
