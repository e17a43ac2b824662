// The procedural meshes (mesh_shapes.ts): counts from mesh_shapes.h's
// formulas, seams that share positions exactly, unit normals, and - through
// a digest of every float's bits, every index and the edge adjacency - the
// very meshes the native build makes (digests from framework/src/fur/mesh's
// makeShape and buildEdgeAdjacency, printed as by mesh_dump.mjs).
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { buildEdgeAdjacency } from '../../dist/fur/mesh/adjacency.js';
import { MeshError, validateMesh } from '../../dist/fur/mesh/mesh.js';
import { positionIds } from '../../dist/fur/mesh/position_ids.js';
import { defaultDetail, detailForTriangles, makeShape, shapeNames } from '../../dist/fur/mesh/mesh_shapes.js';
import { dumpMesh, sha256 } from './mesh_dump.mjs';


const NATIVE = {
    'sphere 6': '8defae6cce68168c2cf8d07a195095c2e78fa00e96e3d0c19ffc1c897c2623fb',
    'sphere 32': 'e9f032aaf8844091573799175d571e98ec3dd12ce3d499fd63c4f3e7f2692e26',
    'torus 2': 'c81f11cfeaec964e3bc6df610b4cbebbb61218a52c5098d6e3fdb0cc8eeab60b',
    'torus 24': '2c3cbec15bbca2bb3f0994d6327db2e0eaf15f90d55378f61a14915ca6e12ce4',
    'cube 3': '864dc6ce6168009b2ce79a760ab77e3bff9b4295f7c4f15b004f2310f5fdcfed',
    'cube 8': '6341dcb47842a1607a55390ea4543d8ff25951d68f015b26b8b9ad4d58f7ff05',
};

for (const [key, digest] of Object.entries(NATIVE))
    test(`makeShape ${key}: the native floats, indices and edges`, () => {
        const [shape, detail] = key.split(' ');
        assert.equal(sha256(dumpMesh(makeShape(shape, Number(detail)))), digest);
    });

// mesh_shapes.h: vertex and triangle counts.
function expected(shape, d) {
    if (shape === 'sphere') return { vertices: (2 * d + 1) * (d + 1), triangles: 4 * d * d - 4 * d };
    if (shape === 'torus') return { vertices: (2 * d + 1) * (d + 1), triangles: 4 * d * d };
    return { vertices: 6 * (d + 1) * (d + 1), triangles: 12 * d * d };
}

test('vertex and triangle counts per shape and detail', () => {
    assert.deepEqual(shapeNames(), ['sphere', 'torus', 'cube']);
    for (const shape of shapeNames())
        for (const d of [shape === 'cube' ? 1 : 2, 3, 6, 17, 32, defaultDetail(shape)]) {
            const m = makeShape(shape, d);
            const e = expected(shape, d);
            assert.equal(m.positions.length, 3 * e.vertices, `${shape} ${d}`);
            assert.equal(m.normals.length, 3 * e.vertices);
            assert.equal(m.uvs.length, 2 * e.vertices);
            assert.equal(m.indices.length, 3 * e.triangles);
            assert.equal(m.name, `${shape}-${e.triangles}`);
            validateMesh(m);
        }
});

test('normals are unit length and uvs lie in [0, 1]', () => {
    for (const shape of shapeNames()) {
        const m = makeShape(shape, 9);
        for (let i = 0; i < m.normals.length; i += 3)
            assert.ok(Math.abs(Math.hypot(m.normals[i], m.normals[i + 1], m.normals[i + 2]) - 1) < 1e-6, `${shape} ${i / 3}`);
        for (const x of m.uvs) assert.ok(x >= 0 && x <= 1);
    }
});

// How many distinct positions the mesh has (-0 and +0 being one).
function positions(m) {
    const keys = new Set();
    for (let i = 0; i < m.positions.length; i += 3) keys.add(`${m.positions[i]},${m.positions[i + 1]},${m.positions[i + 2]}`);
    assert.equal(positionIds(m.positions).count, keys.size);
    return keys.size;
}

test('seams repeat vertices at exactly the same positions (as natively)', () => {
    const d = 8;
    // Sphere: the seam column repeats the first one; each pole row is one point.
    assert.equal(positions(makeShape('sphere', d)), 2 * d * (d - 1) + 2);
    // Torus: the last column and the last row repeat the first ones.
    assert.equal(positions(makeShape('torus', d)), 2 * d * d);
    // Cube: faces meet at shared edges and corners.
    assert.equal(positions(makeShape('cube', d)), 6 * (d + 1) * (d + 1) - 12 * (d + 1) + 8);
    // The seam's texture coordinates differ: u = 1 there, u = 0 at the start.
    const s = makeShape('sphere', d);
    const row = 2 * d + 1;
    const first = 3 * row; // row 1, column 0
    const last = 3 * (2 * row - 1); // row 1, last column
    assert.deepEqual([...s.positions.subarray(last, last + 3)], [...s.positions.subarray(first, first + 3)]);
    assert.deepEqual([s.uvs[2 * row], s.uvs[2 * (2 * row - 1)]], [0, 1]);
});

test('the sphere has no degenerate triangle; its poles are fans', () => {
    for (const d of [2, 5, 32]) {
        const a = buildEdgeAdjacency(makeShape('sphere', d));
        assert.equal(a.degenerateTriangles, 0);
    }
});

test('makeShape refuses unknown shapes and details out of range', () => {
    assert.throws(() => makeShape('cone', 8), { name: 'MeshError', message: "unknown mesh shape 'cone' (known: sphere, torus, cube)" });
    assert.throws(() => makeShape('sphere', 1), { message: 'mesh sphere: detail must be between 2 and 2048 (not 1)' });
    assert.throws(() => makeShape('cube', 0), { message: 'mesh cube: detail must be between 1 and 2048 (not 0)' });
    assert.throws(() => makeShape('torus', 2049), (e) => e instanceof MeshError);
    assert.throws(() => makeShape('torus', 2.5), (e) => e instanceof MeshError);
});

test('defaultDetail and detailForTriangles', () => {
    assert.deepEqual(shapeNames().map(defaultDetail), [32, 24, 8]);
    assert.equal(detailForTriangles('sphere', 3968), 32);
    assert.equal(detailForTriangles('torus', 2304), 24);
    assert.equal(detailForTriangles('cube', 768), 8);
    assert.equal(detailForTriangles('cube', 1), 1);
    assert.equal(detailForTriangles('sphere', 0), 2);
    assert.equal(detailForTriangles('torus', 1e12), 2048);
});
