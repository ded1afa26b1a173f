/**
 * The handout of a lesson (`#/<slug>/handout?<lesson link>&handout.…`): its
 * options, a preview of its pages exactly as they print, and the actions that
 * print them (the browser's own dialog, so "save as PDF" too) or save each
 * frame as an SVG in a zip. Everything is made here, offline.
 */
import { h, setText } from '../dom';
import type { AnyLesson } from '../lesson';
import type { Loaded } from '../lessonState';
import type { LessonMeta } from '../meta';
import { makePaperTheme } from '../../render/theme';
import { download } from '../exportFigure';
import { pageGeometry, rowsPerPage, tableRows, PX_PER_MM } from './geometry';
import { frameSvg } from './frameSvg';
import {
  type FramePlan,
  type HandoutOptions,
  type Item,
  type PerPage,
  paginate,
  planItems,
  tablesOf,
  writeOptions,
} from './plan';
import { buildSheets, fitFrameText } from './sheets';

/** KaTeX's faces a formula may use: a face loads only when first laid out, which would be after it was measured. */
const KATEX_FACES = [
  '400 1em KaTeX_Main',
  '700 1em KaTeX_Main',
  'italic 400 1em KaTeX_Main',
  'italic 400 1em KaTeX_Math',
  'italic 700 1em KaTeX_Math',
  '400 1em KaTeX_Size1',
  '400 1em KaTeX_Size2',
  '400 1em KaTeX_Size3',
  '400 1em KaTeX_Size4',
  '400 1em KaTeX_AMS',
  '400 1em KaTeX_SansSerif',
];

let fontsLoaded: Promise<unknown> | null = null;
function formulaFonts(): Promise<unknown> {
  fontsLoaded ??= Promise.all(
    KATEX_FACES.map((face) => document.fonts.load(face).catch(() => [])),
  ).then(() => document.fonts.ready);
  return fontsLoaded;
}

export interface HandoutHost {
  notice(message: string): void;
  /** Writes the handout's link (options changed) without a new history entry. */
  replaceLink(hash: string): void;
}

export class HandoutPage {
  readonly element: HTMLElement;
  private readonly pages = h('div', { class: 'handout-pages' });
  private readonly status = h('p', { class: 'handout-status', role: 'status' });
  private readonly pageStyle = h('style', {});
  private frames: FramePlan[][] = [];
  private builds = 0;

  constructor(
    private readonly meta: LessonMeta,
    private readonly lesson: AnyLesson,
    private readonly loaded: Loaded<unknown>,
    /** The lesson's own link query (its state and views) as shown. */
    private readonly lessonQuery: string,
    private options: HandoutOptions,
    private readonly host: HandoutHost,
  ) {
    this.element = h(
      'div',
      { class: 'handout' },
      this.pageStyle,
      this.controls(),
      this.status,
      this.pages,
    );
    this.build();
  }

  /** The link to the lesson as shown (what the title block prints). */
  get lessonLink(): string {
    const base = `${location.origin}${location.pathname}`;
    return `${base}#/${this.meta.slug}${this.lessonQuery ? `?${this.lessonQuery}` : ''}`;
  }

  private controls(): HTMLElement {
    const scenes = this.lesson.scenes ?? [];
    const chosen = (id: string) =>
      this.options.scenes.length === 0 || this.options.scenes.includes(id);
    const sceneBoxes = scenes.map((scene) =>
      h('input', { type: 'checkbox', value: scene.id, checked: chosen(scene.id) }),
    );
    const radios = <K extends keyof HandoutOptions>(
      key: K,
      legend: string,
      choices: readonly [HandoutOptions[K], string][],
    ) =>
      h(
        'fieldset',
        { class: 'handout-choice' },
        h('legend', {}, legend),
        choices.map(([value, label]) =>
          h(
            'label',
            {},
            h('input', {
              type: 'radio',
              name: `handout-${key}`,
              value: String(value),
              checked: this.options[key] === value,
              onchange: () => this.change({ [key]: value } as Partial<HandoutOptions>),
            }),
            label,
          ),
        ),
      );
    const onScenes = () => {
      const ids = sceneBoxes.filter((b) => b.checked).map((b) => b.value);
      if (ids.length === 0) {
        this.host.notice('A handout needs at least one scene: the last one stays chosen.');
        const keep = this.options.scenes[0] ?? scenes[0]?.id;
        sceneBoxes.forEach((b) => (b.checked = b.value === keep));
        this.change({ scenes: keep ? [keep] : [] });
        return;
      }
      this.change({ scenes: ids.length === scenes.length ? [] : ids });
    };
    sceneBoxes.forEach((b) => b.addEventListener('change', onScenes));
    return h(
      'form',
      {
        class: 'handout-controls',
        'aria-label': 'Handout options',
        onsubmit: (e: Event) => e.preventDefault(),
      },
      h('h1', {}, `Handout: ${this.meta.title}`),
      h(
        'fieldset',
        { class: 'handout-scenes' },
        h('legend', {}, 'Scenes'),
        scenes.map((scene, i) => h('label', {}, sceneBoxes[i], scene.label)),
      ),
      radios('steps', 'Steps', [
        ['all', 'Every step'],
        ['last', 'Each scene’s last step'],
      ]),
      radios('perPage', 'Frames a page', [
        [1, '1'],
        [2, '2'],
        [4, '4'],
        [6, '6'],
      ] as [PerPage, string][]),
      radios('paper', 'Paper', [
        ['a4', 'A4'],
        ['letter', 'Letter'],
      ]),
      radios('values', 'Points and parameter', [
        ['now', 'As on screen now'],
        ['own', 'Each scene’s own'],
      ]),
      h(
        'div',
        { class: 'handout-actions' },
        h(
          'button',
          { type: 'button', class: 'primary', onclick: () => void this.print() },
          'Print or save as PDF…',
        ),
        h('button', { type: 'button', onclick: () => void this.saveZip() }, 'Frames as SVG (.zip)'),
        h(
          'a',
          { href: `#/${this.meta.slug}${this.lessonQuery ? `?${this.lessonQuery}` : ''}` },
          'Back to the lesson',
        ),
      ),
    );
  }

