import { fitToWidth, refitAll } from '../render/fit';
import type { Theme } from '../render/theme';
import { fmt, h } from './dom';
import { download, figuresToPng, figuresToSvg } from './exportFigure';
import { FigureView } from './figureView';
import type { AnyLesson, DrawInfo, LessonPanel } from './lesson';
import { LessonStore, type Loaded, storageKey } from './lessonState';
import { prefersReducedMotion } from './settings';

/** What the app shell offers a lesson page. */
export interface Shell {
  theme(): Theme;
  notice(message: string): void;
  announce(message: string): void;
}

const isTyping = (target: EventTarget | null) =>
  target instanceof HTMLElement &&
  (target.isContentEditable ||
    target.tagName === 'INPUT' ||
    target.tagName === 'TEXTAREA' ||
    target.tagName === 'SELECT');

/**
 * Hosts one lesson: its figures, the construction controls, its side panel,
 * and the plumbing that keeps state, URL, local storage and undo in step.
 */
export class LessonPage<S> {
  readonly element: HTMLElement;
  readonly store: LessonStore<S>;
  readonly figures: FigureView<S>[];
  private readonly panel: LessonPanel<S>;
  private hover: string | null = null;
  private frame = 0;
  private urlTimer = 0;
  private playing: { last: number; timer: number } | null = null;
  private readonly unsubscribe: () => void;
  private readonly panelResize: ResizeObserver;
  private readonly controls: {
    slider?: HTMLInputElement;
    number?: HTMLInputElement;
    back?: HTMLButtonElement;
    forward?: HTMLButtonElement;
    status?: HTMLElement;
    play?: HTMLButtonElement;
    undo: HTMLButtonElement;
    redo: HTMLButtonElement;
  };

  constructor(
    readonly lesson: AnyLesson,
    loaded: Loaded<S>,
    private readonly shell: Shell,
  ) {
    this.store = new LessonStore<S>(lesson, loaded.state);
    const host = {
      get: () => this.store.state,
      set: (next: S, options: { coalesce?: string; windowMs?: number; record?: boolean }) =>
        this.store.set(next, options),
      theme: () => shell.theme(),
      info: () => this.info(),
      setHover: (id: string | null) => this.setHover(id),
      announce: (text: string) => shell.announce(text),
      requestDraw: () => this.requestDraw(),
      settle: () => this.writeUrl(),
    };
    this.figures = lesson.figures.map((spec) => new FigureView<S>(spec, host));
    this.panel = lesson.panel({
      get: () => this.store.state,
      set: (next, options) => this.store.set(next, options),
      notice: (message) => shell.notice(message),
      setHover: (id) => this.setHover(id),
      theme: () => shell.theme(),
    });

    const undo = h(
      'button',
      { type: 'button', title: 'Undo (Ctrl+Z)', onclick: () => this.store.undo() },
      'Undo',
    );
    const redo = h(
      'button',
      { type: 'button', title: 'Redo (Ctrl+Shift+Z)', onclick: () => this.store.redo() },
      'Redo',
    );
    this.controls = { undo, redo };
    const toolbar = h(
      'div',
      { class: 'lesson-tools', role: 'toolbar', 'aria-label': 'Lesson tools' },
      undo,
      redo,
      h(
        'button',
        { type: 'button', title: 'Fit the view to the figure (0)', onclick: () => this.fit() },
        'Fit view',
      ),
      h('button', { type: 'button', onclick: () => void this.copyLink() }, 'Copy link'),
      h(
        'button',
        {
          type: 'button',
          title: 'Save the figure as a PNG image',
          onclick: () => void this.exportPng(),
        },
        'PNG',
      ),
      h(
        'button',
        {
          type: 'button',
          title: 'Save the figure as an SVG drawing',
          onclick: () => this.exportSvg(),
        },
        'SVG',
      ),
    );

    const figureBox = h(
      'div',
      { class: `figures layout-${lesson.layout ?? 'row'}` },
      ...this.figures.map((f) => f.element),
    );
    const stage = h(
      'section',
      { class: 'stage', 'aria-label': 'Figure' },
      figureBox,
      this.buildControls(),
    );
    const presets = lesson.presets?.length
      ? h(
          'div',
          { class: 'presets', role: 'group', 'aria-label': 'Presets' },
          h('span', { class: 'presets-title' }, 'Presets'),
          ...lesson.presets.map((preset) =>
            h(
              'button',
              {
                type: 'button',
                'data-preset': preset.id,
                onclick: () => {
                  this.store.set(preset.apply(this.store.state));
                  this.fit();
                },
              },
              preset.label,
            ),
          ),
        )
      : null;
    const aside = h(
      'aside',
      { class: 'panel', 'aria-label': 'Explanation' },
      presets,
      this.panel.element,
    );
    this.element = h(
      'div',
      { class: 'lesson-page', 'data-lesson': lesson.slug },
      h('div', { class: 'lesson-head' }, h('h1', {}, lesson.title), toolbar),
      h('div', { class: 'lesson-body' }, stage, aside),
    );

    // Formulas fit the panel's width; its height follows its content, so only
    // a change of width may refit them (else fitting could feed itself).
    let panelWidth = -1;
    this.panelResize = new ResizeObserver(([entry]) => {
      const width = Math.round(entry.contentRect.width);
      if (width !== panelWidth) {
        panelWidth = width;
        this.refresh();
      }
    });
    this.panelResize.observe(aside);
    for (const issue of loaded.issues) shell.notice(`Ignored from the link: ${issue}.`);
    this.unsubscribe = this.store.subscribe(() => {
      this.requestDraw();
      this.scheduleUrl();
    });
    this.requestDraw();
    this.scheduleUrl();
  }

