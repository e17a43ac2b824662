// The objects of a scene file (framework/src/raytrace/scene/scene_shapes.cpp):
// spheres, planes, discs, triangles, rectangles and boxes (both become
// triangles, in the native order and winding) and tori. Materials must be
// read first: objects refer to them by name.
import { rotationDouble, radiansDouble, transformDouble } from './box_rotation.js';
import { add, cross, f32, length, sub } from './float32.js';
import { Json } from './json_parse.js';
import { at, has, JsonReader } from './json_reader.js';
import { Material, MaterialType, Scene, Sphere, Torus, Vec3 } from './scene.js';

function item(list: string, i: number): string {
    return `${list}[${i}]`;
}

// A material with the native defaults.
export function defaultMaterial(name: string): Material {
    return {
        name,
        type: MaterialType.Plastic,
        ior: f32(1.5),
        n: [0, 0, 0],
        k: [0, 0, 0],
        ambient: [0, 0, 0],
        diffuse: [1, 1, 1],
        specular: [0, 0, 0],
        shininess: 30,
        texture: -1,
        normalMap: -1,
    };
}

// "material": a name from "materials", or "color": a flat colour (a material
// of its own with that diffuse colour, named after the object).
function materialOf(r: JsonReader, obj: Json, where: string, scene: Scene): number {
    if (has(obj, 'material')) {
        const name = at(obj, 'material');
        if (typeof name !== 'string') r.fail(`${where}.material`, 'expected the name of a material');
        const index = scene.materials.findIndex((m) => m.name === name);
        if (index < 0) r.fail(`${where}.material`, `unknown material "${name}"`);
        return index;
    }
    const flat = defaultMaterial(where);
    flat.diffuse = r.color(r.member(obj, where, 'color'), `${where}.color`);
    scene.materials.push(flat);
    return scene.materials.length - 1;
}

function readSpheres(r: JsonReader, doc: Json, scene: Scene): void {
    const spheres = r.member(doc, 'scene', 'spheres');
    if (!Array.isArray(spheres)) r.fail('spheres', 'expected a list');
    spheres.forEach((s, i) => {
        const where = item('spheres', i);
        r.allowOnly(s, where, ['center', 'radius', 'material', 'color', 'motion']);
        const sphere: Sphere = {
            center: r.vec3(r.member(s, where, 'center'), `${where}.center`),
            radius: r.positive(r.member(s, where, 'radius'), `${where}.radius`),
            material: 0,
            motion: { axis: [0, 0, 0], amplitude: 0, periodSeconds: 1 },
        };
        sphere.material = materialOf(r, s, where, scene);
        if (has(s, 'motion')) {
            const m = at(s, 'motion');
            const mw = `${where}.motion`;
            r.allowOnly(m, mw, ['axis', 'amplitude', 'period']);
            sphere.motion.axis = r.vec3(r.member(m, mw, 'axis'), `${mw}.axis`);
            sphere.motion.amplitude = r.number(r.member(m, mw, 'amplitude'), `${mw}.amplitude`);
            sphere.motion.periodSeconds = r.positive(r.member(m, mw, 'period'), `${mw}.period`);
        }
        scene.spheres.push(sphere);
    });
}

function readPlanes(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'planes').forEach((p, i) => {
        const where = item('planes', i);
        r.allowOnly(p, where, ['point', 'normal', 'tile_size', 'material', 'color']);
        const point = r.vec3(r.member(p, where, 'point'), `${where}.point`);
        const normal = r.direction(r.member(p, where, 'normal'), `${where}.normal`);
        const tileSize = has(p, 'tile_size') ? r.positive(at(p, 'tile_size'), `${where}.tile_size`) : 1;
        scene.planes.push({ point, normal, tileSize, material: materialOf(r, p, where, scene) });
    });
}

function readDiscs(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'discs').forEach((d, i) => {
        const where = item('discs', i);
        r.allowOnly(d, where, ['center', 'normal', 'radius', 'material', 'color']);
        const center = r.vec3(r.member(d, where, 'center'), `${where}.center`);
        const normal = r.direction(r.member(d, where, 'normal'), `${where}.normal`);
        const radius = r.positive(r.member(d, where, 'radius'), `${where}.radius`);
        scene.discs.push({ center, normal, radius, material: materialOf(r, d, where, scene) });
    });
}

function addTriangle(r: JsonReader, where: string, scene: Scene, a: Vec3, b: Vec3, c: Vec3, material: number): void {
    if (!(length(cross(sub(b, a), sub(c, a))) > f32(1e-8))) r.fail(where, 'degenerate: the corners lie on one line');
    scene.triangles.push({ vertices: [a, b, c], material });
}

function readTriangles(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'triangles').forEach((t, i) => {
        const where = item('triangles', i);
        r.allowOnly(t, where, ['vertices', 'material', 'color']);
        const v = r.member(t, where, 'vertices');
        if (!Array.isArray(v) || v.length !== 3) r.fail(`${where}.vertices`, 'expected three [x, y, z] corners');
        const material = materialOf(r, t, where, scene);
        // In order: with two bad corners the first is named, as natively.
        const a = r.vec3(v[0]!, `${where}.vertices[0]`);
        const b = r.vec3(v[1]!, `${where}.vertices[1]`);
        const c = r.vec3(v[2]!, `${where}.vertices[2]`);
        addTriangle(r, where, scene, a, b, c, material);
    });
}

// corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v: its
// front (normal) is cross(edge_u, edge_v).
function readRectangles(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'rectangles').forEach((rect, i) => {
        const where = item('rectangles', i);
        r.allowOnly(rect, where, ['corner', 'edge_u', 'edge_v', 'material', 'color']);
        const p = r.vec3(r.member(rect, where, 'corner'), `${where}.corner`);
        const u = r.vec3(r.member(rect, where, 'edge_u'), `${where}.edge_u`);
        const v = r.vec3(r.member(rect, where, 'edge_v'), `${where}.edge_v`);
        const material = materialOf(r, rect, where, scene);
        addTriangle(r, where, scene, p, add(p, u), add(add(p, u), v), material);
        addTriangle(r, where, scene, p, add(add(p, u), v), add(p, v), material);
    });
}

// An axis-aligned box turned by rotation_y degrees about its vertical axis:
// 12 triangles, every face counter-clockwise seen from outside.
function readBoxes(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'boxes').forEach((box, i) => {
        const where = item('boxes', i);
        r.allowOnly(box, where, ['center', 'size', 'rotation_y', 'material', 'color']);
        const center = r.vec3(r.member(box, where, 'center'), `${where}.center`);
        const size = r.vec3(r.member(box, where, 'size'), `${where}.size`);
        for (const s of size) if (!(s > 0)) r.fail(`${where}.size`, 'every side must be positive');
        const turn = has(box, 'rotation_y') ? r.number(at(box, 'rotation_y'), `${where}.rotation_y`) : 0;
        const material = materialOf(r, box, where, scene);
        const turning = rotationDouble(radiansDouble(turn), [0, 1, 0]);
        const corner = (c: number[]): Vec3 => {
            const local = [0, 1, 2].map((k) => (c[k]! - 0.5) * size[k]!);
            const w = transformDouble(turning, [local[0]!, local[1]!, local[2]!, 1]);
            return add(center, [f32(w[0]!), f32(w[1]!), f32(w[2]!)]);
        };
        // Each face: the axis it is normal to, and which side.
        for (let axis = 0; axis < 3; ++axis) {
            for (let side = 0; side < 2; ++side) {
                let u = (axis + 1) % 3;
                let v = (axis + 2) % 3;
                if (side === 0) [u, v] = [v, u]; // keeps the face counter-clockwise from outside
                const atCorner = (du: number, dv: number): Vec3 => {
                    const c = [0, 0, 0];
                    c[axis] = side;
                    c[u] = du;
                    c[v] = dv;
                    return corner(c);
                };
                addTriangle(r, where, scene, atCorner(0, 0), atCorner(1, 0), atCorner(1, 1), material);
                addTriangle(r, where, scene, atCorner(0, 0), atCorner(1, 1), atCorner(0, 1), material);
            }
        }
    });
}

function readTori(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'tori').forEach((t, i) => {
        const where = item('tori', i);
        r.allowOnly(t, where, ['center', 'axis', 'major_radius', 'minor_radius', 'spin', 'material', 'color']);
        const torus: Torus = {
            center: r.vec3(r.member(t, where, 'center'), `${where}.center`),
            axis: r.direction(r.member(t, where, 'axis'), `${where}.axis`),
            majorRadius: r.positive(r.member(t, where, 'major_radius'), `${where}.major_radius`),
            minorRadius: r.positive(r.member(t, where, 'minor_radius'), `${where}.minor_radius`),
            spinAxis: [0, 1, 0],
            spinPeriod: 0,
            material: 0,
        };
        if (torus.minorRadius >= torus.majorRadius) r.fail(where, 'minor_radius must be smaller than major_radius');
        if (has(t, 'spin')) {
            const spin = at(t, 'spin');
            const sw = `${where}.spin`;
            r.allowOnly(spin, sw, ['axis', 'period']);
            torus.spinAxis = r.direction(r.member(spin, sw, 'axis'), `${sw}.axis`);
            torus.spinPeriod = r.positive(r.member(spin, sw, 'period'), `${sw}.period`);
        }
        torus.material = materialOf(r, t, where, scene);
        scene.tori.push(torus);
    });
}

// Texture coordinates exist on spheres, planes and discs; a tangent (for
// normal maps) on spheres only. Anything else would render flat or black.
function checkTexturesFit(r: JsonReader, scene: Scene): void {
    const check = (list: string, i: number, material: number, uv: boolean, tangent: boolean) => {
        const m = scene.materials[material]!;
        const where = `${item(list, i)}.material`;
        if (m.texture >= 0 && !uv)
            r.fail(where, `material "${m.name}" has a texture, but ${list} have no texture coordinates (spheres, planes and discs do)`);
        if (m.normalMap >= 0 && !tangent) r.fail(where, `material "${m.name}" has a normal map, but only spheres take normal maps`);
    };
    scene.planes.forEach((p, i) => check('planes', i, p.material, true, false));
    scene.discs.forEach((d, i) => check('discs', i, d.material, true, false));
    scene.triangles.forEach((t, i) => check('triangles', i, t.material, false, false));
    scene.tori.forEach((t, i) => check('tori', i, t.material, false, false));
}

export function readShapes(r: JsonReader, doc: Json, scene: Scene): void {
    readSpheres(r, doc, scene);
    readPlanes(r, doc, scene);
    readDiscs(r, doc, scene);
    readTriangles(r, doc, scene);
    readRectangles(r, doc, scene);
    readBoxes(r, doc, scene);
    readTori(r, doc, scene);
    checkTexturesFit(r, scene);
}
