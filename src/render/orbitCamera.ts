/**
 * The projection of a figure in space: an orbit camera around a target point,
 * z up, orthographic or perspective. Drag to orbit, wheel or pinch to zoom;
 * the drag plane of a handle faces the viewer, and a ray through a screen
 * point lets a handle move along one axis.
 */
import { type Bounds, type Projection, readNumbers, viewNumber } from './projection';

const DEG = Math.PI / 180;
const MAX_PITCH = 89 * DEG;

export interface CameraSettings {
  /** Turn about the z axis, in degrees. */
  yaw: number;
  /** Elevation above the xy plane, in degrees (−89 … 89). */
  pitch: number;
  perspective: boolean;
}

export interface Ray {
  origin: number[];
  direction: number[];
}

const dot3 = (a: readonly number[], b: readonly number[]) =>
  a[0] * b[0] + a[1] * b[1] + (a[2] ?? 0) * (b[2] ?? 0);

/** Where a figure in space looks from when its lesson does not say. */
const DEFAULT_CAMERA: CameraSettings = { yaw: -60, pitch: 25, perspective: false };

export class OrbitCamera implements Projection {
  readonly dimension = 3;
  width = 300;
  height = 150;
  /** Radians. */
  yaw: number;
  pitch: number;
  perspective: boolean;
  /** Pixels per world unit at the target's depth. */
  scale = 100;
  /** Eye distance from the target, in world units (perspective only). */
  distance = 10;
  target: [number, number, number] = [0, 0, 0];
  // The camera's frame in world coordinates: right, up, and towards the viewer.
  right: number[] = [1, 0, 0];
  up: number[] = [0, 0, 1];
  back: number[] = [0, -1, 0];

  constructor(settings: CameraSettings = DEFAULT_CAMERA) {
    this.yaw = settings.yaw * DEG;
    this.pitch = settings.pitch * DEG;
    this.perspective = settings.perspective;
    this.updateFrame();
  }

  get affine(): boolean {
    return !this.perspective;
  }

  private updateFrame(): void {
    const cy = Math.cos(this.yaw);
    const sy = Math.sin(this.yaw);
    const cp = Math.cos(this.pitch);
    const sp = Math.sin(this.pitch);
    this.back = [cp * cy, cp * sy, sp];
    this.right = [-sy, cy, 0];
    this.up = [-sp * cy, -sp * sy, cp];
  }

  /** The direction from the scene towards the viewer (for lighting and back faces). */
  towardsViewer(): readonly number[] {
    return this.back;
  }

  resize(width: number, height: number): void {
    this.width = Math.max(1, width);
    this.height = Math.max(1, height);
  }

  private relative(p: readonly number[]): [number, number, number] {
    const v = [p[0] - this.target[0], p[1] - this.target[1], (p[2] ?? 0) - this.target[2]];
    return [dot3(v, this.right), dot3(v, this.up), dot3(v, this.back)];
  }

  /** Screen magnification at a depth `zc` towards the viewer from the target. */
  private factor(zc: number): number {
    if (!this.perspective) return 1;
    // A point at or behind the eye is pushed just in front of it.
    return this.distance / Math.max(this.distance - zc, this.distance * 0.05);
  }

  toScreen(p: readonly number[]): [number, number] {
    const [xc, yc, zc] = this.relative(p);
    const k = this.scale * this.factor(zc);
    return [this.width / 2 + xc * k, this.height / 2 - yc * k];
  }

  depth(p: readonly number[]): number {
    return -this.relative(p)[2];
  }

  toWorld(screen: readonly number[], anchor: readonly number[] = this.target): number[] {
    const zc = this.relative(anchor)[2];
    const k = this.scale * this.factor(zc);
    const xc = (screen[0] - this.width / 2) / k;
    const yc = (this.height / 2 - screen[1]) / k;
    return [0, 1, 2].map(
      (i) => this.target[i] + xc * this.right[i] + yc * this.up[i] + zc * this.back[i],
    );
  }

  /** The line of sight through a screen point, from the viewer into the scene. */
  ray(screen: readonly number[]): Ray {
    const onTarget = this.toWorld(screen, this.target);
    if (!this.perspective) {
      return {
        origin: onTarget.map((v, i) => v + this.back[i] * this.distance * 100),
        direction: this.back.map((v) => -v),
      };
    }
    const eye = this.target.map((v, i) => v + this.back[i] * this.distance);
    const d = onTarget.map((v, i) => v - eye[i]);
    const length = Math.hypot(d[0], d[1], d[2]) || 1;
    return { origin: eye, direction: d.map((v) => v / length) };
  }

  /** The point of the line `through + s·axis` nearest to the line of sight through `screen`. */
  closestOnAxis(screen: readonly number[], through: readonly number[], axis: number[]): number[] {
    const { origin, direction } = this.ray(screen);
    const w0 = [0, 1, 2].map((i) => through[i] - origin[i]);
    const a = dot3(axis, axis);
    const b = dot3(axis, direction);
    const c = dot3(direction, direction);
    const d = dot3(axis, w0);
    const e = dot3(direction, w0);
    const denominator = a * c - b * b;
    // Looking straight down the axis: it cannot move along it from here.
    const s = Math.abs(denominator) < 1e-12 ? 0 : (b * e - c * d) / denominator;
    return [0, 1, 2].map((i) => through[i] + s * axis[i]);
  }

