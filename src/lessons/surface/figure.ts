import type { DrawInfo, FigureSpec, Handle, Point } from '../../app/lesson';
import type { OrbitCamera } from '../../render/orbitCamera';
import type { Painter, StrokeStyle } from '../../render/painter';
import { SpaceScene } from '../../render/space';
import { type PatchSamples, type SurfaceModel } from './model';
import { type SurfaceState } from './state';
import { drawConstruction, drawOverConstruction } from './construction';

/** What a scene shows of the patch itself at its step. */
export interface PatchShown {
  net: boolean;
  /** Corners ringed and labelled. */
  corners: boolean;
  /** The four boundary curves. */
  edges: boolean;
  /** Iso-lines, or the shaded patch (per the look), and how strongly. */
  patch: 'none' | 'faint' | 'full';
  /** The point x(u, v). */
  point: boolean;
}

/** The patch part of each scene's step, before the scene's own construction is drawn. */
export function patchShown(state: SurfaceState): PatchShown {
  const k = state.k;
  const none: PatchShown = {
    net: k >= 0,
    corners: false,
    edges: false,
    patch: 'none',
    point: false,
  };
  switch (state.s) {
    case 'patch':
      return {
        net: k >= 1,
        corners: k >= 2,
        edges: k >= 3,
        patch: k >= 5 ? 'full' : 'none',
        point: k >= 5,
      };
    case 'rows':
      return { ...none, patch: k >= 5 ? 'faint' : 'none', point: k >= 4 };
    case 'casteljau':
      return { ...none, point: k === 3 || k === 6 };
    case 'matrix':
    case 'weights':
      return { ...none, patch: k >= 3 ? 'faint' : 'none', point: k >= 3 };
    case 'normal':
      return { ...none, patch: 'full', point: true };
    case 'join':
      return { ...none, patch: k >= 2 ? 'full' : 'none', corners: false, edges: k >= 1 };
  }
}

/** Points on the surface are drawn a hair towards the viewer, so they sort in front of its facets. */
export function lift(camera: OrbitCamera, size: number): (p: readonly number[]) => Point {
  const back = camera.towardsViewer();
  const d = size * 0.004;
  return (p) => [p[0] + back[0] * d, p[1] + back[1] * d, p[2] + back[2] * d];
}

export function netSize(m: SurfaceModel): number {
  const b = m.bounds;
  return Math.max(b.maxX - b.minX, b.maxY - b.minY, (b.maxZ ?? 0) - (b.minZ ?? 0), 1e-9);
}

/** Short x, y, z axes from the corner of the net's box: which way is which when orbiting, and for Shift-drags. */
function drawAxes(scene: SpaceScene, painter: Painter, m: SurfaceModel, info: DrawInfo): void {
  const theme = painter.theme;
  const b = m.bounds;
  const origin = [b.minX, b.minY, b.minZ ?? 0];
  const length = netSize(m) * 0.18;
  (['x', 'y', 'z'] as const).forEach((name, d) => {
    const end = origin.map((value, i) => (i === d ? value + length : value));
    scene.line(origin, end, { color: theme.axis, width: theme.sizes.thin });
    if (!info.thumbnail) scene.label(name, end, { color: theme.muted, dx: 4, dy: -4 });
  });
}

function drawNet(scene: SpaceScene, net: readonly Point[][], style: StrokeStyle): void {
  for (const row of net) scene.polyline(row, style);
  for (let n = 0; n < net[0].length; n++)
    scene.polyline(
      net.map((row) => row[n]),
      style,
    );
}

function drawPatch(
  scene: SpaceScene,
  painter: Painter,
  samples: PatchSamples,
  state: SurfaceState,
  strength: 'faint' | 'full',
  color: string,
  up: (p: readonly number[]) => Point,
): void {
  const theme = painter.theme;
  const faint = strength === 'faint';
  if (state.look === 'shaded') {
    const g = samples.grid;
    for (let i = 0; i + 1 < g.length; i++) {
      for (let j = 0; j + 1 < g[i].length; j++) {
        scene.quad([g[i][j], g[i + 1][j], g[i + 1][j + 1], g[i][j + 1]], color, {
          alpha: faint ? 0.35 : 0.92,
        });
      }
    }
  }
  const lines = state.look === 'lines';
  const style: StrokeStyle = {
    color: lines && !faint ? theme.curve : theme.curveFaint,
    width: lines && !faint ? theme.sizes.line : theme.sizes.thin,
    alpha: faint ? 0.6 : 1,
    role: 'curve',
  };
  if (lines || !faint) {
    for (const line of [...samples.uLines, ...samples.vLines]) scene.polyline(line.map(up), style);
  }
}

