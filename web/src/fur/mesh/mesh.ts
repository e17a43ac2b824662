// A triangle mesh as the fur track draws it (framework/src/fur/mesh/mesh.h,
// mesh.cpp): one list of vertices (position, normal, texture coordinate) and
// three indices per triangle, counter-clockwise seen from outside. Vertices
// that share a position but not a normal or texture coordinate (a seam, a
// cube's corner) are separate vertices; edge adjacency (adjacency.ts) finds
// neighbours by position. The arrays are flat and typed, ready for a GL
// buffer; storing into a Float32Array rounds as the native float does.
import { f32, vmax, vmin } from '../../scene/float32.js';
import type { Vec3 } from '../../scene/scene.js';
import { positionIds } from './position_ids.js';

export interface Mesh {
    name: string; // "sphere-2k", "assets/meshes/blob.obj": for messages
    positions: Float32Array; // x, y, z per vertex
    normals: Float32Array; // x, y, z per vertex, unit length
    uvs: Float32Array; // u, v per vertex
    indices: Uint32Array; // three per triangle
}

// Any problem with a mesh: "NAME: what is wrong".
export class MeshError extends Error {
    constructor(message: string) {
        super(message);
        this.name = 'MeshError';
    }
}

export function vertexCount(mesh: Mesh): number {
    return mesh.positions.length / 3;
}

export function triangleCount(mesh: Mesh): number {
    return Math.floor(mesh.indices.length / 3);
}

// Bytes of the vertex and index buffers the GPU holds for this mesh.
export function bufferBytes(mesh: Mesh): number {
    return (mesh.positions.length + mesh.normals.length + mesh.uvs.length + mesh.indices.length) * 4;
}

function vertex(positions: Float32Array, i: number): Vec3 {
    return [positions[3 * i]!, positions[3 * i + 1]!, positions[3 * i + 2]!];
}

// Area-weighted vertex normals; vertices at one position get one normal
// (smooth across seams). Triangles of zero area add nothing; a vertex that
// touches only such triangles gets (0, 1, 0). Sums in double, as natively.
export function computeSmoothNormals(mesh: Mesh): void {
    const p = mesh.positions;
    const { ids, count: positionCount } = positionIds(p);
    const sums = new Float64Array(3 * positionCount);
    const idx = mesh.indices;
    for (let t = 0; t + 2 < idx.length; t += 3) {
        const a = idx[t]!;
        const b = idx[t + 1]!;
        const c = idx[t + 2]!;
        // The edges in float (vec3 - vec3), their cross product in double:
        // its length is twice the area, so the weighting comes free.
        const e1 = [f32(p[3 * b]! - p[3 * a]!), f32(p[3 * b + 1]! - p[3 * a + 1]!), f32(p[3 * b + 2]! - p[3 * a + 2]!)] as const;
        const e2 = [f32(p[3 * c]! - p[3 * a]!), f32(p[3 * c + 1]! - p[3 * a + 1]!), f32(p[3 * c + 2]! - p[3 * a + 2]!)] as const;
        const n0 = e1[1] * e2[2] - e2[1] * e1[2];
        const n1 = e1[2] * e2[0] - e2[2] * e1[0];
        const n2 = e1[0] * e2[1] - e2[0] * e1[1];
        for (const v of [a, b, c]) {
            const id = ids[v]!;
            sums[3 * id] += n0;
            sums[3 * id + 1] += n1;
            sums[3 * id + 2] += n2;
        }
    }
    const count = vertexCount(mesh);
    const normals = new Float32Array(3 * count);
    for (let i = 0; i < count; ++i) {
        normals[3 * i + 1] = 1;
        const id = ids[i]!; // untouched: a zero sum, so (0, 1, 0)
        const x = sums[3 * id]!;
        const y = sums[3 * id + 1]!;
        const z = sums[3 * id + 2]!;
        const length = Math.sqrt(x * x + y * y + z * z);
        if (length > 0) normals.set([x / length, y / length, z / length], 3 * i);
    }
    mesh.normals = normals;
}

// Texture coordinates by spherical projection around the centre of the
// bounding box (for OBJ files without any): a tiling fur pattern needs only
// a continuous, roughly even parameterisation.
export function computeSphericalUvs(mesh: Mesh): void {
    const count = vertexCount(mesh);
    let lo: Vec3 = [Infinity, Infinity, Infinity];
    let hi: Vec3 = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < count; ++i) {
        lo = vmin(lo, vertex(mesh.positions, i));
        hi = vmax(hi, vertex(mesh.positions, i));
    }
    // 0.5f * (lo + hi), in float.
    const centre = [0, 1, 2].map((k) => f32(0.5 * f32(lo[k]! + hi[k]!)));
    const uvs = new Float32Array(2 * count);
    for (let i = 0; i < count; ++i) {
        let d = [0, 1, 2].map((k) => f32(mesh.positions[3 * i + k]! - centre[k]!));
        const r = Math.sqrt(d[0]! * d[0]! + d[1]! * d[1]! + d[2]! * d[2]!);
        if (r === 0) {
            uvs.set([0.5, 0.5], 2 * i);
            continue;
        }
        d = d.map((x) => x / r);
        const y = d[1]! < -1 ? -1 : 1 < d[1]! ? 1 : d[1]!; // std::clamp
        uvs.set([0.5 + Math.atan2(d[0]!, d[2]!) / (2 * Math.PI), Math.acos(y) / Math.PI], 2 * i);
    }
    mesh.uvs = uvs;
}

const INT32_MAX = 2147483647;

// Throws MeshError("NAME: what") for an empty mesh, indices out of range,
// non-finite values, or attribute lists of the wrong length.
export function validateMesh(mesh: Mesh): void {
    const fail = (what: string): never => {
        throw new MeshError(`${mesh.name}: ${what}`);
    };
    if (mesh.positions.length === 0 || mesh.indices.length === 0) fail('the mesh has no triangles');
    if (mesh.indices.length % 3 !== 0) fail('the index count is not a multiple of 3');
    // 32-bit indices, and draw counts in a GLsizei (the adjacency buffer
    // holds four indices per edge: twice the triangles' indices).
    const count = vertexCount(mesh);
    if (count > INT32_MAX || mesh.indices.length > Math.floor(INT32_MAX / 2))
        fail('too large: at most 2^31 vertices and 2^30 indices');
    // Natively a vertex is a vec3; here a flat list could be cut short.
    if (mesh.positions.length % 3 !== 0 || mesh.normals.length !== 3 * count || mesh.uvs.length !== 2 * count)
        fail('every vertex needs a normal and a texture coordinate');
    for (const i of mesh.indices) if (i >= count) fail(`index ${i} is past the last vertex (${count} vertices)`);
    const finite = (a: Float32Array, i: number, n: number) => {
        for (let k = n * i; k < n * i + n; ++k) if (!Number.isFinite(a[k])) return false;
        return true;
    };
    for (let i = 0; i < count; ++i)
        if (!finite(mesh.positions, i, 3) || !finite(mesh.normals, i, 3) || !finite(mesh.uvs, i, 2))
            fail(`vertex ${i} has a value that is not a finite number`);
}
