import type { DrawingSurface } from './surface';

interface Style {
  strokeStyle: string;
  fillStyle: string;
  lineWidth: number;
  lineCap: CanvasLineCap;
  lineJoin: CanvasLineJoin;
  font: string;
  textAlign: CanvasTextAlign;
  textBaseline: CanvasTextBaseline;
  globalAlpha: number;
  dash: number[];
  /** The id of the clip path in force, if any. */
  clip?: string;
}

export function escapeXml(text: string): string {
  return text.replace(/[<>&"']/g, (c) =>
    c === '<' ? '&lt;' : c === '>' ? '&gt;' : c === '&' ? '&amp;' : c === '"' ? '&quot;' : '&apos;',
  );
}

const round = (v: number) => Math.round(v * 100) / 100;

/**
 * Records drawing calls and writes them out as SVG elements: vector export of
 * exactly what the canvas shows, and a recording context for tests
 * (`elements` lists what was drawn).
 */
export class SvgContext implements DrawingSurface {
  private style: Style = {
    strokeStyle: '#000',
    fillStyle: '#000',
    lineWidth: 1,
    lineCap: 'butt',
    lineJoin: 'miter',
    font: '10px sans-serif',
    textAlign: 'start',
    textBaseline: 'alphabetic',
    globalAlpha: 1,
    dash: [],
  };
  private stack: Style[] = [];
  /** Clip paths made so far (their ids are numbered). */
  private clips = 0;
  private path: string[] = [];
  /** The SVG elements drawn so far, in order. */
  readonly elements: string[] = [];
  /** Every text drawn, in order: handy for tests. */
  readonly texts: string[] = [];

  get strokeStyle() {
    return this.style.strokeStyle;
  }
  set strokeStyle(v: string | CanvasGradient | CanvasPattern) {
    this.style.strokeStyle = String(v);
  }
  get fillStyle() {
    return this.style.fillStyle;
  }
  set fillStyle(v: string | CanvasGradient | CanvasPattern) {
    this.style.fillStyle = String(v);
  }
  get lineWidth() {
    return this.style.lineWidth;
  }
  set lineWidth(v: number) {
    this.style.lineWidth = v;
  }
  get lineCap() {
    return this.style.lineCap;
  }
  set lineCap(v: CanvasLineCap) {
    this.style.lineCap = v;
  }
  get lineJoin() {
    return this.style.lineJoin;
  }
  set lineJoin(v: CanvasLineJoin) {
    this.style.lineJoin = v;
  }
  get font() {
    return this.style.font;
  }
  set font(v: string) {
    this.style.font = v;
  }
  get textAlign() {
    return this.style.textAlign;
  }
  set textAlign(v: CanvasTextAlign) {
    this.style.textAlign = v;
  }
  get textBaseline() {
    return this.style.textBaseline;
  }
  set textBaseline(v: CanvasTextBaseline) {
    this.style.textBaseline = v;
  }
  get globalAlpha() {
    return this.style.globalAlpha;
  }
  set globalAlpha(v: number) {
    this.style.globalAlpha = v;
  }

  save(): void {
    this.stack.push({ ...this.style, dash: [...this.style.dash] });
  }
  restore(): void {
    const s = this.stack.pop();
    if (s) this.style = s;
  }
  setLineDash(segments: number[]): void {
    this.style.dash = [...segments];
  }
  beginPath(): void {
    this.path = [];
  }
  moveTo(x: number, y: number): void {
    this.path.push(`M${round(x)} ${round(y)}`);
  }
  lineTo(x: number, y: number): void {
    this.path.push(`L${round(x)} ${round(y)}`);
  }
  bezierCurveTo(c1x: number, c1y: number, c2x: number, c2y: number, x: number, y: number): void {
    this.path.push(
      `C${round(c1x)} ${round(c1y)} ${round(c2x)} ${round(c2y)} ${round(x)} ${round(y)}`,
    );
  }
  quadraticCurveTo(cx: number, cy: number, x: number, y: number): void {
    this.path.push(`Q${round(cx)} ${round(cy)} ${round(x)} ${round(y)}`);
  }
  arc(x: number, y: number, r: number, start: number, end: number, anticlockwise = false): void {
    const sweep = anticlockwise ? start - end : end - start;
    const sx = x + r * Math.cos(start);
    const sy = y + r * Math.sin(start);
    this.path.push(this.path.length ? `L${round(sx)} ${round(sy)}` : `M${round(sx)} ${round(sy)}`);
    if (Math.abs(sweep) >= 2 * Math.PI - 1e-9) {
      // A full circle: two half arcs, since one SVG arc cannot end where it starts.
      const mx = x - r * Math.cos(start);
      const my = y - r * Math.sin(start);
      const f = anticlockwise ? 0 : 1;
      this.path.push(`A${round(r)} ${round(r)} 0 1 ${f} ${round(mx)} ${round(my)}`);
      this.path.push(`A${round(r)} ${round(r)} 0 1 ${f} ${round(sx)} ${round(sy)}`);
      return;
    }
    const ex = x + r * Math.cos(end);
    const ey = y + r * Math.sin(end);
    const large = Math.abs(sweep) % (2 * Math.PI) > Math.PI ? 1 : 0;
    this.path.push(
      `A${round(r)} ${round(r)} 0 ${large} ${anticlockwise ? 0 : 1} ${round(ex)} ${round(ey)}`,
    );
  }
  rect(x: number, y: number, w: number, h: number): void {
    this.path.push(`M${round(x)} ${round(y)}h${round(w)}v${round(h)}h${round(-w)}Z`);
  }
  closePath(): void {
    this.path.push('Z');
  }
  clip(): void {
    const id = `clip${++this.clips}`;
    this.elements.push(`<clipPath id="${id}"><path d="${this.path.join('')}"/></clipPath>`);
    this.style.clip = id;
  }

  /** The attributes every element takes from the state: its opacity and its clip. */
  private shared(): string {
    const s = this.style;
    return (
      (s.globalAlpha < 1 ? ` opacity="${round(s.globalAlpha)}"` : '') +
      (s.clip ? ` clip-path="url(#${s.clip})"` : '')
    );
  }

  stroke(): void {
    if (!this.path.length) return;
    const s = this.style;
    const dash = s.dash.length ? ` stroke-dasharray="${s.dash.join(' ')}"` : '';
    this.elements.push(
      `<path d="${this.path.join('')}" fill="none" stroke="${escapeXml(s.strokeStyle)}" stroke-width="${round(s.lineWidth)}" stroke-linecap="${s.lineCap}" stroke-linejoin="${s.lineJoin}"${dash}${this.shared()}/>`,
    );
  }
  fill(): void {
    if (!this.path.length) return;
    this.elements.push(
      `<path d="${this.path.join('')}" fill="${escapeXml(this.style.fillStyle)}"${this.shared()}/>`,
    );
  }
  fillRect(x: number, y: number, w: number, h: number): void {
    this.elements.push(
      `<rect x="${round(x)}" y="${round(y)}" width="${round(w)}" height="${round(h)}" fill="${escapeXml(this.style.fillStyle)}"${this.shared()}/>`,
    );
  }
  fillText(text: string, x: number, y: number): void {
    // Only filled text counts as what was written; a stroke is its halo.
    this.texts.push(text);
    this.text(text, x, y, `fill="${escapeXml(this.style.fillStyle)}"`);
  }
  strokeText(text: string, x: number, y: number): void {
    const s = this.style;
    this.text(
      text,
      x,
      y,
      `fill="none" stroke="${escapeXml(s.strokeStyle)}" stroke-width="${round(s.lineWidth)}" stroke-linejoin="${s.lineJoin}"`,
    );
  }
  private text(text: string, x: number, y: number, paint: string): void {
    const s = this.style;
    const anchor =
      s.textAlign === 'center'
        ? 'middle'
        : s.textAlign === 'right' || s.textAlign === 'end'
          ? 'end'
          : 'start';
    const baseline =
      s.textBaseline === 'middle'
        ? 'central'
        : s.textBaseline === 'top' || s.textBaseline === 'hanging'
          ? 'hanging'
          : s.textBaseline === 'bottom'
            ? 'text-after-edge'
            : 'alphabetic';
    const { size, family, weight } = parseFont(s.font);
    this.elements.push(
      `<text x="${round(x)}" y="${round(y)}" font-size="${size}" font-family="${escapeXml(family)}" font-weight="${weight}" text-anchor="${anchor}" dominant-baseline="${baseline}" ${paint}${this.shared()}>${escapeXml(text)}</text>`,
    );
  }
  measureText(text: string): { width: number } {
    // Without a canvas we can only estimate: average glyph width of a sans-serif.
    return { width: text.length * parseFont(this.style.font).size * 0.56 };
  }

  /** The whole drawing as an SVG document of the given size. */
  toSvg(width: number, height: number, background?: string): string {
    const bg = background
      ? `<rect width="100%" height="100%" fill="${escapeXml(background)}"/>`
      : '';
    return `<svg xmlns="http://www.w3.org/2000/svg" width="${round(width)}" height="${round(height)}" viewBox="0 0 ${round(width)} ${round(height)}">${bg}${this.elements.join('')}</svg>`;
  }
}

function parseFont(font: string): { size: number; family: string; weight: string } {
  const match = /(?:(bold|\d{3})\s+)?(?:italic\s+)?([\d.]+)px\s+(.+)$/.exec(font.trim());
  if (!match) return { size: 10, family: 'sans-serif', weight: 'normal' };
  return { size: Number(match[2]), family: match[3], weight: match[1] ?? 'normal' };
}
