// A fur scene (assets/scenes/fur/*.json): one mesh with a transform, a
// directional light, the camera, and the fur's parameters and textures. The
// port of the native loadFurScene (framework/src/fur/mesh/fur_scene.cpp):
// the same keys, defaults, checks in the same order and one-line messages
// "FILE: where: what", thrown as FurSceneError. One difference: files named
// in the scene become URLs resolved against the scene file's URL, and
// whether they exist is not checked here (a browser cannot look
// synchronously); the page reports a missing file when it fetches it.
import { f32 } from '../../scene/float32.js';
import { formatG } from '../../scene/format_g.js';
import { isObject, Json, JsonNumber } from '../../scene/json_parse.js';
import { at, has, JsonReader, parseJsonText, readSceneCamera, SceneError } from '../../scene/json_reader.js';
import type { CameraPose, Vec3 } from '../../scene/scene.js';
import { resolveAgainst } from '../../scene/scene_urls.js';
import { shapeNames } from './mesh_shapes.js';

export { modelMatrix } from './fur_model_matrix.js';

// A SceneError, so that code catching any scene problem catches this too.
export class FurSceneError extends SceneError {
    constructor(message: string) {
        super(message);
        this.name = 'FurSceneError';
    }
}

export interface FurMeshSpec {
    shape: string; // "sphere", "torus", "cube" (mesh_shapes.ts); '' when obj is set
    detail: number;
    obj: string; // URL of an OBJ file (obj_mesh.ts); '' when shape is set
}

export interface FurParameters {
    length: number; // world units at scale 1 (along the normal)
    shells: number; // layers drawn, the skin included
    patternScale: number; // pattern tiles per unit of texture coordinate
    shadowIntensity: number; // darkening at the root: 1 - intensity * (1 - layer)
    colorMap: string; // URLs
    pattern: string;
    finMap: string;
    // Stage f4: strands bend along gravity by up to this share of their
    // length; `strandDensity` roots per unit area; `strandSegments` segments.
    gravity: number;
    strandDensity: number;
    strandSegments: number;
}

export interface FurScene {
    file: string; // as shown in messages
    background: Vec3;
    camera: CameraPose;
    fovYDeg: number;
    mesh: FurMeshSpec;
    // Model transform: scale, then rotate about z, then x, then y (degrees;
    // y last, so that `spin`, degrees per second added to y, turns the model
    // about the world's vertical), then translate.
    translate: Vec3;
    rotateDeg: Vec3;
    scale: Vec3;
    spinDegPerSecond: number;
    lightDirection: Vec3; // toward the light, unit length
    lightColor: Vec3;
    ambient: Vec3;
    fur: FurParameters;
}

// JsonReader failing with FurSceneError, plus the fur scene's own checks.
class FurSceneReader extends JsonReader {
    constructor(
        file: string,
        private readonly fileUrl: string,
    ) {
        super(file);
    }

    override fail(where: string, what: string): never {
        throw new FurSceneError(`${this.file}: ${where}: ${what}`);
    }

    // A file named relative to the scene file, as a normalised URL (native:
    // existingFile, which also checks that it exists).
    fileUrlOf(v: Json, where: string): string {
        return resolveAgainst(this.fileUrl, this.string(v, where));
    }

    integer(v: Json, where: string, lo: number, hi: number): number {
        if (!(v instanceof JsonNumber && v.isInteger)) this.fail(where, 'expected a whole number');
        if (v.value < lo || v.value > hi) this.fail(where, `must be between ${lo} and ${hi}`);
        return v.value;
    }

    // LO and HI are floats, printed as "%.6g" (1e6 -> "1e+06").
    within(v: Json, where: string, lo: number, hi: number): number {
        const f = this.number(v, where);
        if (!(f >= lo && f <= hi)) this.fail(where, `must be between ${formatG(lo, 6)} and ${formatG(hi, 6)}`);
        return f;
    }
}

function readMesh(r: FurSceneReader, doc: Json, s: FurScene): void {
    const m = r.member(doc, 'scene', 'mesh');
    r.allowOnly(m, 'mesh', ['shape', 'detail', 'obj']);
    if (has(m, 'obj') === has(m, 'shape')) r.fail('mesh', 'give either "shape" (sphere, torus, cube) or "obj" (a file)');
    if (has(m, 'obj')) {
        s.mesh.obj = r.fileUrlOf(at(m, 'obj'), 'mesh.obj');
        return;
    }
    s.mesh.shape = r.string(at(m, 'shape'), 'mesh.shape');
    if (!shapeNames().includes(s.mesh.shape))
        r.fail('mesh.shape', `unknown shape '${s.mesh.shape}' (known: sphere, torus, cube)`);
    if (has(m, 'detail')) s.mesh.detail = r.integer(at(m, 'detail'), 'mesh.detail', 2, 512);
}

function readTransform(r: FurSceneReader, doc: Json, s: FurScene): void {
    if (!has(doc, 'transform')) return;
    // A transform that is not an object is ignored, as natively (contains()
    // is false on it).
    const t = at(doc, 'transform');
    r.allowOnly(t, 'transform', ['translate', 'rotate', 'scale', 'spin']);
    if (has(t, 'translate')) s.translate = r.vec3(at(t, 'translate'), 'transform.translate');
    if (has(t, 'rotate')) s.rotateDeg = r.vec3(at(t, 'rotate'), 'transform.rotate');
    if (has(t, 'scale')) {
        s.scale = r.vec3(at(t, 'scale'), 'transform.scale');
        for (const factor of s.scale)
            if (!(factor > 0))
                r.fail('transform.scale', 'every factor must be positive (a mirror would turn the triangles inside out)');
    }
    if (has(t, 'spin')) s.spinDegPerSecond = r.number(at(t, 'spin'), 'transform.spin');
}

