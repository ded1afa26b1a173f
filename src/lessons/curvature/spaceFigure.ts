import type { KitFigure } from '../../kit/lesson';
import type { Point } from '../../math';
import { OrbitCamera } from '../../render/orbitCamera';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/projection';
import { SpaceScene } from '../../render/space';
import { COLOURS, arrowUnit, vectorArrow } from './marks';
import type { CurvatureModel } from './model';
import { spacePoints } from './points';
import type { SpaceAt } from './spaceModel';
import type { CurvatureState } from './state';

/** The curve in space with its Frenet frame T, N, B and the osculating plane. */
export const spaceFigure: KitFigure<CurvatureState, CurvatureModel> = {
  id: 'space',
  title: 'The curve in space with the Frenet frame T, N, B and the osculating plane',
  kind: 'space',
  camera: { yaw: -55, pitch: 35, perspective: false },
  // The curve and its osculating circle at t, shown or not yet: the camera
  // fits a sphere round them once, so the circle a later step shows is in
  // view (the view is not fitted again as the clicker steps), with room for
  // the control points near the curve. A circle larger than twice the curve
  // (near an inflection, κ → 0) is left to run off the view rather than
  // shrink the curve to a dot.
  bounds: (m) => {
    const { curve, circle, size, at } = m.space;
    // The circle's diameter, 2/|κ| (none where κ = 0).
    const small = circle.length > 0 && 2 / Math.abs(at.curvature!) <= 2 * size;
    return boundsOf(small ? [...curve, ...circle] : curve);
  },
  draw(painter, m, info) {
    const labels = !info.thumbnail;
    const theme = painter.theme;
    const camera = painter.view;
    if (!(camera instanceof OrbitCamera)) return;
    const scene = new SpaceScene(painter, camera);
    const { part } = m.state;
    const { space, shown } = m;
    // A plane curve shows its osculating circle with κ, and its B = ±e_z with N.
    const inSpace = part === 'space';
    drawAxes(scene, painter, space.curve, labels);
    if (inSpace && m.state.spaceCurve === 'bezier')
      scene.polyline(m.state.spacePoints, {
        color: theme.polygon,
        width: theme.sizes.thin,
        dash: [6, 5],
      });
    if (part === 'arc') drawFence(scene, painter, m);
    scene.polyline(space.curve, { color: theme.curve, width: theme.sizes.curve, role: 'curve' });
    const at = space.at;
    const unit = arrowUnit(space.size);
    if (shown.has(inSpace ? 'osculating' : 'curvature') && at.normal && at.tangent) {
      const h = 1.2 * unit;
      const corner = (a: number, b: number) =>
        at.point.map((v, d) => v + h * (a * at.tangent![d] + b * at.normal![d]));
      scene.quad(
        [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)],
        painter.color(COLOURS.normal),
        {
          alpha: 0.35,
        },
      );
      scene.polyline(space.circle, {
        color: painter.color(COLOURS.curvature),
        width: theme.sizes.line,
      });
    }
    if (inSpace && shown.has('frames'))
      for (const frame of space.along)
        drawFrame(scene, painter, frame, 0.6 * unit, theme.sizes.thin);
    const flips =
      inSpace && shown.has('flips')
        ? space.flips.map((t) => space.curve[Math.round(t * (space.curve.length - 1))])
        : [];
    for (const p of flips) scene.dot(p, theme.ink, theme.sizes.point * 1.4);
    // P(t) over the handles, and so over the scene: at t = 0 it is Q₀.
    painter.movingPoint(at.point, 1.3);
    if (labels) scene.label('P(t)', at.point, { halo: true, dx: -12, dy: 22, align: 'right' });
    scene.flush();
    // Each flip's name on whichever side of its dot the frames leave clear;
    // where they leave none it is left out, not boxed over the frames it is
    // about: the κ, τ plot names the flip's t too, and the caption says it.
    if (labels)
      for (const p of flips)
        painter.label('frame flips: κ → 0', p, {
          halo: true,
          bold: true,
          around: theme.sizes.point * 1.4 + theme.sizes.line,
          optional: true,
        });
    // The frame at t goes over everything: it is what the step talks about.
    if (part === 'space' || part === 'plane') {
      const frame = {
        ...at,
        tangent: shown.has('tangent') ? at.tangent : null,
        normal: shown.has('normal') ? at.normal : null,
        binormal: shown.has(inSpace ? 'binormal' : 'normal') ? at.binormal : null,
      };
      drawFrameOver(painter, frame, unit, labels);
      const why = inSpace ? at.why : null;
      if (labels && why && shown.has('tangent')) painter.note(why);
      // B = T × N is +e_z where the curve turns left (κ > 0), −e_z where it turns right.
      const up = at.binormal ? (at.binormal[2] > 0 ? '+e_z' : '−e_z') : '±e_z';
      if (labels && part === 'plane' && shown.has('normal'))
        painter.screenLabel(
          `A plane curve: B = T × N = ${up}, τ = 0`,
          12,
          painter.view.height - 12,
          // A remark beside the subject: where no place is clear of the
          // curve (a 1366 × 768 projector's small space figure), left out
          // whole rather than boxed over the curve and T.
          { color: theme.muted, halo: true, optional: true },
        );
    }
  },
  points: [spacePoints],
  trail: (m) => m.space.at.point,
  weight: 2,
};

