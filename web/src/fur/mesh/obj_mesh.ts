// A triangle mesh from a Wavefront OBJ file: the port of the native
// loadObjMesh (framework/src/fur/mesh/obj_mesh.cpp). Every object and group
// as one mesh; polygons are triangulated as tinyobjloader does
// (obj_triangulate.ts), and one vertex is made per distinct (position,
// normal, texture coordinate) triple, in the order the triangles first name
// them. Missing normals are computed (smooth, area-weighted) and missing
// texture coordinates by spherical projection; a file that mixes faces with
// and without them gets them computed for every face. Materials are ignored.
import { length } from '../../scene/float32.js';
import { computeSmoothNormals, computeSphericalUvs, Mesh, validateMesh } from './mesh.js';
import { ObjCorner, ObjData, ObjError, readObj } from './obj_reader.js';
import { triangulate } from './obj_triangulate.js';

export { ObjError };

// Forward references are legal in OBJ (natively too): indices are checked
// against the whole file.
function checkIndices(data: ObjData, file: string): void {
    const counts = { v: data.vertices.length / 3, vt: data.texcoords.length / 2, vn: data.normals.length / 3 };
    const names = { v: 'vertex', vt: 'texture coordinate', vn: 'normal' };
    for (const face of data.faces)
        for (const c of face.corners)
            for (const kind of ['v', 'vt', 'vn'] as const)
                if (c[kind] >= counts[kind])
                    throw new ObjError(`${file}:${face.line}: a face names ${names[kind]} ${c[kind] + 1}, which does not exist`);
}

// Normals as written may not be unit length; a zero (or non-finite) one is
// replaced by the smooth normal there, the others are kept (in float).
function normaliseGivenNormals(mesh: Mesh): void {
    const bad: number[] = [];
    const n = mesh.normals;
    for (let k = 0; k < n.length / 3; ++k) {
        const l = length([n[3 * k]!, n[3 * k + 1]!, n[3 * k + 2]!]);
        if (l > 0 && Number.isFinite(l)) for (let i = 3 * k; i < 3 * k + 3; ++i) n[i] = n[i]! / l;
        else bad.push(k);
    }
    if (bad.length === 0) return;
    const smooth: Mesh = { ...mesh };
    computeSmoothNormals(smooth);
    for (const k of bad) n.set(smooth.normals.subarray(3 * k, 3 * k + 3), 3 * k);
}

// The mesh in TEXT, the contents of an OBJ file, named SHOWNNAME in messages
// and as the mesh's name. Throws ObjError ("FILE:LINE: what", or
// "FILE: what" for the file as a whole) or MeshError.
export function parseObjMesh(text: string, shownName: string): Mesh {
    const data = readObj(text, shownName);
    checkIndices(data, shownName);
    const corners: ObjCorner[] = [];
    for (const face of data.faces) triangulate(face.corners, data.vertices, corners);
    if (corners.length === 0) throw new ObjError(`${shownName}: the file has no faces (f lines)`);
    // Does every face corner name a normal / a texture coordinate?
    const allNormals = corners.every((c) => c.vn >= 0);
    const allUvs = corners.every((c) => c.vt >= 0);

    const positions: number[] = [];
    const normals: number[] = [];
    const uvs: number[] = [];
    const indices = new Uint32Array(corners.length);
    const vertexOf = new Map<string, number>();
    corners.forEach((c, i) => {
        const n = allNormals ? c.vn : -1;
        const t = allUvs ? c.vt : -1;
        const key = `${c.v},${n},${t}`;
        let index = vertexOf.get(key);
        if (index === undefined) {
            index = vertexOf.size;
            vertexOf.set(key, index);
            positions.push(...data.vertices.slice(3 * c.v, 3 * c.v + 3));
            if (n >= 0) normals.push(...data.normals.slice(3 * n, 3 * n + 3));
            if (t >= 0) uvs.push(...data.texcoords.slice(2 * t, 2 * t + 2));
        }
        indices[i] = index;
    });
    const mesh: Mesh = {
        name: shownName,
        positions: Float32Array.from(positions),
        normals: Float32Array.from(normals),
        uvs: Float32Array.from(uvs),
        indices,
    };
    if (allNormals) normaliseGivenNormals(mesh);
    else computeSmoothNormals(mesh);
    if (!allUvs) computeSphericalUvs(mesh);
    validateMesh(mesh);
    return mesh;
}
