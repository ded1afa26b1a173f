import type { DrawInfo, Point } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import type { OrbitCamera } from '../../render/orbitCamera';
import type { Painter, StrokeStyle } from '../../render/painter';
import { SpaceScene } from '../../render/space';
import { type PatchSamples, type SurfaceModel } from './model';
import { type SurfaceState } from './state';
import type { Reveal } from './scripts';
import { drawConstruction, drawOverConstruction } from './construction';
import { placeNetLabels } from './netLabels';
import { namedPoints, netPoints, secondNetPoints } from './points';

/** What a scene shows of the patch itself at its step. */
export interface PatchShown {
  net: boolean;
  /** Corners ringed and labelled. */
  corners: boolean;
  /** The four boundary curves. */
  edges: boolean;
  /** Iso-lines, or the shaded patch (per the look), and how strongly. */
  patch: 'none' | 'faint' | 'full';
  /** The iso-curves u, v = 0, ⅛, …, 1 alone, before the patch is shaded. */
  isoCurves: boolean;
  /** The point P(u, v). */
  point: boolean;
}

/** The patch part of each scene's step, before the scene's own construction is drawn. */
export function patchShown({ state, shown }: SurfaceModel): PatchShown {
  const none: PatchShown = {
    net: true,
    corners: false,
    edges: false,
    patch: 'none',
    isoCurves: false,
    point: false,
  };
  switch (state.mode) {
    // The patch and the nets worth seeing: each step by its name ('surface' is
    // the patch without its point, which a step of its own then adds).
    case 'patch':
      return {
        net: shown.has('net'),
        corners: shown.has('corners') || shown.has('cornerQuad'),
        edges: shown.has('edges'),
        isoCurves: shown.has('isoCurves'),
        patch: shown.has('patch') || shown.has('surface') ? 'full' : 'none',
        point: shown.has('patch') || shown.has('point'),
      };
    case 'rows':
      return { ...none, patch: shown.has('isoU') ? 'faint' : 'none', point: shown.has('point') };
    case 'casteljau':
      return { ...none, point: shown.is('uThenV') || shown.is('vThenU') };
    case 'matrix':
      return {
        ...none,
        patch: shown.has('product') ? 'faint' : 'none',
        point: shown.has('product'),
      };
    case 'weights':
      return {
        ...none,
        patch: shown.has('products') ? 'faint' : 'none',
        point: shown.has('products'),
      };
    case 'normal':
      return { ...none, patch: 'full', point: true };
    case 'join':
      return { ...none, patch: shown.has('patches') ? 'full' : 'none', edges: shown.has('edge') };
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
  edges: boolean,
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
    const isoLines = lines
      ? [...samples.uLines, ...samples.vLines]
      : [...samples.facetLines, ...(edges ? [] : samples.facetEdges)];
    for (const line of isoLines) scene.polyline(line.map(up), style);
  }
}

/** The patch's share of the figures' row, against the heat map's 1. */
export const PATCH_WEIGHT = 1.2;

export const spaceFigure: KitFigure<SurfaceState, SurfaceModel> = {
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
    const shown = patchShown(m);
    const patchColor = painter.color(5);
    const netStyle: StrokeStyle = {
      color: theme.polygon,
      width: theme.sizes.line,
      dash: [6, 5],
      alpha: shown.patch === 'full' ? 0.7 : 1,
    };

    drawAxes(scene, painter, m, info);
    if (shown.patch !== 'none') {
      const edges = shown.edges && state.mode !== 'join';
      drawPatch(scene, painter, m.patch, state, shown.patch, patchColor, up, edges);
      if (m.second)
        drawPatch(scene, painter, m.second, state, shown.patch, painter.color(4), up, edges);
    }
    if (shown.net) {
      drawNet(scene, state.net, netStyle);
      if (state.mode === 'join') drawNet(scene, state.secondNet, netStyle);
    }
    if (shown.isoCurves && shown.patch === 'none') {
      for (const line of [...m.patch.uLines, ...m.patch.vLines])
        scene.polyline(line.map(up), {
          color: theme.curve,
          width: theme.sizes.line,
          role: 'curve',
        });
    }
    if (shown.edges && state.mode !== 'join') {
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
      const net = state.net;
      for (const corner of [net[0][0], net[3][0], net[0][3], net[3][3]])
        scene.dot(corner, theme.accent, theme.sizes.point * 1.8);
    }
    drawConstruction(scene, painter, m, info, up);
    scene.flush();
    if (shown.point) {
      painter.movingPoint(up(m.point), 1.6);
      if (!info.thumbnail)
        painter.label('P(u,v)', m.point, {
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
    if (!info.thumbnail) placeNetLabels(painter, m.state.net, namedPoints(m.state));
  },
  points: [netPoints, secondNetPoints],
  trail: (m) => (patchShown(m).point ? m.point : null),
  drawnFrom: drawnFromState,
};

/** Steps that draw nothing at P(u, v): the net, its corners and edges, the patch without its point. */
const AWAY_FROM_THE_POINT: readonly Reveal[] = [
  'points',
  'net',
  'corners',
  'cornerQuad',
  'edges',
  'isoCurves',
  'surface',
];

/**
 * What the patch is drawn from: the whole state, with (u, v) only once the
 * scene reaches a step that draws something at P(u, v). Until then a slider's
 * drag leaves the patch as it is.
 */
export function drawnFromState(m: SurfaceModel): readonly unknown[] {
  const { state, shown } = m;
  const atPoint = state.mode !== 'patch' || !shown.only(AWAY_FROM_THE_POINT);
  const { u, v, ...rest } = state;
  return [shown.key, ...Object.values(rest), ...(atPoint ? [u, v] : [])];
}
