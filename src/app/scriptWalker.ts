/**
 * Walks a lesson's script as the clicker does: the next or previous step, and
 * past a scene's last (first) step the next (previous) scene; Home and End;
 * a scene button. A scene the clicker left is found again as it was left.
 * Owns the scene buttons and the step status under the figure.
 */
import { h } from './dom';
import type { AnyLesson } from './lesson';
import type { LessonStore } from './lessonState';
import { StepControl } from './stepControl';

export interface WalkerHost {
  /** Fits every figure to the new scene. */
  fit(): void;
  announce(message: string): void;
  /**
   * Past a scene's last step, does Next first say "Scene done. Next: …"? (A
   * student learning alone is told; the lecturer's clicker goes straight on.)
   */
  pauseAtSceneEnd(): boolean;
}

export class ScriptWalker<S> {
  /** The step buttons and status; absent for a lesson without steps or scenes. */
  readonly steps?: StepControl;
  /** The scene buttons above the panel, or null for a lesson with one scene. */
  readonly sceneGroup: HTMLElement | null;
  private sceneButtons: HTMLButtonElement[] = [];
  /** The state each scene was left in, so the clicker going back finds it as it was. */
  private readonly memory = new Map<number, S>();
  /** The state at which Next said "Scene done": the next press opens the next scene. */
  private doneAt: S | null = null;

  constructor(
    private readonly lesson: AnyLesson,
    private readonly store: LessonStore<S>,
    private readonly host: WalkerHost,
  ) {
    if (lesson.steps || lesson.scenes?.length)
      this.steps = new StepControl((delta) => this.advance(delta, true));
    this.sceneGroup = this.buildSceneGroup();
  }

  /** The step a state is at and its scene's last step. */
  stepOf(state: S): { k: number; count: number } {
    const steps = this.lesson.steps;
    if (!steps) return { k: 0, count: 0 };
    return { k: (state as Record<string, number>)[steps.key], count: steps.count(state) };
  }

  private withStep(state: S, k: number): S {
    const key = this.lesson.steps?.key;
    return key === undefined ? state : { ...state, [key]: k };
  }

  private buildSceneGroup(): HTMLElement | null {
    const scenes = this.lesson.scenes;
    if (!scenes?.length) return null;
    this.sceneButtons = scenes.map((scene, i) =>
      h(
        'button',
        {
          type: 'button',
          'data-scene': scene.id,
          'aria-pressed': String(i === this.store.scene),
          title: `Scene ${i + 1} of ${scenes.length}: opens at its first step`,
          onclick: () => this.openScene(i, 'first', true),
        },
        scene.label,
      ),
    );
    return h(
      'div',
      { class: 'presets', role: 'group', 'aria-label': 'Scenes' },
      h('span', { class: 'presets-title' }, 'Scenes'),
      ...this.sceneButtons,
    );
  }

  private markScene(index: number): void {
    this.sceneButtons.forEach((b, i) => b.setAttribute('aria-pressed', String(i === index)));
  }

  /**
   * Opens scene `index` at its first or last step. A click on its button is an
   * edit (undoable) and sets the scene up afresh; the clicker is not an edit,
   * and finds a scene it left as it was left.
   */
  openScene(index: number, at: 'first' | 'last', fresh: boolean): void {
    const scenes = this.lesson.scenes ?? [];
    const scene = scenes[index];
    if (!scene) return;
    this.memory.set(this.store.scene, this.store.state);
    const kept = fresh ? undefined : this.memory.get(index);
    const base = kept ?? scene.apply(this.store.state);
    const k = at === 'first' ? 0 : this.stepOf(base).count;
    this.store.scene = index;
    this.store.set(this.withStep(base, k), { record: fresh });
    this.markScene(index);
    this.host.fit();
    this.host.announce(`Scene ${index + 1} of ${scenes.length}: ${scene.label}`);
  }

  /** A link is a new starting point of the script: its scene, and no memory of others. */
  restart(scene: number): void {
    this.memory.clear();
    this.store.scene = scene;
    this.markScene(scene);
  }

  /**
   * The clicker: the next (or previous) step, and past the last (first) one
   * the next (previous) scene. A student's Next button (`button`) says
   * "Scene done" first; a clicker's key goes straight on.
   */
  advance(delta: 1 | -1, button = false): void {
    const { k, count } = this.stepOf(this.store.state);
    const next = k + delta;
    if (next >= 0 && next <= count) {
      this.store.set(this.withStep(this.store.state, next), { record: false });
      return;
    }
    const scene = this.store.scene + delta;
    const scenes = this.lesson.scenes ?? [];
    if (scene >= 0 && scene < scenes.length) {
      if (button && delta > 0 && this.doneAt !== this.store.state && this.host.pauseAtSceneEnd()) {
        this.doneAt = this.store.state;
        this.update(this.store.state);
        this.host.announce(`Scene done. Next: ${scenes[scene].label}`);
        return;
      }
      this.doneAt = null;
      this.openScene(scene, delta > 0 ? 'first' : 'last', false);
    } else this.host.announce(delta > 0 ? 'The end of the lesson' : 'The start of the lesson');
  }

  /** Home / End: the first or last step of this scene. */
  stepTo(end: 'first' | 'last'): void {
    const { k, count } = this.stepOf(this.store.state);
    const target = end === 'first' ? 0 : count;
    if (target !== k) this.store.set(this.withStep(this.store.state, target), { record: false });
  }

  /** The step status under the figure: "Step k/n: caption", and whether Back and Next can go on. */
  update(state: S): void {
    if (!this.steps) return;
    const { k, count } = this.stepOf(state);
    const scenes = this.lesson.scenes?.length ?? 0;
    const next = this.lesson.scenes?.[this.store.scene + 1];
    if (this.doneAt !== state) this.doneAt = null;
    const done = next ? `Scene done. Next: ${next.label}.` : '';
    const stepText = (at: S, j: number) =>
      this.lesson.steps
        ? `${count > 0 ? `Step ${j}/${count}: ` : ''}${this.lesson.steps.describe(at, j)}`
        : `Scene ${this.store.scene + 1} of ${scenes}`;
    const text = this.doneAt !== null && next ? done : stepText(state, k);
    // One height for the scene's every step, and for "Scene done" after them.
    this.steps.reserve(`${this.store.scene}/${count}/${window.innerWidth}`, () => [
      done,
      ...Array.from({ length: count + 1 }, (_, j) => stepText(this.withStep(state, j), j)),
    ]);
    this.steps.update(
      text,
      k === 0 && this.store.scene === 0,
      k === count && this.store.scene >= scenes - 1,
      this.doneAt !== null ? 'Next scene ▶' : 'Next ▶',
    );
  }
}
