// Edges with their neighbours (framework/src/fur/mesh/adjacency.cpp, ported
// so that the edges, their order and their corners are the native ones):
// four indices per edge, A B C D, where B-C is the edge, A the third corner
// of one triangle (A, B, C counter-clockwise from outside) and D the third
// corner of the triangle on the other side. Natively they feed a geometry
// shader (GL_LINES_ADJACENCY); the web draws fins as instanced quads from
// the same edges (fin_instances.ts).
//
// Neighbours are found by position, not by index, so seams (vertices
// repeated with other texture coordinates or normals) do not cut the mesh.
// The awkward cases, each with one rule the fin shader and the silhouette
// count share:
//   - a boundary edge (one triangle) gets D = A: the edge then counts as a
//     silhouette from every side - the rim of an open surface shows its fur;
//   - a non-manifold edge (three or more triangles) is split into pairs of
//     triangles that run along it in opposite directions; whatever is left
//     over is treated as boundary;
//   - a degenerate triangle (zero area, or two corners at one position) has
//     no normal and no silhouette: it is left out, and its neighbours see a
//     boundary there.
import type { Mesh } from './mesh.js';
import { mix, positionIds } from './position_ids.js';

export { EDGE_INSTANCE_FLOATS, EDGE_INSTANCE_LAYOUT, edgeInstances } from './fin_instances.js';

export interface EdgeAdjacency {
    indices: Uint32Array; // 4 per edge: A, B, C, D
    interiorEdges: number; // two triangles
    boundaryEdges: number; // one triangle, and non-manifold leftovers
    nonManifoldEdges: number; // edges with three or more triangles
    degenerateTriangles: number; // left out
}

export function edgeCount(adjacency: EdgeAdjacency): number {
    return adjacency.indices.length / 4;
}

// Zero area, or so thin that float cannot give it a normal (in double).
function degenerate(p: Float32Array, a: number, b: number, c: number, pos: Uint32Array): boolean {
    if (pos[a] === pos[b] || pos[b] === pos[c] || pos[a] === pos[c]) return true;
    const e1x = p[3 * b]! - p[3 * a]!;
    const e1y = p[3 * b + 1]! - p[3 * a + 1]!;
    const e1z = p[3 * b + 2]! - p[3 * a + 2]!;
    const e2x = p[3 * c]! - p[3 * a]!;
    const e2y = p[3 * c + 1]! - p[3 * a + 1]!;
    const e2z = p[3 * c + 2]! - p[3 * a + 2]!;
    // glm::cross, then glm::length: sqrt((x*x + y*y) + z*z).
    const nx = e1y * e2z - e2y * e1z;
    const ny = e1z * e2x - e2z * e1x;
    const nz = e1x * e2y - e2x * e1y;
    const area2 = Math.sqrt(nx * nx + ny * ny + nz * nz);
    const d1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const d2 = e2x * e2x + e2y * e2y + e2z * e2z;
    const scale = d1 < d2 ? d2 : d1; // std::max
    return !(area2 > 1e-12 * scale);
}

// Half-edges - one side of an edge as a triangle sees it: the edge from B to
// C in the triangle's winding, and the third corner A - grouped by their
// undirected edge (the two position ids), each group in triangle order and
// the groups in order of first appearance, as the native std::map plus its
// `order` list. Flat arrays and linked lists: a mesh can have millions.
class HalfEdges {
    readonly a: Uint32Array;
    readonly b: Uint32Array;
    readonly c: Uint32Array;
    readonly from: Uint32Array; // position ids of B and C
    readonly to: Uint32Array;
    readonly next: Int32Array; // the next half-edge of its group, -1: none
    count = 0;
    groups = 0;
    readonly head: Int32Array; // per group: first and last half-edge, size
    private readonly tail: Int32Array;
    readonly size: Uint32Array;
    private readonly lo: Uint32Array; // per group: its position ids
    private readonly hi: Uint32Array;
    private readonly table: Int32Array; // hash of (lo, hi) -> group

