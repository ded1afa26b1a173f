/**
 * An exercise's marks over a figure: the student's guess, the answer, or a
 * target to reach, each with a short label.
 */
import type { Painter } from '../render/painter';
import type { Theme } from '../render/theme';
import type { Point } from './lesson';

/** A point marked over a figure: a guess (a cross), the answer (a ring) or a target (a ring with a dot), with a short label. */
export interface FigureMark {
  kind: 'guess' | 'answer' | 'target';
  at: Point;
  label: string;
}

/** An exercise's marks: the guess as a cross, the answer as a ring, a dashed line from one to the other. */
export function drawMarks(painter: Painter, marks: readonly FigureMark[], theme: Theme): void {
  const guess = marks.find((m) => m.kind === 'guess');
  const answer = marks.find((m) => m.kind === 'answer');
  const size = painter.sizes.handle;
  if (guess && answer)
    painter.segment(guess.at, answer.at, {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [6, 5],
    });
  if (answer)
    painter.ring(answer.at, size * 1.3, { color: theme.ink, width: theme.sizes.line * 1.4 });
  if (guess)
    painter.cross(guess.at, size * 1.2, { color: theme.accent, width: theme.sizes.line * 1.6 });
  for (const mark of marks) painter.labelClear(mark.label, mark.at, []);
}
