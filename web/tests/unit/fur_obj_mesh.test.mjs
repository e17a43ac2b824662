// OBJ meshes (obj_mesh.ts, obj_reader.ts, obj_triangulate.ts, obj_number.ts):
// the same mesh as the native build (tinyobjloader plus framework/src/fur/
// mesh/obj_mesh.cpp) - checked through a digest of every float's bits, every
// index and the edge adjacency, taken from the native code on the same text
// - and a "FILE:LINE: what" error for every malformed line.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

import { buildEdgeAdjacency } from '../../dist/fur/mesh/adjacency.js';
import { MeshError } from '../../dist/fur/mesh/mesh.js';
import { ObjError, parseObjMesh } from '../../dist/fur/mesh/obj_mesh.js';
import { parseObjNumber } from '../../dist/fur/mesh/obj_number.js';
import { dumpMesh, sha256 } from './mesh_dump.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');


const TEXTS = {
  // Quads split along either diagonal, a concave pentagon and a star, full
  // v/vt/vn corners, relative indices, statements that change nothing, CRLF.
  full: [
    '# full corners', 'mtllib none.mtl', 'o thing', 'g a b', 's 1', 'usemtl skin',
    'v 0 0 0', 'v 1.000000 0 0', 'v 1 1.25e0 0', 'v 0 1 0', 'v 0.123456789012 0.5 1.0E-1', 'v -0.5 0.5 0.',
    'v 2 0 0', 'v 3 0 0', 'v 3 1 0', 'v 2.5 0.3 0', 'v 2 1 0',
    'vt 0 0', 'vt 1 0 0', 'vt 1 1', 'vt 0.3333333333',
    'vn 0 0 1', 'vn 0 0 2.5', 'vn 0.1 0.2 0.97', 'vn 0 0 0',
    'f 1/1/1 2/2/2 3/3/3 4/4/1',
    'f -10/-1/-1 -9/-2/-2 -8/-3/-3 -11/-4/-4',
    'f 1/1/3 4/2/2 6/3/1 5/4/3',
    'f 7/1/1 8/2/2 9/3/3 10/4/1 11/1/2',
    's off', 'g', 'f 7/1/4 8/2/4 9/3/4',
  ].join('\r\n') + '\r\n',
  // Faces without normals or uvs among others: both are computed everywhere.
  mixed: [
    'v -1 -1 -1', 'v 1 -1 -1', 'v 1 1 -1', 'v -1 1 -1', 'v -1 -1 1', 'v 1 -1 1', 'v 1 1 1', 'v -1 1 1',
    'vt 0 0', 'vt 1 0', 'vt 1 1', 'vt 0 1', 'vn 0 0 -1',
    'f 1/1 4/2 3/3 2/4', 'f 5 6 7 8', 'f 1//1 2//1 6//1 5//1', 'f 2 3 7 6', 'f 3 4 8 7', 'f 4/1/1 1/2/1 5/3/1 8/4/1',
  ].join('\n'),
  // An eight-pointed star in the xz plane and a spiral-ish 7-gon, only v.
  polygons: [
    'v 0 0 1', 'v 0.2 0 0.2', 'v 1 0 0', 'v 0.2 0 -0.2', 'v 0 0 -1', 'v -0.2 0 -0.2', 'v -1 0 0', 'v -0.2 0 0.2',
    'f 1 2 3 4 5 6 7 8',
    'v 0 5 0', 'v 1 5.1 0', 'v 1.2 6 0.3', 'v 0.1 6.5 0.1', 'v -0.7 6.1 0', 'v -0.2 5.6 -0.1', 'v -0.9 5.2 0',
    'f 9 10 11 12 13 14 15',
    'f 1 3 5',
  ].join('\n'),
};

const NATIVE = {
    full: '110fbb57926873961978de6f96c0f0fe2d6b0f776613c141c03692521f26ced3',
    mixed: '6aa1e2cfe01dcf5ae466895d0e3870e280338622bbccd13e92cc1a6a4d9de84e',
    polygons: 'a5c6673c6b679a78fde200d3dc560cc07ebbd338dd72443e0c022465573d1cf0',
};

test('assets/meshes/blob.obj: the native mesh (482 vertices, 960 triangles)', () => {
    const m = parseObjMesh(readFileSync(path.join(ROOT, 'assets/meshes/blob.obj'), 'utf8'), 'assets/meshes/blob.obj');
    assert.equal(m.name, 'assets/meshes/blob.obj');
    assert.equal(m.positions.length / 3, 482);
    assert.equal(m.indices.length / 3, 960); // 64 triangles and 448 quads
    const a = buildEdgeAdjacency(m);
    assert.equal(a.boundaryEdges, 0);
    assert.equal(a.indices.length / 4, 1440);
    assert.equal(sha256(dumpMesh(m, false)), 'ed0518f4cfb26b145f235b5bf40fcda1fdf51fb01ed4e0a42eea8a9916e113ed');
});

