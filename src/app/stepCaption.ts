/**
 * The projected caption of a lesson page: the scene and step, the step's
 * sentence and formula, in presenter view; and "predict, then show", the
 * question put to the room before the next press. The lecturer's ink is
 * wiped when the step changes.
 */
import { presenting } from './settings';
import type { AnyLesson } from './lesson';
import type { LessonStore } from './lessonState';
import type { Presenter } from './presenter';
import type { ScriptWalker } from './scriptWalker';

export interface CaptionHost<S, M> {
  readonly lesson: AnyLesson;
  readonly store: LessonStore<S>;
  readonly walker: ScriptWalker<S>;
  readonly presenter: Presenter;
  model(state: S): M;
  /** Is the side panel shown beside presenter view? (It changes the caption's width.) */
  panelShown(): boolean;
  announce(message: string): void;
  /** The caption must be written again for the same state. */
  rewrite(): void;
}

export class StepCaption<S, M> {
  /** The room is asked to predict the next step (presenter's Q). */
  private asking = false;
  /** The step the question was asked at: any other step answers it. */
  private askedAt = '';
  /** The step the caption and ink were last shown for. */
  private shownStep = '';

  constructor(private readonly host: CaptionHost<S, M>) {}

  /**
   * Predict, then show: the caption asks the room what the next step will
   * show (nothing of it is drawn yet); the next press reveals it. Pressed
   * again, the question is withdrawn.
   */
  ask(): void {
    const { store, walker, presenter } = this.host;
    const { k, count } = walker.stepOf(store.state);
    if (!this.asking && k >= count) {
      this.host.announce('The last step of this scene: nothing further to predict');
      return;
    }
    this.asking = !this.asking;
    this.askedAt = `${store.scene}/${k}`;
    presenter.captionBox.asking(this.asking);
    this.shownStep = '';
    this.host.rewrite();
  }

  /** The caption of the current step, for presenter view; ink is cleared when the step changes. */
  update(state: S, model: M): void {
    const { lesson, store, walker, presenter } = this.host;
    const steps = lesson.steps;
    const scenes = lesson.scenes ?? [];
    const { k, count } = walker.stepOf(state);
    const key = `${store.scene}/${k}`;
    if (key !== this.shownStep) {
      if (this.shownStep !== '') presenter.clearInk();
      this.shownStep = key;
    }
    if (!presenting()) return;
    const scene = scenes[store.scene];
    const sceneAt = (k: number) =>
      scene
        ? `${scene.label} · ${scenes.length > 1 ? `scene ${store.scene + 1}/${scenes.length}, ` : ''}step ${k}/${count}`
        : '';
    const sceneText = sceneAt(k);
    // One caption height for the whole scene: the figure keeps its size as the clicker steps.
    if (steps)
      presenter.captionBox.reserveFor(
        `${store.scene}/${count}/${window.innerWidth}/${this.host.panelShown()}`,
        count,
        (j) => {
          const at = { ...store.state, [steps.key]: j } as S;
          return {
            scene: sceneAt(j),
            step: steps.describe(at, j),
            formula: steps.formula?.(this.host.model(at), at) ?? null,
          };
        },
      );
    if (this.asking && key !== this.askedAt) {
      this.asking = false;
      presenter.captionBox.asking(false);
    }
    if (this.asking) {
      presenter.captionBox.set(
        sceneText,
        `Predict before the next press: what will step ${k + 1} show, and why?`,
        null,
      );
      return;
    }
    presenter.captionBox.set(
      sceneText,
      steps ? steps.describe(state, k) : '',
      steps?.formula?.(model, state) ?? null,
    );
  }
}
