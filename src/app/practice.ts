/**
 * The practice card of a lesson page: its exercises, one at a time, posed
 * from the seed in the link. A guess is placed with a tap on the figure or
 * typed; numbers are typed; a construction is made on the figure itself.
 * Check says right or wrong with a hint, "Show me" walks the working, "New
 * numbers" draws a new seed. Results are announced politely; progress is kept
 * on this device. The card's parts are practiceCard.ts, its answer fields
 * practiceFields.ts.
 */
import type { ExerciseSpec, Posed, Verdict } from '../kit/exercise';
import { newSeed } from '../kit/exercise';
import type { Point } from '../math';
import { fmt, h, setChildren, setClass, setDisabled, setHidden, setText } from './dom';
import type { FigureMark } from './figureView';
import { exerciseButtons, practiceCard, tallyText } from './practiceCard';
import { answerFields, readNumber } from './practiceFields';
import { recordTotal, recordTry } from './progress';
import type { PracticeLink } from './urlState';

/** What the card needs from the page. */
export interface PracticeHost<S> {
  slug: string;
  defaults: S;
  /** The current state (a construction is checked on it). */
  get(): S;
  /** Opens the exercise's figure: its state, in its scene. */
  open(state: S, scene: string | undefined): void;
  /** Shows the working: the state at step 0, then its steps one by one. */
  walk(state: S, scene: string | undefined): void;
  /** The marks changed: redraw the figures. */
  redraw(): void;
  /** The exercise or its seed changed: write the link. */
  linkChanged(): void;
  /** The card opened or closed (the page makes room for it). */
  toggled(open: boolean): void;
  /**
   * Hides the lesson's own text while a question is open (its tables would
   * give the answer away), and shows it again once it is answered.
   */
  quiet(on: boolean): void;
  /** The title of a figure, to say where to tap. */
  figureTitle(id: string): string;
  /** Can a guess be placed on this figure with a tap (not a figure in space, turned by the finger)? */
  tappable(id: string): boolean;
}

export class Practice<S> {
  readonly element: HTMLElement;
  private readonly list: HTMLElement;
  private readonly prompt: HTMLElement;
  private readonly fields: HTMLElement;
  private readonly result: HTMLElement;
  private readonly tally: HTMLElement;
  private readonly showButton: HTMLButtonElement;
  private inputs: HTMLInputElement[] = [];
  private current: { spec: ExerciseSpec<S>; seed: number; posed: Posed<S> } | null = null;
  private guess: Point | null = null;
  private revealed = false;

  constructor(
    private readonly exercises: readonly ExerciseSpec<S>[],
    private readonly host: PracticeHost<S>,
  ) {
    recordTotal(host.slug, exercises.length);
    const card = practiceCard({
      check: () => this.check(),
      showMe: () => this.showMe(),
      newNumbers: () =>
        this.start(this.current?.spec.id ?? exercises[0].id, newSeed(this.current?.seed ?? 0)),
      close: () => this.close(),
    });
    this.element = card.element;
    this.list = card.list;
    this.prompt = card.prompt;
    this.fields = card.fields;
    this.result = card.result;
    this.tally = card.tally;
    this.showButton = card.showButton;
  }

  get active(): boolean {
    return this.current !== null;
  }

  /** The exercise's part of the link, or null when not practising. */
  link(): PracticeLink | null {
    return this.current ? { id: this.current.spec.id, seed: this.current.seed } : null;
  }

  /**
   * Opens an exercise with a seed (from a link, a button, or New numbers),
   * on its own figure or on the one a link kept (`kept`).
   */
  start(id: string, seed: number, kept?: S): void {
    const spec = this.exercises.find((e) => e.id === id) ?? this.exercises[0];
    const posed = spec.pose(seed, this.host.defaults);
    this.current = { spec, seed, posed };
    this.guess = null;
    this.revealed = false;
    setHidden(this.element, false);
    this.host.toggled(true);
    this.host.open(kept ?? posed.state, posed.scene);
    this.renderList();
    setText(this.prompt, posed.prompt);
    this.renderFields(posed);
    setText(this.result, '');
    setClass(this.result, 'practice-result');
    setDisabled(this.showButton, false);
    // A construction is helped by the lesson's live numbers; a question would be given away.
    this.host.quiet(posed.task.kind !== 'construct');
    this.renderTally();
    this.host.redraw();
    this.host.linkChanged();
  }

  close(): void {
    this.host.quiet(false);
    this.current = null;
    this.guess = null;
    setHidden(this.element, true);
    this.host.toggled(false);
    this.host.redraw();
    this.host.linkChanged();
  }

