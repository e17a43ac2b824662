// The edges of the core's edge adjacency (native: fur/mesh/adjacency.h)
// packed for instanced drawing: WebGL 2 has no
// geometry shader, so the web draws one quad instance per edge and its
// vertex shader does what fin.geom does natively with the four vertices of
// GL_LINES_ADJACENCY (A, B, C, D; the edge is B-C). Everything is in object
// space; the shader applies the model matrix.
//
// 22 floats per edge (stride 88 bytes), in the adjacency's edge order:
//   offset  0: A.xyz    third corner of the first triangle
//   offset  3: B.xyz    the edge's first end
//   offset  6: C.xyz    the edge's second end
//   offset  9: D.xyz    third corner of the other triangle (= A on a boundary)
//   offset 12: nB.xyz   vertex normal at B        (fin.geom's vNormal[1])
//   offset 15: nC.xyz   vertex normal at C        (fin.geom's vNormal[2])
//   offset 18: uvB.xy   texture coordinate at B   (fin.geom's vUv[1])
//   offset 20: uvC.xy   texture coordinate at C   (fin.geom's vUv[2])
import type { MeshArrays } from './fur_mesh_buffers.js';

export const EDGE_INSTANCE_FLOATS = 22;
// Where each attribute starts, in floats, and its size.
export const EDGE_INSTANCE_LAYOUT = [
    { name: 'a', offset: 0, size: 3 },
    { name: 'b', offset: 3, size: 3 },
    { name: 'c', offset: 6, size: 3 },
    { name: 'd', offset: 9, size: 3 },
    { name: 'normalB', offset: 12, size: 3 },
    { name: 'normalC', offset: 15, size: 3 },
    { name: 'uvB', offset: 18, size: 2 },
    { name: 'uvC', offset: 20, size: 2 },
] as const;

// ADJACENCY: 4 vertex indices per edge, A B C D.
export function edgeInstances(mesh: MeshArrays, adjacency: Uint32Array): Float32Array {
    const edges = adjacency.length / 4;
    const out = new Float32Array(EDGE_INSTANCE_FLOATS * edges);
    const copy = (from: Float32Array, size: number, vertex: number, at: number) => {
        for (let k = 0; k < size; ++k) out[at + k] = from[size * vertex + k]!;
    };
    for (let e = 0; e < edges; ++e) {
        const o = EDGE_INSTANCE_FLOATS * e;
        for (let k = 0; k < 4; ++k) copy(mesh.positions, 3, adjacency[4 * e + k]!, o + 3 * k);
        const b = adjacency[4 * e + 1]!;
        const c = adjacency[4 * e + 2]!;
        copy(mesh.normals, 3, b, o + 12);
        copy(mesh.normals, 3, c, o + 15);
        copy(mesh.uvs, 2, b, o + 18);
        copy(mesh.uvs, 2, c, o + 20);
    }
    return out;
}
