import { h } from '../../app/dom';
import { texNumber } from '../../render/formula';
import { hoveredSegment } from './figure';
import { joined, live, tex } from '../../render/formulaParts';
import { setHidden, setText } from '../../app/dom';
import { LiveFormula } from '../../render/formula';
import type { RoadModel } from './model';
import { capital, gestures } from '../../kit/gestures';

const LETTERS = ['a', 'b', 'c', 'd'];
const power = (degree: number) => (degree === 0 ? '' : degree === 1 ? '\\,p' : `\\,p^{${degree}}`);

/** The coefficients of one segment: the one under the pointer, else the one the marker is on. */
export function segmentSection() {
  const title = h('h2', {});
  const text = h('p', { class: 'note' });
  const formula = new LiveFormula(true);
  const element = h(
    'section',
    { 'aria-label': 'Segment coefficients' },
    title,
    text,
    formula.element,
  );

  return {
    element,
    update(m: RoadModel, hover: string | null) {
      const shown = m.visible;
      const pieces = shown?.pieces ?? [];
      setHidden(formula.element, !shown || !pieces.length);
      if (!shown || !pieces.length) {
        setText(title, 'Coefficients of a segment');
        setText(
          text,
          shown
            ? 'No segment of this road is drawn yet.'
            : 'Turn off the comparison to read the coefficients of one road.',
        );
        return;
      }
      // While the solve is under way only the last pieces exist, newest first.
      const hovered = hoveredSegment(m, hover);
      const i =
        Number.isInteger(hovered) && hovered >= 0 && hovered < pieces.length
          ? hovered
          : (shown.marker?.piece ?? 0);
      const index = shown.offset + i;
      const coefficients = m.coefficients(i);
      setText(
        title,
        `Segment ${index}: from P${index} to P${(index + 1) % m.state.villages.length}`,
      );
      setText(
        text,
        `${capital(gestures().point)} the road, or move p̄, to choose a segment. Its coefficients, with the local parameter p from 0 to 1:`,
      );
      const names = coefficients
        .map((_, degree) => `${LETTERS[degree]}_{${index}}${power(degree)}`)
        .join(' + ');
      // x(p) = a + b p + c p² + d p³ with the signs in the shape, so a number is never "+ −3".
      const poly = (d: number) =>
        joined(
          coefficients.map((c, degree) => {
            const sign = degree === 0 ? '' : c[d] < 0 ? ' - ' : ' + ';
            return tex`${sign}${live(texNumber(degree === 0 ? c[d] : Math.abs(c[d]), 3))}${power(degree)}`;
          }),
          '',
        );
      formula.set(
        tex`\begin{aligned}P(p) &= ${names}\\ x(p) &= ${poly(0)}\\ y(p) &= ${poly(1)}\end{aligned}`,
      );
    },
  };
}
