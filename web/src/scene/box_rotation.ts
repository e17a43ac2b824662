// The turn of a box about its vertical axis, in double as natively
// (scene_shapes.cpp's readBoxes): glm::rotate(glm::dmat4(1.0), angle, axis)
// and glm's mat4 * vec4, operation for operation, so that the corners
// come out as the same floats (the specialised shader prints them). Double
// sin and cos are the same in practice on every C library and in every
// JavaScript engine; float sinf/cosf are not, which is why the native code
// turns boxes in double.
type Mat = number[][];  // four columns of four numbers

export function rotationDouble(angleRad: number, v: [number, number, number]): Mat {
    const c = Math.cos(angleRad);
    const s = Math.sin(angleRad);
    const inv = 1 / Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const a = [v[0] * inv, v[1] * inv, v[2] * inv];
    const t = [a[0]! * (1 - c), a[1]! * (1 - c), a[2]! * (1 - c)];
    const r = [
        [c + t[0]! * a[0]!, t[0]! * a[1]! + s * a[2]!, t[0]! * a[2]! - s * a[1]!],
        [t[1]! * a[0]! - s * a[2]!, c + t[1]! * a[1]!, t[1]! * a[2]! + s * a[0]!],
        [t[2]! * a[0]! + s * a[1]!, t[2]! * a[1]! - s * a[0]!, c + t[2]! * a[2]!],
    ];
    const m = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
    const column = (i: number) =>
        [0, 1, 2, 3].map((k) => m[0]![k]! * r[i]![0]! + m[1]![k]! * r[i]![1]! + m[2]![k]! * r[i]![2]!);
    return [column(0), column(1), column(2), m[3]!];
}

// glm's mat4 * vec4: (m0 v0 + m1 v1) + (m2 v2 + m3 v3).
export function transformDouble(m: Mat, v: [number, number, number, number]): number[] {
    return [0, 1, 2, 3].map(
        (k) => (m[0]![k]! * v[0] + m[1]![k]! * v[1]) + (m[2]![k]! * v[2] + m[3]![k]! * v[3]),
    );
}

export const radiansDouble = (deg: number) => deg * 0.01745329251994329576923690768489;
