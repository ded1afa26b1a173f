/**
 * What the browser test of a lesson's practice needs for each exercise: a
 * seed, what the prompt must say for it (the numbers the seed poses, so the
 * data cannot drift from the app), and the answer worked out independently of
 * the app (by hand, or with a few lines of plain arithmetic in the data file,
 * never by importing src/).
 */
export type Answer =
  /** A point kind: the answer in the figure's coordinates. */
  | { point: readonly [number, number] }
  /** A number kind: the numbers, in field order. */
  | { numbers: readonly number[]; wrong: readonly number[] }
  /** A construct kind: drag these handles to these figure coordinates, in order. */
  | { moves: readonly { figure: string; handle: string; to: readonly [number, number] }[] };

export interface PracticeCase {
  /** The exercise's id (`ex=<id>` in the link). */
  id: string;
  seed: number;
  /** Texts the prompt contains for this seed (its numbers, as written on screen). */
  prompt: readonly string[];
  answer: Answer;
}