  private buildControls(): HTMLElement {
    const lesson = this.lesson;
    const parts: HTMLElement[] = [];
    const parameter = lesson.parameter;
    if (parameter) {
      const slider = h('input', {
        type: 'range',
        min: parameter.min,
        max: parameter.max,
        step: parameter.step,
        'aria-label': parameter.label,
        class: 'param-slider',
      });
      const number = h('input', {
        type: 'number',
        min: parameter.min,
        max: parameter.max,
        step: parameter.step,
        'aria-label': `${parameter.label} value`,
        class: 'param-number',
      });
      const setParameter = (value: number, coalesce: string) => {
        if (!Number.isFinite(value)) return;
        const clamped = Math.min(parameter.max, Math.max(parameter.min, value));
        this.store.set(
          { ...this.store.state, [parameter.key]: clamped },
          { coalesce, windowMs: 1500 },
        );
      };
      slider.addEventListener('input', () => setParameter(Number(slider.value), 'slider'));
      number.addEventListener('change', () => setParameter(Number(number.value), 'number'));
      this.controls.slider = slider;
      this.controls.number = number;
      const play = h(
        'button',
        {
          type: 'button',
          class: 'play',
          'aria-label': 'Play',
          title: 'Play / pause (K)',
          onclick: () => this.togglePlay(),
        },
        '▶',
      );
      this.controls.play = play;
      parts.push(
        h(
          'div',
          { class: 'param' },
          h('span', { class: 'param-name', 'aria-hidden': 'true' }, parameter.label),
          slider,
          number,
          play,
        ),
      );
    }
    if (lesson.steps) {
      const back = h(
        'button',
        { type: 'button', onclick: () => this.step(-1), title: 'Step back (PageUp, ←)' },
        '◀ Step back',
      );
      const forward = h(
        'button',
        { type: 'button', onclick: () => this.step(1), title: 'Step forward (PageDown, →, space)' },
        'Step forward ▶',
      );
      const status = h('span', { class: 'step-status', 'aria-live': 'polite' });
      this.controls.back = back;
      this.controls.forward = forward;
      this.controls.status = status;
      parts.push(h('div', { class: 'steps' }, back, status, forward));
    }
    return h('div', { class: 'controls' }, ...parts);
  }

  info(): DrawInfo {
    return { hover: this.hover, thumbnail: false };
  }

  /** Redraws after a change of display settings (projector mode changes every size). */
  refresh(): void {
    refitAll(this.element);
    this.requestDraw();
  }

  setHover(id: string | null): void {
    if (id === this.hover) return;
    this.hover = id;
    this.requestDraw();
  }