  private change(patch: Partial<HandoutOptions>): void {
    this.options = { ...this.options, ...patch };
    const handout = writeOptions(this.options);
    const query = [this.lessonQuery, handout].filter((q) => q !== '').join('&');
    this.host.replaceLink(`#/${this.meta.slug}/handout${query ? `?${query}` : ''}`);
    this.build();
  }

  /** Plans, paginates and draws every page (the bench times this). */
  build(): void {
    const started = performance.now();
    const geometry = pageGeometry(this.options.paper, this.options.perPage);
    this.frames = planItems(this.lesson, this.loaded.state, this.loaded.scene, this.options);
    const items: Item[] = this.frames.flatMap((scene) =>
      scene.length === 0
        ? []
        : [...scene, ...tablesOf(this.lesson, scene[scene.length - 1], rowsPerPage(geometry))],
    );
    const pages = paginate(items, this.options.perPage, (table) =>
      tableRows(geometry, table.table.rows.length),
    );
    performance.measure('handout-plan', { start: started });
    const drawing = performance.now();
    const sheets = buildSheets(pages, {
      meta: this.meta,
      lesson: this.lesson,
      geometry,
      views: this.loaded.views,
      link: this.lessonLink,
      date: new Date(),
    });
    this.pages.replaceChildren(...sheets);
    performance.measure('handout-draw', { start: drawing });
    // Our own constant text: the paper's size for the print dialog.
    setText(this.pageStyle, `@page { size: ${geometry.paper.css}; margin: 0; }`);
    const count = this.frames.reduce((n, s) => n + s.length, 0);
    setText(
      this.status,
      `${count} frame${count === 1 ? '' : 's'} on ${pages.length} page${pages.length === 1 ? '' : 's'} (${this.options.paper === 'a4' ? 'A4' : 'Letter'}, ${this.options.perPage} a page).`,
    );
    this.element.dataset.pages = String(pages.length);
    this.element.dataset.frames = String(count);
    this.element.dataset.ready = 'false';
    const built = ++this.builds;
    // Formulas are measured in their own fonts, all loaded before the first measure.
    void formulaFonts().then(() =>
      requestAnimationFrame(() => {
        if (built !== this.builds) return;
        const fitting = performance.now();
        fitFrameText(this.pages);
        performance.measure('handout-fit', { start: fitting });
        this.element.dataset.ready = 'true';
        performance.measure('handout-build', { start: started });
      }),
    );
  }

  private async print(): Promise<void> {
    await document.fonts.ready;
    window.print();
  }

  /** Every frame as its own SVG, named by scene and step, in one zip. */
  private async saveZip(): Promise<void> {
    const { zipSync, strToU8 } = await import('fflate');
    const geometry = pageGeometry(this.options.paper, 1);
    const theme = makePaperTheme();
    const files: Record<string, Uint8Array> = {};
    for (const scene of this.frames)
      for (const frame of scene) {
        const name = `${String(frame.scene.index + 1).padStart(2, '0')}-${frame.scene.id}-step-${String(frame.step).padStart(2, '0')}.svg`;
        files[name] = strToU8(
          frameSvg(
            this.lesson,
            frame.state,
            frame.figures,
            geometry.figure.width * PX_PER_MM,
            geometry.figure.height * PX_PER_MM,
            theme,
            this.loaded.views,
          ),
        );
      }
    const zip = zipSync(files, { level: 6 });
    download(new Blob([zip], { type: 'application/zip' }), `${this.meta.slug}-handout.zip`);
  }
}
