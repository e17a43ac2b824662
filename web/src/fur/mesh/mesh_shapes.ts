// The procedural meshes of the fur track: a sphere, a torus and a cube, each
// at any tessellation (framework/src/fur/mesh/mesh_shapes.cpp, ported line
// for line: the same vertex and triangle order, computed in double and
// stored as float, so the vertices are the native ones).
//   sphere: 2*DETAIL slices, DETAIL stacks, 4*DETAIL^2 - 4*DETAIL triangles,
//           radius 1; the poles are fans, so no triangle is degenerate;
//   torus:  ring radius 1, tube radius 0.4, 4*DETAIL^2 triangles;
//   cube:   side 2, each face a DETAIL x DETAIL grid, 12*DETAIL^2 triangles,
//           one normal per face (sharp edges).
// Every shape has a texture seam, where vertices repeat (same position,
// other texture coordinate); the sphere's poles repeat too.
import { Mesh, MeshError } from './mesh.js';

type DVec3 = [number, number, number];

const MAX_DETAIL = 2048; // 16M triangles for the sphere: far past any use
const SHAPES = ['sphere', 'torus', 'cube'];

// glm::normalize on a dvec3: v * (1 / sqrt(dot(v, v))).
function normalize(v: DVec3): DVec3 {
    const s = 1 / Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return [v[0] * s, v[1] * s, v[2] * s];
}

// A mesh whose arrays are filled in place, sized up front.
class Builder {
    vertices = 0;
    triangles = 0;
    readonly mesh: Mesh;

    constructor(vertexCount: number, triangleCount: number) {
        this.mesh = {
            name: '',
            positions: new Float32Array(3 * vertexCount),
            normals: new Float32Array(3 * vertexCount),
            uvs: new Float32Array(2 * vertexCount),
            indices: new Uint32Array(3 * triangleCount),
        };
    }

    addVertex(p: DVec3, n: DVec3, u: number, v: number): void {
        this.mesh.positions.set(p, 3 * this.vertices);
        this.mesh.normals.set(n, 3 * this.vertices);
        this.mesh.uvs.set([u, v], 2 * this.vertices);
        ++this.vertices;
    }

    addTriangle(a: number, b: number, c: number): void {
        this.mesh.indices.set([a, b, c], 3 * this.triangles);
        ++this.triangles;
    }
}

// A (columns+1) x (rows+1) grid of vertices from POINT(u, v), u, v in [0, 1];
// NORMAL likewise. SKIP(row) leaves out one triangle of each cell in that
// row (the sphere's pole fans): 0 keeps both, 1 drops the first, 2 the
// second. WRAPU / WRAPV: the shape closes along u / v, so the last column /
// row is computed from 0, not 1: the seam's vertices share their positions
// exactly (sin(2 pi) is not 0 in floating point) and adjacency finds the
// neighbours across it.
function addGrid(
    m: Builder,
    columns: number,
    rows: number,
    wrapU: boolean,
    wrapV: boolean,
    point: (u: number, v: number) => DVec3,
    normal: (u: number, v: number) => DVec3,
    skip: (row: number) => number,
): void {
    const base = m.vertices;
    for (let r = 0; r <= rows; ++r)
        for (let c = 0; c <= columns; ++c) {
            const u = c / columns;
            const v = r / rows;
            const pu = wrapU && c === columns ? 0 : u;
            const pv = wrapV && r === rows ? 0 : v;
            m.addVertex(point(pu, pv), normalize(normal(pu, pv)), u, v);
        }
    const at = (r: number, c: number) => base + r * (columns + 1) + c;
    for (let r = 0; r < rows; ++r)
        for (let c = 0; c < columns; ++c) {
            const s = skip(r);
            if (s !== 1) m.addTriangle(at(r, c), at(r, c + 1), at(r + 1, c + 1));
            if (s !== 2) m.addTriangle(at(r, c), at(r + 1, c + 1), at(r + 1, c));
        }
}

function sphere(detail: number): Mesh {
    const columns = 2 * detail;
    const rows = detail;
    const m = new Builder((columns + 1) * (rows + 1), 2 * columns * rows - 2 * columns);
    // u runs around (longitude), v from the south pole (v = 0) to the north.
    const p = (u: number, v: number): DVec3 => {
        // The poles exactly: sin(pi) is not 0 in floating point either.
        if (v <= 0 || v >= 1) return [0, v <= 0 ? -1 : 1, 0];
        const phi = 2 * Math.PI * u;
        const theta = Math.PI * v;
        return [-Math.sin(theta) * Math.sin(phi), -Math.cos(theta), -Math.sin(theta) * Math.cos(phi)];
    };
    // Row 0 touches the south pole, the last row the north pole: each of
    // their quads has one real triangle and one of zero area, left out.
    addGrid(m, columns, rows, true, false, p, p, (r) => (r === 0 ? 1 : r === rows - 1 ? 2 : 0));
    return m.mesh;
}