function drawFrameOver(painter: Painter, at: SpaceAt, unit: number, labels: boolean): void {
  const vectors: [Point | null, string, number][] = [
    [at.tangent, 'T', COLOURS.tangent],
    [at.normal, 'N', COLOURS.normal],
    [at.binormal, 'B', COLOURS.binormal],
  ];
  for (const [v, name, colour] of vectors)
    if (v) vectorArrow(painter, at.point, v, unit, name, painter.color(colour), labels);
}

function drawFrame(
  scene: SpaceScene,
  painter: Painter,
  at: SpaceAt,
  length: number,
  width: number,
): void {
  const vectors: [Point | null, number][] = [
    [at.tangent, COLOURS.tangent],
    [at.normal, COLOURS.normal],
    [at.binormal, COLOURS.binormal],
  ];
  for (const [v, colour] of vectors)
    if (v)
      scene.line(
        at.point,
        at.point.map((x, d) => x + length * v[d]),
        { color: painter.color(colour), width: width * 2 },
      );
}

/** Short x, y, z axes from the lowest corner of the curve's box, for orientation. */
function drawAxes(
  scene: SpaceScene,
  painter: Painter,
  curve: readonly Point[],
  labels: boolean,
): void {
  const box = boundsOf(curve);
  const origin = [box.minX, box.minY, box.minZ ?? 0];
  const length = 0.25 * Math.max(box.maxX - box.minX, box.maxY - box.minY, 1e-9);
  const colour = painter.theme.axis;
  ['x', 'y', 'z'].forEach((name, d) => {
    const tip = origin.map((v, k) => v + (k === d ? length : 0));
    scene.line(origin, tip, { color: colour, width: painter.theme.sizes.thin });
    if (labels) scene.label(name, tip, { color: painter.theme.muted, dx: 4, dy: -4 });
  });
}

/** Arc length part: the curve lifted to height proportional to s, with posts at the ticks. */
function drawFence(scene: SpaceScene, painter: Painter, m: CurvatureModel): void {
  const arc = m.arc!;
  const height = (0.5 * m.space.size) / (arc.length || 1);
  const lifted = arc.plotPoints.map((p, i) => [p[0], p[1], height * arc.plot[2 * i + 1]]);
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('arcLength'))
    scene.polyline(lifted, { color: painter.color(3), width: theme.sizes.line });
  const posts = (points: readonly Point[], s: readonly number[], colour: string) =>
    points.forEach((p, i) =>
      scene.line([p[0], p[1], 0], [p[0], p[1], height * s[i]], {
        color: colour,
        width: theme.sizes.line,
      }),
    );
  // While equal steps of s are new, only their posts stand.
  if (shown.has('table') && !shown.is('equalLength'))
    posts(
      arc.byT,
      arc.table.map((r) => r.s),
      painter.color(0),
    );
  if (shown.has('equalLength'))
    posts(
      arc.byS,
      arc.equal.map((r) => r.s),
      painter.color(1),
    );
  if (shown.has('arcLength'))
    scene.label('height = s(t)', lifted[lifted.length - 1], {
      color: painter.color(3),
      halo: true,
      dx: 8,
    });
}
