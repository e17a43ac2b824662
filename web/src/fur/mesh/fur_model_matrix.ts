// FurScene::modelMatrix (framework/src/fur/mesh/fur_scene.cpp) with glm's
// own float arithmetic (glm 0.9.9 ext/matrix_transform.inl, no SIMD, no
// FMA), so the matrix is the native one bit for bit:
//   translate(I, t) * rotate(y + spin * t) * rotate(x) * rotate(z) * scale(s).
import { cosf, f32, normalize, radians, scale as scale3, sinf } from '../../scene/float32.js';
import type { Vec3 } from '../../scene/scene.js';
import type { FurScene } from './fur_scene.js';

type Vec4 = [number, number, number, number];
type Mat4 = [Vec4, Vec4, Vec4, Vec4]; // four columns

const times = (a: Vec4, s: number): Vec4 => [f32(a[0] * s), f32(a[1] * s), f32(a[2] * s), f32(a[3] * s)];
const plus = (a: Vec4, b: Vec4): Vec4 => [f32(a[0] + b[0]), f32(a[1] + b[1]), f32(a[2] + b[2]), f32(a[3] + b[3])];

// glm::translate(m, v): m[3] = m[0] * v[0] + m[1] * v[1] + m[2] * v[2] + m[3].
function translate(m: Mat4, v: Vec3): Mat4 {
    const c3 = plus(plus(plus(times(m[0], v[0]), times(m[1], v[1])), times(m[2], v[2])), m[3]);
    return [m[0], m[1], m[2], c3];
}

// glm::rotate(m, angle, v): the rotation about the axis v, applied after m.
function rotate(m: Mat4, angle: number, v: Vec3): Mat4 {
    const c = cosf(angle);
    const s = sinf(angle);
    const axis = normalize(v);
    const temp = scale3(axis, f32(1 - c));
    const r: Vec3[] = [
        [f32(c + f32(temp[0] * axis[0])), f32(f32(temp[0] * axis[1]) + f32(s * axis[2])), f32(f32(temp[0] * axis[2]) - f32(s * axis[1]))],
        [f32(f32(temp[1] * axis[0]) - f32(s * axis[2])), f32(c + f32(temp[1] * axis[1])), f32(f32(temp[1] * axis[2]) + f32(s * axis[0]))],
        [f32(f32(temp[2] * axis[0]) + f32(s * axis[1])), f32(f32(temp[2] * axis[1]) - f32(s * axis[0])), f32(c + f32(temp[2] * axis[2]))],
    ];
    const column = (i: number): Vec4 => plus(plus(times(m[0], r[i]![0]), times(m[1], r[i]![1])), times(m[2], r[i]![2]));
    return [column(0), column(1), column(2), m[3]];
}

// glm::scale(m, v): each of the first three columns times its factor.
function scale(m: Mat4, v: Vec3): Mat4 {
    return [times(m[0], v[0]), times(m[1], v[1]), times(m[2], v[2]), m[3]];
}

// The model matrix at TIMESECONDS (a float natively), column-major as
// glm::mat4 and gl.uniformMatrix4fv(location, false, ...) take it.
export function modelMatrix(scene: FurScene, timeSeconds: number): Float32Array {
    const identity: Mat4 = [
        [1, 0, 0, 0],
        [0, 1, 0, 0],
        [0, 0, 1, 0],
        [0, 0, 0, 1],
    ];
    const yDeg = f32(scene.rotateDeg[1] + f32(scene.spinDegPerSecond * f32(timeSeconds)));
    let m = translate(identity, scene.translate);
    m = rotate(m, radians(yDeg), [0, 1, 0]);
    m = rotate(m, radians(scene.rotateDeg[0]), [1, 0, 0]);
    m = rotate(m, radians(scene.rotateDeg[2]), [0, 0, 1]);
    m = scale(m, scene.scale);
    return Float32Array.from(m.flat());
}