    constructor(capacity: number) {
        [this.a, this.b, this.c, this.from, this.to, this.size, this.lo, this.hi] = Array.from({ length: 8 }, () => new Uint32Array(capacity));
        [this.next, this.head, this.tail] = Array.from({ length: 3 }, () => new Int32Array(capacity));
        let slots = 1;
        while (slots < 2 * capacity) slots *= 2;
        this.table = new Int32Array(slots).fill(-1);
    }

    private group(lo: number, hi: number): number {
        const mask = this.table.length - 1;
        let slot = mix(mix(lo) ^ hi) & mask;
        for (; ; slot = (slot + 1) & mask) {
            const g = this.table[slot]!;
            if (g < 0) break;
            if (this.lo[g] === lo && this.hi[g] === hi) return g;
        }
        const g = this.groups++;
        this.table[slot] = g;
        this.lo[g] = lo;
        this.hi[g] = hi;
        this.head[g] = this.tail[g] = -1;
        return g;
    }

    add(a: number, b: number, c: number, from: number, to: number): void {
        const h = this.count++;
        this.a[h] = a;
        this.b[h] = b;
        this.c[h] = c;
        this.from[h] = from;
        this.to[h] = to;
        this.next[h] = -1;
        const g = this.group(Math.min(from, to), Math.max(from, to));
        if (this.tail[g]! < 0) this.head[g] = h;
        else this.next[this.tail[g]!] = h;
        this.tail[g] = h;
        ++this.size[g];
    }
}

export function buildEdgeAdjacency(mesh: Mesh): EdgeAdjacency {
    const pos = positionIds(mesh.positions).ids;
    const out: EdgeAdjacency = { indices: new Uint32Array(0), interiorEdges: 0, boundaryEdges: 0, nonManifoldEdges: 0, degenerateTriangles: 0 };
    const idx = mesh.indices;
    const halves = new HalfEdges(idx.length);
    for (let t = 0; t + 2 < idx.length; t += 3) {
        const v0 = idx[t]!;
        const v1 = idx[t + 1]!;
        const v2 = idx[t + 2]!;
        if (degenerate(mesh.positions, v0, v1, v2, pos)) {
            ++out.degenerateTriangles;
            continue;
        }
        // Edge k runs from corner k to k + 1; A is the corner before it.
        halves.add(v2, v0, v1, pos[v0]!, pos[v1]!);
        halves.add(v0, v1, v2, pos[v1]!, pos[v2]!);
        halves.add(v1, v2, v0, pos[v2]!, pos[v0]!);
    }
    // Every half-edge becomes one edge (boundary) or two become one.
    const indices = new Uint32Array(4 * halves.count);
    let edges = 0;
    const emit = (h: number, d: number) => {
        const o = 4 * edges++;
        indices[o] = halves.a[h]!;
        indices[o + 1] = halves.b[h]!;
        indices[o + 2] = halves.c[h]!;
        indices[o + 3] = d;
    };
    const used = new Uint8Array(halves.count);
    for (let g = 0; g < halves.groups; ++g) {
        if (halves.size[g]! > 2) ++out.nonManifoldEdges;
        // Pair each side with the first unused side after it running the other way.
        for (let h = halves.head[g]!; h >= 0; h = halves.next[h]!) {
            if (used[h]) continue;
            used[h] = 1;
            let j = halves.next[h]!;
            while (j >= 0 && (used[j] || halves.from[j] !== halves.to[h])) j = halves.next[j]!;
            if (j >= 0) {
                used[j] = 1;
                emit(h, halves.a[j]!);
                ++out.interiorEdges;
            } else {
                emit(h, halves.a[h]!);
                ++out.boundaryEdges;
            }
        }
    }
    out.indices = indices.slice(0, 4 * edges);
    return out;
}
