/**
 * The presenter's ghost: a kept model drawn faintly under the current one, to
 * compare a change with what was there before, without labels or handles.
 */
import { Painter } from '../render/painter';
import type { Projection } from '../render/projection';
import type { DrawingSurface } from '../render/surface';
import type { Theme } from '../render/theme';
import type { DrawInfo, FigureSpec } from './lesson';

/** Draws `ghost` with the figure's own drawing in a faint palette. */
export function drawGhost<S, M>(
  surface: DrawingSurface,
  view: Projection,
  spec: FigureSpec<S, M>,
  ghost: M,
  theme: Theme,
  info: DrawInfo,
): void {
  surface.save();
  // Every stroke sets its own alpha: a faint palette makes the ghost faint.
  const faint: Theme = {
    ...theme,
    curve: theme.curveFaint,
    ink: theme.curveFaint,
    polygon: theme.curveFaint,
    accent: theme.curveFaint,
    palette: theme.palette.map(() => theme.curveFaint),
  };
  const painter = new Painter(surface, view, faint, {
    curve: true,
    labels: false,
    numbers: false,
  });
  spec.draw(painter, ghost, info);
  surface.restore();
}
