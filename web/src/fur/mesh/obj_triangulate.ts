// Polygons split into triangles as the native build's tinyobjloader (Debian
// 2.0.0~rc10, built without mapbox earcut, float real_t) splits them, so
// that the triangles - and with them the order in which vertices are first
// met - are the native ones (tiny_obj_loader.h, exportGroupsToShape):
//   - a quad along its shorter diagonal: [0 1 2] [0 2 3] when |v2 - v0|^2 <
//     |v3 - v1|^2, else [0 1 3] [1 2 3];
//   - a larger polygon by ear clipping in the plane of the two axes that
//     its first non-flat corner spans most; as natively, a polygon the ears
//     cannot be cut from loses its remaining triangles.
// All arithmetic is in float, as tinyobjloader's.
import type { ObjCorner } from './obj_reader.js';

const f32 = Math.fround;
const FLT_EPSILON = 2 ** -23;

// Appends the triangles of FACE (corner indices into VERTICES, x y z per
// vertex, all in range) to OUT, three corners each.
export function triangulate(face: ObjCorner[], vertices: ArrayLike<number>, out: ObjCorner[]): void {
    if (face.length === 3) out.push(...face);
    else if (face.length === 4) splitQuad(face, vertices, out);
    else clipEars(face, vertices, out);
}

function splitQuad(q: ObjCorner[], v: ArrayLike<number>, out: ObjCorner[]): void {
    const sqr = (i: number, j: number) => {
        const d = [0, 1, 2].map((k) => f32(v[3 * q[j]!.v + k]! - v[3 * q[i]!.v + k]!));
        return f32(f32(f32(d[0]! * d[0]!) + f32(d[1]! * d[1]!)) + f32(d[2]! * d[2]!));
    };
    const [c0, c1, c2, c3] = q as [ObjCorner, ObjCorner, ObjCorner, ObjCorner];
    if (sqr(0, 2) < sqr(1, 3)) out.push(c0, c1, c2, c0, c2, c3);
    else out.push(c0, c1, c3, c1, c2, c3);
}

// The two axes to work in: by default y and z; the first corner whose edges
// are not parallel decides (its cross product's largest component is the
// axis left out).
function projectionAxes(face: ObjCorner[], v: ArrayLike<number>): [number, number] {
    const axes: [number, number] = [1, 2];
    const n = face.length;
    for (let k = 0; k < n; ++k) {
        const p = [0, 1, 2].map((i) => 3 * face[(k + i) % n]!.v);
        const e0 = [0, 1, 2].map((a) => f32(v[p[1]! + a]! - v[p[0]! + a]!));
        const e1 = [0, 1, 2].map((a) => f32(v[p[2]! + a]! - v[p[1]! + a]!));
        const crossAbs = (a: number, b: number) => Math.abs(f32(f32(e0[a]! * e1[b]!) - f32(e0[b]! * e1[a]!)));
        const cx = crossAbs(1, 2);
        const cy = crossAbs(2, 0);
        const cz = crossAbs(0, 1);
        if (cx > FLT_EPSILON || cy > FLT_EPSILON || cz > FLT_EPSILON) {
            if (!(cx > cy && cx > cz)) {
                axes[0] = 0;
                if (cz > cx && cz > cy) axes[1] = 1;
            }
            break;
        }
    }
    return axes;
}

// Whether (tx, ty) lies inside the triangle (W. R. Franklin's pnpoly), in float.
function inside(vx: number[], vy: number[], tx: number, ty: number): boolean {
    let c = false;
    for (let i = 0, j = 2; i < 3; j = i++) {
        if (vy[i]! > ty !== vy[j]! > ty) {
            const x = f32(f32(f32(f32(vx[j]! - vx[i]!) * f32(ty - vy[i]!)) / f32(vy[j]! - vy[i]!)) + vx[i]!);
            if (tx < x) c = !c;
        }
    }
    return c;
}

function clipEars(face: ObjCorner[], v: ArrayLike<number>, out: ObjCorner[]): void {
    const [ax, ay] = projectionAxes(face, v);
    const x = (c: ObjCorner) => v[3 * c.v + ax]!;
    const y = (c: ObjCorner) => v[3 * c.v + ay]!;
    const remaining = face.slice();
    let guess = 0;
    // How many tries are left without cutting an ear.
    let remainingIterations = face.length;
    let previousRemaining = remaining.length;
    while (remaining.length > 3 && remainingIterations > 0) {
        const n = remaining.length;
        if (guess >= n) guess -= n;
        if (previousRemaining !== n) {
            previousRemaining = n;
            remainingIterations = n;
        } else {
            --remainingIterations;
        }
        const ind = [0, 1, 2].map((k) => remaining[(guess + k) % n]!);
        const vx = ind.map(x);
        const vy = ind.map(y);
        const e0x = f32(vx[1]! - vx[0]!);
        const e0y = f32(vy[1]! - vy[0]!);
        const e1x = f32(vx[2]! - vx[1]!);
        const e1y = f32(vy[2]! - vy[1]!);
        const cross = f32(f32(e0x * e1y) - f32(e0y * e1x));
        // Not the triangle's area, but what tinyobjloader compares with.
        const area = f32(f32(f32(vx[0]! * vy[1]!) - f32(vy[0]! * vx[1]!)) * 0.5);
        if (f32(cross * area) < 0) {
            ++guess; // an internal angle
            continue;
        }
        let overlap = false;
        for (let other = 3; other < n && !overlap; ++other) {
            const c = remaining[(guess + other) % n]!;
            overlap = inside(vx, vy, x(c), y(c));
        }
        if (overlap) {
            ++guess;
            continue;
        }
        out.push(...ind); // an ear: cut off its middle corner
        remaining.splice((guess + 1) % n, 1);
    }
    if (remaining.length === 3) out.push(...remaining);
}
