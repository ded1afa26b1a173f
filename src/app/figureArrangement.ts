/**
 * The figures' arrangement on the page: the lesson's layout, or in presenter
 * view its tall layout for a scene whose subject that draws larger (see
 * tallLayout.ts). Chosen once a scene, a view and a size of the figures'
 * box, so a figure keeps its size through a scene's steps; never on a frame
 * of a drag (the box's size is read by a ResizeObserver, not while drawing).
 */
import type { FigureSpec, LayoutNode } from './lesson';
import { buildLayout, showFigures } from './layout';
import { layoutFor } from './tallLayout';
import type { Theme } from '../render/theme';

interface Arranged<S, M> {
  readonly element: HTMLElement;
  readonly spec: FigureSpec<S, M>;
}

type Layout = 'row' | 'column' | LayoutNode | undefined;

export class FigureArrangement<S, M> {
  /** The root of the built layout, inside `box` (the presenter's ink and laser stand beside it). */
  private root: HTMLElement;
  private layout: Layout;
  /** What the arrangement was chosen for: the view, the scene and the box's size. */
  private chosenFor = '';
  private shownKey: string | null = null;
  private area = { width: 0, height: 0 };
  private readonly observer: ResizeObserver;

  constructor(
    private readonly lesson: {
      readonly layout?: Layout;
      readonly tallLayout?: LayoutNode;
      readonly figures: readonly FigureSpec<S, M>[];
    },
    private readonly figures: readonly Arranged<S, M>[],
    /** The figures' box. */
    readonly box: HTMLElement,
    /** The box changed size: a frame must run to arrange the figures again. */
    resized: () => void,
  ) {
    this.layout = lesson.layout;
    this.root = this.build(this.layout);
    box.append(this.root);
    this.observer = new ResizeObserver(([entry]) => {
      const width = Math.round(entry.contentRect.width);
      const height = Math.round(entry.contentRect.height);
      if (width === this.area.width && height === this.area.height) return;
      this.area = { width, height };
      if (lesson.tallLayout) resized();
    });
    this.observer.observe(box);
  }

  disconnect(): void {
    this.observer.disconnect();
  }

  /**
   * Shows the figures the scene declares (`ids`, null for all), arranged for
   * `scene` in this view. `model` is read only when the arrangement is chosen.
   */
  arrange(
    ids: readonly string[] | null,
    presenting: boolean,
    scene: number,
    model: () => M,
    theme: () => Theme,
  ): void {
    const tall = this.lesson.tallLayout;
    const shownKey = ids === null ? '' : ids.join(',');
    if (tall) {
      const key = `${presenting}|${scene}|${shownKey}|${this.area.width}x${this.area.height}`;
      if (key !== this.chosenFor) {
        this.chosenFor = key;
        const layout = presenting ? this.choose(ids, model(), theme()) : this.lesson.layout;
        if (layout !== this.layout) {
          this.layout = layout;
          const root = this.build(layout);
          this.root.replaceWith(root);
          this.root = root;
          this.shownKey = null;
        }
      }
    }
    if (shownKey === this.shownKey) return;
    this.shownKey = shownKey;
    showFigures(this.box, this.figures, ids);
  }

  private choose(ids: readonly string[] | null, model: M, theme: Theme): Layout {
    const shown = this.lesson.figures.filter((f) => !ids || ids.includes(f.id));
    return layoutFor(this.lesson, shown, model, this.area, theme);
  }

  /** The layout's boxes round the figures, each figure's share its own weight unless the layout gives one. */
  private build(layout: Layout): HTMLElement {
    // A strip keeps its fixed height (figureSize.ts: flex 0 0 its height).
    for (const { element, spec } of this.figures)
      if (!spec.height) element.style.flexGrow = String(spec.weight ?? 1);
    return buildLayout(layout, new Map(this.figures.map((f) => [f.spec.id, f.element])));
  }
}
