// The course's FPS-style camera (native: framework/src/core/camera.cpp):
// yaw 0 looks down -z, positive yaw turns toward +x, pitch clamped short of
// straight up or down.
export type Vec3 = [number, number, number];

export interface CameraPose {
  position: Vec3;
  yawDeg: number;
  pitchDeg: number;
}

const MAX_PITCH_DEG = 89.4;
const rad = (d: number) => (d * Math.PI) / 180;
const clampPitch = (p: number) => Math.min(MAX_PITCH_DEG, Math.max(-MAX_PITCH_DEG, p));

export class Camera {
  pose: CameraPose;
  constructor(pose: CameraPose, readonly fovYDeg: number) {
    this.pose = { position: [...pose.position] as Vec3, yawDeg: pose.yawDeg, pitchDeg: clampPitch(pose.pitchDeg) };
  }
  forward(): Vec3 {
    const y = rad(this.pose.yawDeg), p = rad(this.pose.pitchDeg);
    return [Math.sin(y) * Math.cos(p), Math.sin(p), -Math.cos(y) * Math.cos(p)];
  }
  // normalize(cross(forward, world up))
  right(): Vec3 {
    const [fx, , fz] = this.forward();
    const l = Math.hypot(fz, fx);
    return [-fz / l, 0, fx / l];
  }
  // cross(right, forward)
  up(): Vec3 {
    const [rx, ry, rz] = this.right(), [fx, fy, fz] = this.forward();
    return [ry * fz - rz * fy, rz * fx - rx * fz, rx * fy - ry * fx];
  }
  focalLength(): number {
    return 1 / Math.tan(rad(this.fovYDeg) * 0.5);
  }
  turn(dYawDeg: number, dPitchDeg: number): void {
    this.pose.yawDeg = (this.pose.yawDeg + dYawDeg) % 360;
    this.pose.pitchDeg = clampPitch(this.pose.pitchDeg + dPitchDeg);
  }
  move(alongForward: number, alongRight: number): void {
    const f = this.forward(), r = this.right();
    for (let i = 0; i < 3; ++i) this.pose.position[i] += f[i] * alongForward + r[i] * alongRight;
  }
}

// The headless demo's path (native: core/fly_through.cpp): a slow turn about
// the vertical axis through the origin, always looking at the same part of
// the scene, while the animation clock runs.
export function flyThroughPose(start: CameraPose, frame: number, degreesPerFrame = 4): CameraPose {
  const angle = degreesPerFrame * frame, a = rad(angle);
  const [x, y, z] = start.position;
  return {
    position: [x * Math.cos(a) - z * Math.sin(a), y, x * Math.sin(a) + z * Math.cos(a)],
    yawDeg: start.yawDeg + angle,
    pitchDeg: start.pitchDeg,
  };
}