function torus(detail: number): Mesh {
    const columns = 2 * detail;
    const rows = detail;
    const m = new Builder((columns + 1) * (rows + 1), 2 * columns * rows);
    const ring = 1.0;
    const tube = 0.4;
    const centre = (u: number): DVec3 => {
        const a = 2 * Math.PI * u;
        return [ring * Math.cos(a), 0, -ring * Math.sin(a)];
    };
    const n = (u: number, v: number): DVec3 => {
        const a = 2 * Math.PI * u;
        const b = 2 * Math.PI * v;
        return [Math.cos(b) * Math.cos(a), Math.sin(b), -Math.cos(b) * Math.sin(a)];
    };
    const p = (u: number, v: number): DVec3 => {
        const c = centre(u);
        const d = n(u, v);
        return [c[0] + tube * d[0], c[1] + tube * d[1], c[2] + tube * d[2]];
    };
    addGrid(m, columns, rows, true, true, p, n, () => 0);
    return m.mesh;
}

function cube(detail: number): Mesh {
    const m = new Builder(6 * (detail + 1) * (detail + 1), 12 * detail * detail);
    // Each face: its normal and two axes along it, counter-clockwise from outside.
    const faces: { n: DVec3; u: DVec3; v: DVec3 }[] = [
        { n: [1, 0, 0], u: [0, 0, -1], v: [0, 1, 0] },
        { n: [-1, 0, 0], u: [0, 0, 1], v: [0, 1, 0] },
        { n: [0, 1, 0], u: [1, 0, 0], v: [0, 0, -1] },
        { n: [0, -1, 0], u: [1, 0, 0], v: [0, 0, 1] },
        { n: [0, 0, 1], u: [1, 0, 0], v: [0, 1, 0] },
        { n: [0, 0, -1], u: [-1, 0, 0], v: [0, 1, 0] },
    ];
    for (const f of faces) {
        // f.n + (2u - 1) * f.u + (2v - 1) * f.v, in glm's order.
        const point = (u: number, v: number): DVec3 => {
            const su = 2 * u - 1;
            const sv = 2 * v - 1;
            return [0, 1, 2].map((k) => f.n[k]! + su * f.u[k]! + sv * f.v[k]!) as DVec3;
        };
        addGrid(m, detail, detail, false, false, point, () => f.n, () => 0);
    }
    return m.mesh;
}

// The shapes makeShape knows, for messages and the page's mesh key.
export function shapeNames(): readonly string[] {
    return SHAPES;
}

// The mesh of SHAPE at DETAIL (at least 2 for the sphere and torus, 1 for
// the cube), named "SHAPE-TRIANGLES". Throws MeshError for an unknown shape
// or a detail out of range.
export function makeShape(shape: string, detail: number): Mesh {
    const least = shape === 'cube' ? 1 : 2;
    if (!SHAPES.includes(shape)) throw new MeshError(`unknown mesh shape '${shape}' (known: sphere, torus, cube)`);
    if (!Number.isInteger(detail) || detail < least || detail > MAX_DETAIL)
        throw new MeshError(`mesh ${shape}: detail must be between ${least} and ${MAX_DETAIL} (not ${detail})`);
    const m = shape === 'sphere' ? sphere(detail) : shape === 'torus' ? torus(detail) : cube(detail);
    m.name = `${shape}-${m.indices.length / 3}`;
    return m;
}

// The tessellation the demo scenes use for SHAPE (a few thousand triangles).
export function defaultDetail(shape: string): number {
    return shape === 'cube' ? 8 : shape === 'torus' ? 24 : 32;
}

// The detail that gives SHAPE about TRIANGLES triangles (the bench's series).
export function detailForTriangles(shape: string, triangles: number): number {
    const t = Math.max(1, Math.trunc(triangles));
    const d = shape === 'cube' ? Math.sqrt(t / 12) : shape === 'torus' ? Math.sqrt(t / 4) : 0.5 + Math.sqrt(0.25 + t / 4); // 4d^2 - 4d = t
    const rounded = Math.round(d); // std::lround: d > 0, so halves go up either way
    return Math.min(Math.max(rounded, shape === 'cube' ? 1 : 2), MAX_DETAIL);
}