  requestDraw(): void {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.drawNow();
    });
  }

  /** Draws everything for the current state at once (also used before export). */
  drawNow(): void {
    const state = this.store.state;
    for (const figure of this.figures) figure.draw(state);
    this.panel.update(state, this.info());
    fitToWidth(this.panel.element);
    this.syncControls(state);
  }

  private syncControls(state: S): void {
    const c = this.controls;
    c.undo.disabled = !this.store.canUndo;
    c.redo.disabled = !this.store.canRedo;
    const parameter = this.lesson.parameter;
    if (parameter && c.slider && c.number) {
      const value = (state as Record<string, number>)[parameter.key];
      if (Number(c.slider.value) !== value) c.slider.value = String(value);
      c.slider.setAttribute('aria-valuetext', `${parameter.label} = ${fmt(value, 3)}`);
      if (document.activeElement !== c.number) c.number.value = fmt(value, 3);
    }
    const steps = this.lesson.steps;
    if (steps && c.back && c.forward && c.status) {
      const k = (state as Record<string, number>)[steps.key];
      const count = steps.count(state);
      // A lesson whose current figure has nothing to step hides the buttons.
      if (c.back.parentElement) c.back.parentElement.style.display = count === 0 ? 'none' : '';
      c.back.disabled = k <= 0;
      c.forward.disabled = k >= count;
      c.status.textContent = steps.describe(state, k);
    }
  }

  private scheduleUrl(): void {
    window.clearTimeout(this.urlTimer);
    this.urlTimer = window.setTimeout(() => this.writeUrl(), 100);
  }

  /** The shareable link of the current state. */
  link(): string {
    return `#/${this.lesson.slug}?${this.store.query}`;
  }

  writeUrl(): void {
    window.clearTimeout(this.urlTimer);
    const hash = this.link();
    if (location.hash !== hash) history.replaceState(history.state, '', hash);
    this.remember();
  }

  /** Keeps the state on this device, for the next visit without a link. */
  private remember(): void {
    try {
      localStorage.setItem(storageKey(this.lesson.slug), this.store.query);
    } catch {
      // Storage unavailable: the link still carries the state.
    }
  }

  /** Applies a state typed into the address bar or reached by back/forward. */
  applyQuery(loaded: Loaded<S>): void {
    for (const issue of loaded.issues) this.shell.notice(`Ignored from the link: ${issue}.`);
    if (this.store.query === new LessonStore<S>(this.lesson, loaded.state).query) {
      // Nothing changed, but the address bar must show the state in force.
      if (loaded.issues.length) this.writeUrl();
      return;
    }
    this.store.set(loaded.state);
  }

  step(delta: number): void {
    const steps = this.lesson.steps;
    const state = this.store.state as Record<string, number>;
    if (steps) {
      const count = steps.count(this.store.state);
      const k = Math.min(count, Math.max(0, state[steps.key] + delta));
      if (k !== state[steps.key])
        this.store.set({ ...this.store.state, [steps.key]: k }, { coalesce: 'step', windowMs: 0 });
      return;
    }
    const parameter = this.lesson.parameter;
    if (parameter) {
      const span = parameter.max - parameter.min;
      const v = Math.min(
        parameter.max,
        Math.max(parameter.min, state[parameter.key] + (delta * span) / 20),
      );
      this.store.set(
        { ...this.store.state, [parameter.key]: Number(v.toPrecision(12)) },
        { coalesce: 'step-parameter', windowMs: 1500 },
      );
    }
  }

  stepTo(end: 'first' | 'last'): void {
    const steps = this.lesson.steps;
    if (!steps) return;
    const k = end === 'first' ? 0 : steps.count(this.store.state);
    this.store.set({ ...this.store.state, [steps.key]: k });
  }

  fit(): void {
    for (const figure of this.figures) figure.fit();
  }

  zoom(factor: number): void {
    this.figures.find((f) => f.spec.kind === 'geometry')?.zoom(null, factor);
  }

  togglePlay(): void {
    if (this.playing) this.stopPlay();
    else this.startPlay();
  }

  private startPlay(): void {
    const parameter = this.lesson.parameter;
    if (!parameter || !this.controls.play) return;
    const span = parameter.max - parameter.min;
    const reduced = prefersReducedMotion();
    this.controls.play.textContent = '❚❚';
    this.controls.play.setAttribute('aria-label', 'Pause');
    const advance = (amount: number) => {
      const state = this.store.state as Record<string, number>;
      let v = state[parameter.key] + amount;
      if (v > parameter.max + 1e-12) v = parameter.min;
      this.store.set(
        {
          ...this.store.state,
          [parameter.key]: Math.min(parameter.max, Number(v.toPrecision(12))),
        },
        { record: false },
      );
    };
    if (reduced) {
      // No continuous motion: one calm jump a second.
      this.playing = { last: 0, timer: window.setInterval(() => advance(span / 10), 1000) };
      return;
    }
    this.playing = { last: performance.now(), timer: 0 };
    const tick = (now: number) => {
      if (!this.playing) return;
      const dt = Math.min(0.1, (now - this.playing.last) / 1000);
      this.playing.last = now;
      advance((dt * span) / 5);
      this.playing.timer = requestAnimationFrame(tick);
    };
    this.playing.timer = requestAnimationFrame(tick);
  }

  private stopPlay(): void {
    if (!this.playing) return;
    cancelAnimationFrame(this.playing.timer);
    window.clearInterval(this.playing.timer);
    this.playing = null;
    if (this.controls.play) {
      this.controls.play.textContent = '▶';
      this.controls.play.setAttribute('aria-label', 'Play');
    }
  }

  async copyLink(): Promise<void> {
    this.writeUrl();
    const url = location.href;
    try {
      await navigator.clipboard.writeText(url);
      this.shell.notice('Link copied. It opens this lesson exactly as it is now.');
    } catch {
      this.shell.notice(`Copy this link: ${url}`);
    }
  }

  async exportPng(): Promise<void> {
    this.drawNow();
    const blob = await figuresToPng(this.figures, this.shell.theme().background);
    download(blob, `spline-lab-${this.lesson.slug}.png`);
  }

  exportSvg(): void {
    const svg = figuresToSvg(this.figures, this.store.state, this.shell.theme(), this.info());
    download(new Blob([svg], { type: 'image/svg+xml' }), `spline-lab-${this.lesson.slug}.svg`);
  }

  /** Page-level keys; returns true when the key was used. */
  handleKey(e: KeyboardEvent): boolean {
    const mod = e.ctrlKey || e.metaKey;
    if (mod && (e.key === 'z' || e.key === 'Z')) {
      if (e.shiftKey) this.store.redo();
      else this.store.undo();
      return true;
    }
    if (mod && (e.key === 'y' || e.key === 'Y')) {
      this.store.redo();
      return true;
    }
    // A presentation clicker sends PageDown/PageUp: they step the construction
    // even when the t slider has focus.
    const clicker = e.key === 'PageDown' || e.key === 'PageUp';
    const onSlider = e.target instanceof HTMLInputElement && e.target.type === 'range';
    if (mod || e.altKey || (isTyping(e.target) && !(clicker && onSlider))) return false;
    const onControl =
      e.target instanceof HTMLElement &&
      (e.target.tagName === 'BUTTON' || e.target.classList.contains('handle-proxy'));
    switch (e.key) {
      case 'PageDown':
      case 'ArrowRight':
      case 'ArrowDown':
        if (onControl && e.key !== 'PageDown') return false;
        this.step(1);
        return true;
      case ' ':
        if (onControl) return false;
        this.step(1);
        return true;
      case 'PageUp':
      case 'ArrowLeft':
      case 'ArrowUp':
        if (onControl && e.key !== 'PageUp') return false;
        this.step(-1);
        return true;
      case 'Home':
        this.stepTo('first');
        return true;
      case 'End':
        this.stepTo('last');
        return true;
      case 'k':
      case 'K':
        this.togglePlay();
        return true;
      case '0':
        this.fit();
        return true;
      case '+':
      case '=':
        this.zoom(1.25);
        return true;
      case '-':
        this.zoom(0.8);
        return true;
      default:
        return false;
    }
  }

  destroy(): void {
    this.stopPlay();
    // By now the address bar may already show another page: only remember.
    window.clearTimeout(this.urlTimer);
    this.remember();
    this.unsubscribe();
    this.panelResize.disconnect();
    cancelAnimationFrame(this.frame);
    for (const figure of this.figures) figure.destroy();
    this.panel.destroy?.();
  }
}
