import { h } from '../../app/dom';
import { renderFormula } from '../../render/formula';
import { setHidden, setText } from '../../app/dom';
import { LiveFormula } from '../../render/formula';
import type { RoadModel } from './model';
import { stepFormula, stepText } from './solveSteps';
import { systemTables } from './systemTable';

/** The step-through of the Thomas algorithm and the cost note, for the natural and clamped roads. */
export function solveSection() {
  const title = h('h2', {});
  const text = h('p', {});
  const formulas = [new LiveFormula(true), new LiveFormula(true)];
  const tables = systemTables();
  const cost = h('p', { class: 'note' });
  const costFormula = h('div', {});
  const element = h(
    'section',
    { 'aria-label': 'Solving the system' },
    title,
    text,
    h('div', { class: 'step-formulas' }, ...formulas.map((f) => f.element)),
    tables.element,
    cost,
    costFormula,
  );

  let shownStep = -1;
  let shownCost = '';

  return {
    element,
    update(m: RoadModel) {
      const { solve, state } = m;
      const { progress, cost: counts } = m;
      setHidden(element, !solve || !m.progress);
      if (!solve || !progress || !counts) return;
      const step = m.stage.solveStep ?? 2 * solve.n;
      if (shownStep >= 0 && shownStep !== step) revealInPanel(element);
      shownStep = step;
      const n = solve.n;
      setText(title, `Solving for the gradients: step ${step} of ${2 * n}`);
      setText(text, stepText(state, solve, step, progress.row));
      formulas.forEach((formula, k) => formula.set(stepFormula(solve, k, step, progress.row)));
      tables.update(solve, progress);

      // The cost changes only with the number of villages: written and typeset again only then.
      const { unknowns: N, thomas, elimination, inverse } = counts;
      const key = `${N} ${n}`;
      if (key === shownCost) return;
      shownCost = key;
      setText(
        cost,
        `Why not invert the ${N} × ${N} matrix of all 4m coefficients? Inverting it costs about 2N³ operations, and even Gaussian elimination with both right-hand sides about 2N³/3; the Thomas algorithm sweeps once down and once up the ${n} rows: O(m) against O(m³).`,
      );
      renderFormula(
        costFormula,
        `\\underbrace{${count(thomas)}}_{\\text{Thomas, } x \\text{ and } y}\\ \\ll\\ \\underbrace{${count(elimination)}}_{\\text{elimination, } ${N}\\times${N}}\\ <\\ \\underbrace{${count(inverse)}}_{\\text{inverting } ${N}\\times${N}}`,
        true,
      );
    },
  };
}

/**
 * Stepping with a clicker: bring the solve into view in the side panel, when
 * the panel scrolls on its own (wide screens); on a phone the page is left alone.
 */
function revealInPanel(section: HTMLElement): void {
  const panel = section.closest('.panel');
  if (!(panel instanceof HTMLElement) || panel.scrollHeight <= panel.clientHeight + 1) return;
  const top = section.getBoundingClientRect().top - panel.getBoundingClientRect().top;
  if (top < 0 || top > panel.clientHeight * 0.4) panel.scrollTop += top;
}

/** An operation count with thin spaces between thousands, or in powers of ten when huge. */
function count(value: number): string {
  if (value < 1e9) return Math.round(value).toLocaleString('en').replace(/,/g, '\\,');
  const exponent = Math.floor(Math.log10(value));
  return `${(value / 10 ** exponent).toFixed(1)}\\times10^{${exponent}}`;
}
