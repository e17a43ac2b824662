// glm's float (32-bit) vector maths, operation by operation, so the web build
// computes the very same floats as the native one (framework/src/raytrace/
// scene uses glm 0.9.9 with plain IEEE float arithmetic: no -ffast-math, no
// FMA). Every intermediate result is rounded with Math.fround, in the order
// glm evaluates it; the baked shader text (scene_baking.ts) prints these
// floats with 9 digits, so one differing bit would show.
import type { Vec3 } from './scene.js';

export const f32 = Math.fround;

export function add(a: Vec3, b: Vec3): Vec3 {
    return [f32(a[0] + b[0]), f32(a[1] + b[1]), f32(a[2] + b[2])];
}
export function sub(a: Vec3, b: Vec3): Vec3 {
    return [f32(a[0] - b[0]), f32(a[1] - b[1]), f32(a[2] - b[2])];
}
export function mul(a: Vec3, b: Vec3): Vec3 {
    return [f32(a[0] * b[0]), f32(a[1] * b[1]), f32(a[2] * b[2])];
}
export function scale(a: Vec3, s: number): Vec3 {
    return [f32(a[0] * s), f32(a[1] * s), f32(a[2] * s)];
}
// glm divides each component (it does not multiply by the reciprocal).
export function divide(a: Vec3, s: number): Vec3 {
    return [f32(a[0] / s), f32(a[1] / s), f32(a[2] / s)];
}
export function splat(s: number): Vec3 {
    return [s, s, s];
}

// glm::dot for vec3: tmp = a * b; tmp.x + tmp.y + tmp.z (left to right).
export function dot(a: Vec3, b: Vec3): number {
    const t = mul(a, b);
    return f32(f32(t[0] + t[1]) + t[2]);
}
export function length(v: Vec3): number {
    return f32(Math.sqrt(dot(v, v)));
}
// glm::normalize: v * inversesqrt(dot(v, v)), inversesqrt(x) = 1 / sqrt(x).
export function normalize(v: Vec3): Vec3 {
    return scale(v, f32(1 / f32(Math.sqrt(dot(v, v)))));
}
export function cross(x: Vec3, y: Vec3): Vec3 {
    return [
        f32(f32(x[1] * y[2]) - f32(y[1] * x[2])),
        f32(f32(x[2] * y[0]) - f32(y[2] * x[0])),
        f32(f32(x[0] * y[1]) - f32(y[0] * x[1])),
    ];
}

// glm::min / max / abs on scalars: (y < x) ? y : x, x >= 0 ? x : -x. Not
// Math.min etc., which treat -0 and +0 differently.
export function minf(x: number, y: number): number {
    return y < x ? y : x;
}
export function maxf(x: number, y: number): number {
    return x < y ? y : x;
}
export function absf(x: number): number {
    return x >= 0 ? x : -x;
}
export function vmin(a: Vec3, b: Vec3): Vec3 {
    return [minf(a[0], b[0]), minf(a[1], b[1]), minf(a[2], b[2])];
}
export function vmax(a: Vec3, b: Vec3): Vec3 {
    return [maxf(a[0], b[0]), maxf(a[1], b[1]), maxf(a[2], b[2])];
}
export function vabs(a: Vec3): Vec3 {
    return [absf(a[0]), absf(a[1]), absf(a[2])];
}

// std::sin / std::cos on floats: the nearest float to the true value. C
// libraries' sinf/cosf are off by one bit now and then; these values only
// move spheres and turn tori per frame, where one bit makes no difference.
export function sinf(x: number): number {
    return f32(Math.sin(x));
}
export function cosf(x: number): number {
    return f32(Math.cos(x));
}

// glm::radians for float: degrees * float(pi / 180).
const DEG_TO_RAD = f32(0.01745329251994329576923690768489);
export function radians(deg: number): number {
    return f32(deg * DEG_TO_RAD);
}

// A 4x4 matrix as four columns of four floats (glm's layout).
export type Mat4 = [number[], number[], number[], number[]];

const IDENTITY: Mat4 = [
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [0, 0, 1, 0],
    [0, 0, 0, 1],
];

// c = a * s (a vec4 times a scalar), componentwise.
function scale4(a: number[], s: number): number[] {
    return a.map((x) => f32(x * s));
}
function add4(a: number[], b: number[]): number[] {
    return a.map((x, i) => f32(x + b[i]!));
}

// glm::rotate(glm::mat4(1.0f), angle, v) (ext/matrix_transform.inl),
// including its products with the identity's zeros (they can turn a -0 into
// +0, which the printed text would show).
export function rotation(angle: number, v: Vec3): Mat4 {
    const c = cosf(angle);
    const s = sinf(angle);
    const axis = normalize(v);
    const temp = scale(axis, f32(1 - c));
    const r: number[][] = [
        [
            f32(c + f32(temp[0] * axis[0])),
            f32(f32(temp[0] * axis[1]) + f32(s * axis[2])),
            f32(f32(temp[0] * axis[2]) - f32(s * axis[1])),
        ],
        [
            f32(f32(temp[1] * axis[0]) - f32(s * axis[2])),
            f32(c + f32(temp[1] * axis[1])),
            f32(f32(temp[1] * axis[2]) + f32(s * axis[0])),
        ],
        [
            f32(f32(temp[2] * axis[0]) + f32(s * axis[1])),
            f32(f32(temp[2] * axis[1]) - f32(s * axis[0])),
            f32(c + f32(temp[2] * axis[2])),
        ],
    ];
    const m = IDENTITY;
    const column = (i: number) =>
        add4(add4(scale4(m[0], r[i]![0]!), scale4(m[1], r[i]![1]!)), scale4(m[2], r[i]![2]!));
    return [column(0), column(1), column(2), m[3].slice()];
}

// glm's mat4 * vec4: (m0*v0 + m1*v1) + (m2*v2 + m3*v3), columns times scalars.
export function transform(m: Mat4, v: [number, number, number, number]): number[] {
    const add0 = add4(scale4(m[0], v[0]), scale4(m[1], v[1]));
    const add1 = add4(scale4(m[2], v[2]), scale4(m[3], v[3]));
    return add4(add0, add1);
}

// std::fmod on floats: exact, so the double remainder is already the float.
export function fmod32(a: number, b: number): number {
    return a % b;
}