  worldLength(pixels: number, at: readonly number[] = this.target): number {
    return pixels / (this.scale * this.factor(this.relative(at)[2]));
  }

  fit(bounds: Bounds, pad: number | readonly [number, number] = 40): void {
    const padding = typeof pad === 'number' ? pad : Math.min(...pad);
    const minZ = bounds.minZ ?? 0;
    const maxZ = bounds.maxZ ?? 0;
    this.target = [
      (bounds.minX + bounds.maxX) / 2,
      (bounds.minY + bounds.maxY) / 2,
      (minZ + maxZ) / 2,
    ];
    const radius = Math.max(
      Math.hypot(bounds.maxX - bounds.minX, bounds.maxY - bounds.minY, maxZ - minZ) / 2,
      1e-9,
    );
    this.distance = radius * 4;
    // The box's corners as this camera sees them: fit their extent, not a
    // sphere round them, so a flat patch or a wide figure fills its frame.
    let halfX = 1e-9;
    let halfY = 1e-9;
    for (const x of [bounds.minX, bounds.maxX])
      for (const y of [bounds.minY, bounds.maxY])
        for (const z of [minZ, maxZ]) {
          const [xc, yc] = this.relative([x, y, z]);
          halfX = Math.max(halfX, Math.abs(xc));
          halfY = Math.max(halfY, Math.abs(yc));
        }
    const innerX = Math.max(this.width / 2 - padding, 10);
    const innerY = Math.max(this.height / 2 - padding, 10);
    // Perspective enlarges what is near: leave room for it.
    this.scale = Math.min(innerX / halfX, innerY / halfY) * (this.perspective ? 0.8 : 1);
  }

  dragBy(dx: number, dy: number): void {
    this.yaw -= dx * 0.008;
    this.pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, this.pitch + dy * 0.008));
    this.updateFrame();
  }

  /** Turns the camera by whole degrees (keyboard orbit). */
  orbit(yawDegrees: number, pitchDegrees: number): void {
    this.yaw += yawDegrees * DEG;
    this.pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, this.pitch + pitchDegrees * DEG));
    this.updateFrame();
  }

  zoomAt(_screen: readonly number[], factor: number): void {
    this.scale = Math.min(Math.max(this.scale * factor, 1e-6), 1e9);
  }

  /** `yaw,pitch,scale,tx,ty,tz,perspective` with angles in degrees. */
  encode(): string {
    return [this.yaw / DEG, this.pitch / DEG, this.scale, ...this.target, this.perspective ? 1 : 0]
      .map(viewNumber)
      .join(',');
  }

  /**
   * The camera's angles and projection alone, when they are not `start`'s:
   * the link of a view that was turned and then fitted (`decodeAngles`).
   */
  encodeAngles(start: CameraSettings | undefined): string | null {
    const from = start ?? DEFAULT_CAMERA;
    const angles = [this.yaw / DEG, this.pitch / DEG].map(viewNumber);
    const same =
      Number(angles[0]) === from.yaw &&
      Number(angles[1]) === from.pitch &&
      this.perspective === from.perspective;
    return same ? null : `${angles.join(',')},${this.perspective ? 1 : 0}`;
  }

  /** Takes angles and projection from `encodeAngles`' text; false if it is not that. */
  decodeAngles(text: string): boolean {
    const values = readNumbers(text, 3);
    if (!values) return false;
    const [yaw, pitch, perspective] = values;
    if (Math.abs(yaw) > 36000 || Math.abs(pitch) > 89 || (perspective !== 0 && perspective !== 1))
      return false;
    this.yaw = yaw * DEG;
    this.pitch = pitch * DEG;
    this.perspective = perspective === 1;
    this.updateFrame();
    return true;
  }

  decode(text: string): boolean {
    const values = readNumbers(text, 7);
    if (!values) return false;
    const [yaw, pitch, scale, tx, ty, tz, perspective] = values;
    if (
      Math.abs(yaw) > 36000 ||
      Math.abs(pitch) > 89 ||
      !(scale >= 1e-6 && scale <= 1e9) ||
      [tx, ty, tz].some((v) => Math.abs(v) > 1e9) ||
      (perspective !== 0 && perspective !== 1)
    )
      return false;
    this.yaw = yaw * DEG;
    this.pitch = pitch * DEG;
    this.scale = scale;
    this.target = [tx, ty, tz];
    this.perspective = perspective === 1;
    this.updateFrame();
    return true;
  }

  /** The screen direction (unit, pixels) in which a world axis points from `at`. */
  screenDirection(at: readonly number[], axis: readonly number[]): [number, number] {
    const a = this.toScreen(at);
    const b = this.toScreen(at.map((v, i) => v + (axis[i] ?? 0) * this.worldLength(40, at)));
    const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
    return length < 1e-9 ? [0, 0] : [(b[0] - a[0]) / length, (b[1] - a[1]) / length];
  }
}
