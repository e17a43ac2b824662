// The few 4x4 matrix operations the fur renderer needs, column-major like
// glm and GLSL (element [col * 4 + row]), in the same formulas as glm's
// lookAt (right-handed) and perspective (depth -1..1).
export type Mat4 = Float32Array;
type V3 = [number, number, number];

const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a: V3): V3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / l, a[1] / l, a[2] / l];
};

export function lookAt(eye: V3, center: V3, up: V3): Mat4 {
  const f = normalize(sub(center, eye));
  const s = normalize(cross(f, up));
  const u = cross(s, f);
  return new Float32Array([
    s[0], u[0], -f[0], 0,
    s[1], u[1], -f[1], 0,
    s[2], u[2], -f[2], 0,
    -dot(s, eye), -dot(u, eye), dot(f, eye), 1,
  ]);
}

export function perspective(fovYRad: number, aspect: number, near: number, far: number): Mat4 {
  const t = Math.tan(fovYRad / 2);
  const m = new Float32Array(16);
  m[0] = 1 / (aspect * t);
  m[5] = 1 / t;
  m[10] = -(far + near) / (far - near);
  m[11] = -1;
  m[14] = -(2 * far * near) / (far - near);
  return m;
}

export function transformPoint(m: Mat4, p: V3): V3 {
  return [0, 1, 2].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]) as V3;
}

// The length of column C's xyz (the model's scale along that axis).
export function columnLength(m: Mat4, c: number): number {
  return Math.hypot(m[4 * c], m[4 * c + 1], m[4 * c + 2]);
}