/** The patch's share of the figures' row, against the heat map's 1. */
export const PATCH_WEIGHT = 1.4;

export const spaceFigure: FigureSpec<SurfaceState, SurfaceModel> = {
  id: 'patch',
  title: 'The bicubic Bézier patch in space (drag to orbit, wheel to zoom)',
  kind: 'space',
  camera: { yaw: -60, pitch: 36, perspective: false },
  weight: PATCH_WEIGHT,
  bounds: (m) => m.bounds,
  draw(painter, m, info) {
    const theme = painter.theme;
    const camera = painter.view as OrbitCamera;
    const scene = new SpaceScene(painter, camera);
    const up = lift(camera, netSize(m));
    const state = m.state;
    const shown = patchShown(state);
    const patchColor = painter.color(5);
    const netStyle: StrokeStyle = {
      color: theme.polygon,
      width: theme.sizes.line,
      dash: [6, 5],
      alpha: shown.patch === 'full' ? 0.7 : 1,
    };

    drawAxes(scene, painter, m, info);
    if (shown.patch !== 'none') {
      drawPatch(scene, painter, m.patch, state, shown.patch, patchColor, up);
      if (m.second) drawPatch(scene, painter, m.second, state, shown.patch, painter.color(4), up);
    }
    if (shown.net) {
      drawNet(scene, state.x, netStyle);
      if (state.s === 'join') drawNet(scene, state.y, netStyle);
    }
    if (shown.edges && state.s !== 'join') {
      const g = m.patch;
      for (const edge of [
        g.uLines[0],
        g.uLines[g.uLines.length - 1],
        g.vLines[0],
        g.vLines[g.vLines.length - 1],
      ])
        scene.polyline(edge.map(up), {
          color: theme.curve,
          width: theme.sizes.curve,
          role: 'curve',
        });
    }
    if (shown.corners) {
      const x = state.x;
      for (const corner of [x[0][0], x[3][0], x[0][3], x[3][3]])
        scene.dot(corner, theme.accent, theme.sizes.point * 1.8);
    }
    drawConstruction(scene, painter, m, info, up);
    scene.flush();
    if (shown.point) {
      painter.dot(up(m.point), theme.accent, theme.sizes.point * 1.6);
      if (!info.thumbnail)
        painter.label('x(u,v)', m.point, {
          dx: 12,
          dy: 18,
          color: theme.ink,
          halo: true,
          bold: true,
        });
    }
    if (m.oneSpot)
      painter.note(
        'All 16 control points are on one spot: every row curve, every column curve and the patch shrink to that point, so there is no surface and no normal to draw.',
      );
  },
  drawOver(painter, m, info) {
    drawOverConstruction(painter, m, info);
  },
  handles: (m) => netHandles(m),
  moveHandle(state, id, to) {
    const which = id[0] === 'y' ? 'y' : 'x';
    const [mIndex, nIndex] = id.slice(1).split('_').map(Number);
    const net = state[which].map((row, i) =>
      row.map((p, j) => (i === mIndex && j === nIndex ? [to[0], to[1], to[2]] : p)),
    );
    return { ...state, [which]: net };
  },
  trail: (m) => (patchShown(m.state).point ? m.point : null),
};

/** Labels on every point while the net is the subject; on the corners afterwards. */
function netHandles(m: SurfaceModel): Handle[] {
  const state = m.state;
  const allLabels = state.s === 'patch' && state.k <= 1;
  const handles: Handle[] = [];
  state.x.forEach((row, i) =>
    row.forEach((p, j) =>
      handles.push({
        id: `x${i}_${j}`,
        label: `x_{${i},${j}}`,
        position: p,
        small: true,
        showLabel:
          allLabels || ((i === 0 || i === 3) && (j === 0 || j === 3) && state.s !== 'join'),
      }),
    ),
  );
  if (state.s === 'join') {
    // Row 0 of y sits on row 3 of x: it is edited in the table, so the edge's points stay one handle each.
    state.y.forEach((row, i) =>
      row.forEach((p, j) => {
        if (i > 0)
          handles.push({
            id: `y${i}_${j}`,
            label: `y_{${i},${j}}`,
            position: p,
            small: true,
            showLabel: false,
          });
      }),
    );
  }
  return handles;
}
