/**
 * The order a frame is drawn in while its labels are held: the figure's ink,
 * then its handles, then what goes over the handles (the moving point), then
 * the labels in the order they were given, each placed seeing all the ink it
 * must keep clear of (a curve drawn after a label used to run through it).
 */
export class LabelOrder {
  /** Labels waiting for the figure's ink to be down (see hold), in the order given. */
  private held: (() => void)[] | null = null;
  /** The moving point's drawing, waiting for the handles to be down (see aboveHandles). */
  private above: (() => void)[] | null = null;

  /** Are labels waiting (between `hold` and `placeLabels`)? */
  get holding(): boolean {
    return this.held !== null;
  }

  /** From now until `placeLabels`, labels and what goes over the handles wait. */
  hold(): void {
    this.held = [];
    this.above = [];
  }

  /** Draws over the handles: at once, unless labels are held. */
  aboveHandles(draw: () => void): void {
    if (this.above) this.above.push(draw);
    else draw();
  }

  /** Draws what waited to go over the handles: once the handles are down, before the labels. */
  drawAbove(): void {
    const above = this.above;
    this.above = null;
    above?.forEach((draw) => draw());
  }

  /** Places the labels held back, in the order they were given, on top of the figure. */
  placeLabels(): void {
    this.drawAbove();
    const held = this.held;
    this.held = null;
    held?.forEach((place) => place());
  }

  /** Runs `place` now, or when the held labels are placed. */
  placing(place: () => void): void {
    if (this.held) this.held.push(place);
    else place();
  }
}