  /** The marks on a figure: the guess, and after the check the answer. */
  marks(figure: string): FigureMark[] {
    const posed = this.current?.posed;
    const marks: FigureMark[] = (posed?.marks ?? [])
      .filter((mark) => mark.figure === figure)
      .map((mark) => ({ kind: 'target', at: mark.at, label: mark.label }));
    const task = posed?.task;
    if (task?.kind !== 'point' || task.figure !== figure) return marks;
    if (this.guess) marks.push({ kind: 'guess', at: this.guess, label: 'guess' });
    if (this.revealed) marks.push({ kind: 'answer', at: task.answer, label: 'answer' });
    return marks;
  }

  /** A tap on a figure: places the guess if this exercise asks for a point there. */
  tap(figure: string, at: Point): boolean {
    const task = this.current?.posed.task;
    if (task?.kind !== 'point' || task.figure !== figure || this.revealed) return false;
    this.setGuess([at[0], at[1]]);
    this.inputs[0].value = fmt(at[0]);
    this.inputs[1].value = fmt(at[1]);
    return true;
  }

  private setGuess(point: Point | null): void {
    this.guess = point;
    this.host.redraw();
  }

  private renderList(): void {
    setChildren(
      this.list,
      exerciseButtons(this.host.slug, this.exercises, this.current?.spec, (spec) =>
        this.start(spec.id, this.current?.seed ?? 1),
      ),
    );
  }

  private renderFields(posed: Posed<S>): void {
    const task = posed.task;
    const { help, rows } = answerFields(task, this.host, () => this.typedGuess());
    this.inputs = rows.map((row) => row.querySelector('input') as HTMLInputElement);
    setChildren(this.fields, h('p', { class: 'practice-help' }, help), rows);
    if (task.kind === 'point') this.fields.dataset.figure = task.figure;
    else delete this.fields.dataset.figure;
  }

  /** x or y of a guessed point typed: the guess follows, until the answer is shown. */
  private typedGuess(): void {
    if (this.revealed) return;
    const [x, y] = this.inputs.map((e) => readNumber(e.value));
    this.setGuess(Number.isFinite(x) && Number.isFinite(y) ? [x, y] : null);
  }

  private check(): void {
    const current = this.current;
    if (!current) return;
    const task = current.posed.task;
    let verdict: Verdict;
    if (task.kind === 'number') verdict = task.check(this.inputs.map((e) => readNumber(e.value)));
    else if (task.kind === 'point') {
      if (this.revealed) return;
      const [x, y] = this.inputs.map((e) => readNumber(e.value));
      if (!Number.isFinite(x) || !Number.isFinite(y)) {
        this.say({
          correct: false,
          message: 'Place a guess first: tap the figure, or type x and y.',
        });
        return;
      }
      this.guess = [x, y];
      verdict = task.check([x, y]);
      // The guess is final: the construction runs to the answer, and both stay marked.
      this.revealed = true;
      this.host.walk(current.posed.working, current.posed.scene);
    } else verdict = task.check(this.host.get());
    recordTry(this.host.slug, current.spec.id, verdict.correct);
    if (verdict.correct || task.kind === 'point') this.host.quiet(false);
    this.say(verdict);
    this.renderList();
    this.renderTally();
  }

  private say(verdict: Verdict): void {
    // Written even when the words are the same: the status then says the hint again.
    // eslint-disable-next-line no-restricted-syntax
    this.result.textContent = verdict.message;
    setClass(this.result, `practice-result ${verdict.correct ? 'right' : 'wrong'}`);
  }

  private showMe(): void {
    const current = this.current;
    if (!current) return;
    this.host.quiet(false);
    const task = current.posed.task;
    if (task.kind === 'construct') {
      this.host.open(task.solution, current.posed.scene);
      this.say({ correct: true, message: 'This is one way to do it: compare it with yours.' });
      return;
    }
    this.host.walk(current.posed.working, current.posed.scene);
    if (task.kind === 'number') {
      const answer = task.answer.map((v) => fmtAnswer(v)).join(', ');
      setText(this.result, `The working is on the figure, step by step. The answer: ${answer}.`);
    } else {
      this.revealed = true;
      setText(
        this.result,
        `The construction runs to the point (${task.answer.map((v) => fmtAnswer(v)).join(', ')}).`,
      );
      this.host.redraw();
    }
    setClass(this.result, 'practice-result');
  }

  private renderTally(): void {
    setText(this.tally, tallyText(this.host.slug, this.current?.spec));
  }
}

/** An answer as shown: up to four decimals, no trailing zeros, a true minus sign. */
function fmtAnswer(v: number): string {
  return String(Number(v.toFixed(4))).replace('-', '−');
}