function readLight(r: FurSceneReader, doc: Json, s: FurScene): void {
    const l = r.member(doc, 'scene', 'light');
    r.allowOnly(l, 'light', ['direction', 'color', 'ambient']);
    s.lightDirection = r.direction(r.member(l, 'light', 'direction'), 'light.direction');
    if (has(l, 'color')) s.lightColor = r.color(at(l, 'color'), 'light.color');
    if (has(l, 'ambient')) s.ambient = r.color(at(l, 'ambient'), 'light.ambient');
}

function readFur(r: FurSceneReader, doc: Json, s: FurScene): void {
    const f = r.member(doc, 'scene', 'fur');
    r.allowOnly(f, 'fur', ['length', 'shells', 'pattern_scale', 'shadow_intensity', 'color_map', 'pattern', 'fin_map', 'gravity', 'strand_density', 'strand_segments']);
    const p = s.fur;
    if (has(f, 'length')) p.length = r.positive(at(f, 'length'), 'fur.length');
    if (has(f, 'shells')) p.shells = r.integer(at(f, 'shells'), 'fur.shells', 1, 256);
    if (has(f, 'pattern_scale')) p.patternScale = r.positive(at(f, 'pattern_scale'), 'fur.pattern_scale');
    if (has(f, 'shadow_intensity')) p.shadowIntensity = r.within(at(f, 'shadow_intensity'), 'fur.shadow_intensity', 0, 1);
    p.colorMap = r.fileUrlOf(r.member(f, 'fur', 'color_map'), 'fur.color_map');
    p.pattern = r.fileUrlOf(r.member(f, 'fur', 'pattern'), 'fur.pattern');
    p.finMap = r.fileUrlOf(r.member(f, 'fur', 'fin_map'), 'fur.fin_map');
    if (has(f, 'gravity')) p.gravity = r.within(at(f, 'gravity'), 'fur.gravity', 0, 2);
    if (has(f, 'strand_density')) p.strandDensity = r.within(at(f, 'strand_density'), 'fur.strand_density', 1, 1e6);
    if (has(f, 'strand_segments')) p.strandSegments = r.integer(at(f, 'strand_segments'), 'fur.strand_segments', 1, 16);
}

// The native defaults (fur_scene.h), as floats.
function defaultFurScene(file: string): FurScene {
    return {
        file,
        background: [f32(0.1), f32(0.1), f32(0.1)],
        camera: { position: [0, 0, 0], yawDeg: 0, pitchDeg: 0 },
        fovYDeg: 45,
        mesh: { shape: '', detail: 16, obj: '' },
        translate: [0, 0, 0],
        rotateDeg: [0, 0, 0],
        scale: [1, 1, 1],
        spinDegPerSecond: 0,
        lightDirection: [0, 1, 0],
        lightColor: [1, 1, 1],
        ambient: [f32(0.15), f32(0.15), f32(0.15)],
        fur: {
            length: f32(0.2),
            shells: 30,
            patternScale: 8,
            shadowIntensity: f32(0.6),
            colorMap: '',
            pattern: '',
            finMap: '',
            gravity: f32(0.3),
            strandDensity: 600,
            strandSegments: 4,
        },
    };
}

// The fur scene in TEXT, the contents of the file at FILEURL (the files it
// names are relative to it), named SHOWNNAME in messages, as the native
// build shows it ("assets/scenes/fur/sphere.json"). Throws FurSceneError.
export function parseFurScene(text: string, fileUrl: string, shownName: string): FurScene {
    const s = defaultFurScene(shownName);
    let doc: Json;
    try {
        doc = parseJsonText(text, shownName);
    } catch (e) {
        if (e instanceof SceneError) throw new FurSceneError(e.message);
        throw e;
    }
    const r: FurSceneReader = new FurSceneReader(shownName, fileUrl);
    if (!isObject(doc)) r.fail('scene', 'expected an object');
    if (!doc.has('mesh') && (doc.has('spheres') || doc.has('materials')))
        r.fail('scene', 'a ray-tracing scene (it has spheres or materials, no mesh): fur stages draw fur scenes (assets/scenes/fur/)');
    r.allowOnly(doc, '', ['background', 'camera', 'mesh', 'transform', 'light', 'fur']);
    s.background = r.color(r.member(doc, 'scene', 'background'), 'background');
    const camera = readSceneCamera(r, doc);
    s.camera = camera.pose;
    s.fovYDeg = camera.fovYDeg;
    readMesh(r, doc, s);
    readTransform(r, doc, s);
    readLight(r, doc, s);
    readFur(r, doc, s);
    return s;
}

// Every file the scene needs besides itself: the OBJ file (if any), then
// the colour map, the pattern and the fin map.
export function furSceneFileUrls(scene: FurScene): string[] {
    const f = scene.fur;
    return [...(scene.mesh.obj ? [scene.mesh.obj] : []), f.colorMap, f.pattern, f.finMap];
}