for (const [name, digest] of Object.entries(NATIVE))
    test(`OBJ "${name}": the native floats, triangles and edges`, () => {
        assert.equal(sha256(dumpMesh(parseObjMesh(TEXTS[name], `${name}.obj`), false)), digest);
    });

test('counts: quads split in two, polygons into n - 2, one vertex per distinct corner', () => {
    const full = parseObjMesh(TEXTS.full, 'full.obj');
    assert.equal(full.indices.length / 3, 2 + 2 + 2 + 3 + 1);
    const mixed = parseObjMesh(TEXTS.mixed, 'mixed.obj');
    // Some faces lack normals and uvs: both are computed, so corners key by position only.
    assert.equal(mixed.positions.length / 3, 8);
    assert.equal(mixed.indices.length / 3, 12);
    const polygons = parseObjMesh(TEXTS.polygons, 'p.obj');
    assert.equal(polygons.indices.length / 3, 6 + 5 + 1);
    // Given normals are normalised; the zero one is replaced by a smooth one.
    for (let i = 0; i < full.normals.length; i += 3)
        assert.ok(Math.abs(Math.hypot(full.normals[i], full.normals[i + 1], full.normals[i + 2]) - 1) < 1e-6);
});

test('numbers are read as tinyobjloader reads them', () => {
    assert.equal(parseObjNumber('1.5'), 1.5);
    assert.equal(parseObjNumber('-0'), -0);
    assert.equal(parseObjNumber('.5'), 0.5);
    assert.equal(parseObjNumber('2.'), 2);
    assert.equal(parseObjNumber('+1e2'), 100);
    assert.equal(parseObjNumber('1.25E-1'), 0.125);
    assert.equal(parseObjNumber('0.1'), Math.fround(0.1));
    for (const bad of ['', '-', '.', 'e5', '1e', '1.5abc', 'nan', 'inf', '1,5', '0x10']) assert.equal(parseObjNumber(bad), null, bad);
});

const BAD = [
    ['v 1 2', 'bad.obj:1: expected "v x y z"'],
    ['v 1 2 abc', 'bad.obj:1: "abc" is not a number'],
    ['v 0 0 0\nv 1e39 0 0', 'bad.obj:2: 1e39 is not a finite number (as a float)'],
    ['vn 0 1', 'bad.obj:1: expected "vn x y z"'],
    ['vt', 'bad.obj:1: expected "vt u v"'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2', 'bad.obj:4: a face needs at least 3 corners'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0', 'bad.obj:4: vertex index 0 (OBJ counts from 1)'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x', 'bad.obj:4: "x" is not a vertex index'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\n\n# gap\nf 1 2 4', 'bad.obj:6: a face names vertex 4, which does not exist'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4', 'bad.obj:4: relative vertex index -4 counts back past the first vertex'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1', 'bad.obj:4: a face names texture coordinate 1, which does not exist'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2', 'bad.obj:5: a face names normal 2, which does not exist'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2/ 3/', 'bad.obj:4: "1/" is not a face corner (v, v/vt, v//vn or v/vt/vn)'],
    ['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3', 'bad.obj:4: "1/1/1/1" is not a face corner (v, v/vt, v//vn or v/vt/vn)'],
    ['v 0 0 0\r\nvv 1 0 0', 'bad.obj:2: unknown statement "vv"'],
    ['# nothing\nv 0 0 0\n', 'bad.obj: the file has no faces (f lines)'],
    ['', 'bad.obj: the file has no faces (f lines)'],
];

for (const [text, message] of BAD)
    test(`malformed: ${JSON.stringify(text.split(/\r?\n/).at(-1))} -> ${message}`, () => {
        assert.throws(() => parseObjMesh(text, 'bad.obj'), (e) => {
            assert.ok(e instanceof ObjError && e instanceof MeshError, String(e));
            assert.equal(e.message, message);
            return true;
        });
    });

test('what is ignored: comments, groups, materials, smoothing, lines, blank lines', () => {
    const m = parseObjMesh('# c\n\n  \t\nmtllib x.mtl\no a\ng b\ns 1\nusemtl m\nv 0 0 0 # end\nv 1 0 0 1\nv 0 1 0 0.5 0.5 0.5\nl 1 2\nf 1 2 3 # tri\n', 'ok.obj');
    assert.equal(m.indices.length, 3);
    assert.equal(m.positions.length, 9);
    // A face whose texture coordinates are all given: no spherical projection.
    const uv = parseObjMesh('v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25\nvt 0.5 0.75 0\nf 1/1 2/2 3/1\n', 'uv.obj');
    assert.deepEqual([...uv.uvs], [0.25, 0, 0.5, 0.75, 0.25, 0]);
    // A degenerate mesh is still a mesh (no triangles with area, but valid indices).
    assert.equal(parseObjMesh('v 0 0 0\nf 1 1 1\n', 'd.obj').normals[1], 1);
});
