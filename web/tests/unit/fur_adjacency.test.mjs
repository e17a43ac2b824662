// Edge adjacency (adjacency.ts, the port of framework/src/fur/mesh/
// adjacency.cpp) and its packed form for instanced fins (fin_instances.ts).
// That the edges and their order are the native ones is checked through the
// native digests in fur_mesh_shapes.test.mjs and fur_obj_mesh.test.mjs.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { buildEdgeAdjacency, EDGE_INSTANCE_FLOATS, EDGE_INSTANCE_LAYOUT, edgeCount, edgeInstances } from '../../dist/fur/mesh/adjacency.js';
import { makeShape } from '../../dist/fur/mesh/mesh_shapes.js';

function mesh(positions, indices, uvs) {
    const n = positions.length / 3;
    return {
        name: 'test',
        positions: Float32Array.from(positions),
        normals: Float32Array.from({ length: 3 * n }, (_, i) => (i % 3 === 2 ? 1 : 0)),
        uvs: Float32Array.from(uvs ?? Array.from({ length: 2 * n }, (_, i) => i / 10)),
        indices: Uint32Array.from(indices),
    };
}

const edgesOf = (a) => Array.from({ length: edgeCount(a) }, (_, e) => [...a.indices.subarray(4 * e, 4 * e + 4)]);

test('closed sphere and torus: every edge has two triangles, E = 3T/2', () => {
    for (const [shape, detail] of [['sphere', 2], ['sphere', 7], ['sphere', 32], ['torus', 3], ['torus', 24], ['cube', 1], ['cube', 5]]) {
        const m = makeShape(shape, detail);
        const a = buildEdgeAdjacency(m);
        const triangles = m.indices.length / 3;
        assert.equal(a.boundaryEdges, 0, `${shape} ${detail}`);
        assert.equal(a.nonManifoldEdges, 0);
        assert.equal(a.degenerateTriangles, 0);
        assert.equal(edgeCount(a), (3 * triangles) / 2);
        assert.equal(a.interiorEdges, edgeCount(a));
        // D is never A on a closed mesh, and B-C is an edge of a triangle A B C.
        for (const [A, B, C, D] of edgesOf(a)) {
            assert.notEqual(A, D);
            assert.notEqual(B, C);
        }
    }
});

test('torus detail 2: a tube of two segments, whose four ring edges have four triangles each (natively too)', () => {
    const a = buildEdgeAdjacency(makeShape('torus', 2));
    assert.deepEqual([a.interiorEdges, a.boundaryEdges, a.nonManifoldEdges, a.degenerateTriangles], [24, 0, 4, 0]);
});

test('a single triangle: three boundary edges with D = A, in winding order', () => {
    const a = buildEdgeAdjacency(mesh([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2]));
    assert.equal(a.boundaryEdges, 3);
    assert.equal(a.interiorEdges, 0);
    // Edge k runs from corner k to k + 1; A is the corner before it.
    assert.deepEqual(edgesOf(a), [[2, 0, 1, 2], [0, 1, 2, 0], [1, 2, 0, 1]]);
});

test('two triangles sharing an edge through repeated vertices (a seam)', () => {
    // Square 0 1 2 3 split along 0-2; the second triangle uses copies 4 (= 0) and 5 (= 2).
    const p = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0];
    const a = buildEdgeAdjacency(mesh(p, [0, 1, 2, 4, 5, 3]));
    assert.equal(a.interiorEdges, 1);
    assert.equal(a.boundaryEdges, 4);
    // First appearance order: 0-1, 1-2, 2-0 (paired with 5-4, D = 3), then 2-3, 3-0.
    assert.deepEqual(edgesOf(a), [[2, 0, 1, 2], [0, 1, 2, 0], [1, 2, 0, 3], [4, 5, 3, 4], [5, 3, 4, 5]]);
});

test('degenerate triangles are left out; non-manifold edges pair up opposite sides', () => {
    // A zero-area triangle (collinear) and one with two corners at one position.
    const flat = buildEdgeAdjacency(mesh([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0], [0, 1, 2, 0, 3, 1]));
    assert.equal(flat.degenerateTriangles, 2);
    assert.equal(edgeCount(flat), 0);
    // Three triangles on the edge 0-1: two run 0->1, one 1->0.
    const p = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1];
    const a = buildEdgeAdjacency(mesh(p, [0, 1, 2, 1, 0, 3, 0, 1, 4]));
    assert.equal(a.nonManifoldEdges, 1);
    const shared = edgesOf(a).filter(([, B, C]) => (B === 0 && C === 1) || (B === 1 && C === 0));
    // The first side pairs with the first side running the other way; the third is left alone.
    assert.deepEqual(shared, [[2, 0, 1, 3], [4, 0, 1, 4]]);
    assert.equal(a.interiorEdges, 1);
    assert.equal(a.boundaryEdges, 9 - 2); // the other half-edges, each alone
});

test('edgeInstances: A B C D, the normals and uvs at B and C, per edge', () => {
    const m = mesh([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]);
    m.normals.set([1, 0, 0, 0, 1, 0, 0, 0, 1]);
    const a = buildEdgeAdjacency(m);
    const data = edgeInstances(m, a);
    assert.equal(EDGE_INSTANCE_FLOATS, 22);
    assert.equal(data.length, EDGE_INSTANCE_FLOATS * 3);
    const f = Math.fround;
    // Edge 1: A = 0, B = 1, C = 2, D = 0.
    assert.deepEqual([...data.subarray(22, 44)], [
        0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, // A B C D
        0, 1, 0, 0, 0, 1, // normals at B and C
        f(0.3), f(0.4), f(0.5), f(0.6), // uvs at B and C
    ]);
    // The layout table covers the record without gaps.
    let next = 0;
    for (const { offset, size } of EDGE_INSTANCE_LAYOUT) {
        assert.equal(offset, next);
        next += size;
    }
    assert.equal(next, EDGE_INSTANCE_FLOATS);
    // On a real mesh: one record per edge, points taken from the indices.
    const s = makeShape('torus', 3);
    const sa = buildEdgeAdjacency(s);
    const sd = edgeInstances(s, sa);
    assert.equal(sd.length, EDGE_INSTANCE_FLOATS * edgeCount(sa));
    const last = edgeCount(sa) - 1;
    const D = sa.indices[4 * last + 3];
    assert.deepEqual([...sd.subarray(22 * last + 9, 22 * last + 12)], [...s.positions.subarray(3 * D, 3 * D + 3)]);
});
