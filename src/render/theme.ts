/**
 * Colours and sizes. Projector mode is a theme, not a special case: thick
 * strokes, large labels and handles, and a high-contrast palette that reads
 * from the back of a lecture hall. Series colours follow Okabe & Ito's
 * colour-blind-safe palette.
 */
export interface Sizes {
  /** Main curve stroke (px). */
  curve: number;
  /** Construction lines, polygons. */
  line: number;
  /** Faint helper lines. */
  thin: number;
  /** Radius of a movable point. */
  handle: number;
  /** Radius of a constructed (non-movable) point. */
  point: number;
  /** Label font size (px). */
  label: number;
  /** Small text: axis numbers. */
  small: number;
  /**
   * No text on a figure is set smaller, subscripts included (px): 28 on the
   * projector (read from 15 m), 12 on a screen; none for thumbnails.
   */
  minText?: number;
  /** How much taller a strip of fixed height is drawn (its handles and text are larger on the projector). */
  strip?: number;
}

export interface Theme {
  dark: boolean;
  projector: boolean;
  background: string;
  ink: string;
  muted: string;
  grid: string;
  axis: string;
  curve: string;
  curveFaint: string;
  polygon: string;
  accent: string;
  handleFill: string;
  handleStroke: string;
  focus: string;
  labelHalo: string;
  /**
   * The opacity of a region's fill (a convex hull): stronger on the
   * projector, whose washed-out picture loses a pale tint.
   */
  tint: number;
  /** Colours for series: construction levels, basis functions, methods. */
  palette: readonly string[];
  fontFamily: string;
  sizes: Sizes;
  /**
   * Paper: a stroke in a series colour that sets no dash of its own gets
   * this one, so a grey-scale copy still tells the series apart.
   */
  dashOf?(color: string): number[] | undefined;
}

const FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, "Noto Sans", sans-serif';

const LIGHT = [
  '#0072B2',
  '#D55E00',
  '#009E73',
  '#CC79A7',
  '#E69F00',
  '#56B4E9',
  '#7A5195',
  '#8C6D31',
];
const DARK = [
  '#56B4E9',
  '#FF8F4D',
  '#2BD1A0',
  '#F09ACB',
  '#F5B82E',
  '#8FD3FF',
  '#C39BFF',
  '#D9B56A',
];
const LIGHT_STRONG = [
  '#0050A0',
  '#C04000',
  '#007A55',
  '#A02C80',
  '#B36B00',
  '#1A7FC1',
  '#5A2D91',
  '#6B4F12',
];
const DARK_STRONG = [
  '#6CC6FF',
  '#FF9A5C',
  '#3BF0B5',
  '#FFA8DC',
  '#FFD23F',
  '#A8E0FF',
  '#D3B0FF',
  '#F0CC80',
];

export function makeTheme(dark: boolean, projector: boolean): Theme {
  const sizes: Sizes = projector
    ? {
        curve: 7,
        line: 4.5,
        thin: 4,
        handle: 14,
        point: 9,
        label: 36,
        small: 28,
        minText: 28,
        strip: 2.2,
      }
    : { curve: 3, line: 1.75, thin: 1, handle: 8, point: 5, label: 15, small: 12, minText: 12 };
  if (dark) {
    return {
      dark,
      projector,
      background: projector ? '#000000' : '#12151f',
      ink: projector ? '#ffffff' : '#e8eaf2',
      muted: projector ? '#d0d0d0' : '#9aa3b8',
      grid: projector ? '#2a2a2a' : '#1f2433',
      axis: projector ? '#bbbbbb' : '#5d6680',
      curve: projector ? '#ffffff' : '#f2f4fa',
      curveFaint: projector ? '#777777' : '#4a5168',
      polygon: projector ? '#bbbbbb' : '#7d869e',
      accent: projector ? '#FFD23F' : '#F5B82E',
      handleFill: projector ? '#000000' : '#12151f',
      handleStroke: projector ? '#ffffff' : '#e8eaf2',
      focus: '#FFD23F',
      labelHalo: projector ? '#000000' : '#12151f',
      tint: projector ? 0.3 : 0.16,
      palette: projector ? DARK_STRONG : DARK,
      fontFamily: FONT,
      sizes,
    };
  }
  return {
    dark,
    projector,
    background: '#ffffff',
    ink: projector ? '#000000' : '#1b1f2b',
    muted: projector ? '#333333' : '#5f6677',
    grid: projector ? '#d8d8d8' : '#eceef3',
    axis: projector ? '#555555' : '#a3a9b8',
    curve: projector ? '#000000' : '#1b1f2b',
    curveFaint: projector ? '#7a7a7a' : '#c3c8d4',
    polygon: projector ? '#444444' : '#8a91a3',
    accent: projector ? '#C04000' : '#D55E00',
    handleFill: '#ffffff',
    handleStroke: projector ? '#000000' : '#1b1f2b',
    focus: '#0072B2',
    labelHalo: '#ffffff',
    tint: projector ? 0.35 : 0.13,
    palette: projector ? LIGHT_STRONG : LIGHT,
    fontFamily: FONT,
    sizes,
  };
}

/**
 * Dashes on paper, by palette slot: the curve (ink), slot 0 and the accent
 * (slot 1: P(t), the parameter's marks) stay solid; every other series colour
 * has a pattern of its own.
 */
const PAPER_DASHES: readonly (readonly number[] | undefined)[] = [
  undefined,
  undefined,
  [9, 4],
  [2, 3],
  [12, 3, 2, 3],
  [6, 3],
  [2, 2, 8, 2],
  [14, 4, 2, 4, 2, 4],
];

/**
 * The theme of a handout: light, with black ink and the strong palette, and
 * every series told apart by a dash as well as by colour. Sizes are for a
 * page read in the hand (px at 96 per inch: 13 px labels are 10 pt).
 */
export function makePaperTheme(): Theme {
  const base = makeTheme(false, true);
  const dashes = new Map(
    LIGHT_STRONG.map((colour, i) => [colour.toLowerCase(), PAPER_DASHES[i]] as const),
  );
  return {
    ...base,
    projector: false,
    grid: '#e2e2e2',
    axis: '#555555',
    curveFaint: '#8c8c8c',
    sizes: {
      curve: 2.4,
      line: 1.5,
      thin: 1,
      handle: 5.5,
      point: 3.5,
      label: 13,
      small: 10.5,
      minText: 8,
    },
    dashOf: (colour) => {
      const dash = dashes.get(colour.toLowerCase());
      return dash ? [...dash] : undefined;
    },
  };
}
