// Reading a scene file: the port of the native loadScene
// (framework/src/raytrace/scene/scene.cpp): the same keys, the same checks in
// the same order, the same one-line messages "FILE: where: what", thrown as
// SceneError. One difference: whether image files exist is not checked here
// (a browser cannot look synchronously); see sceneImageUrls.
import { f32 } from './float32.js';
import { isObject, Json, JsonNumber, objectKeys } from './json_parse.js';
import { at, has, JsonReader, parseJsonText, readSceneCamera, SceneError } from './json_reader.js';
import { MaterialType, Scene } from './scene.js';
import { defaultMaterial, readShapes } from './scene_shapes.js';
import { resolveAgainst, sceneImageUrls } from './scene_urls.js';

export { SceneError, sceneImageUrls };

// JsonReader with the scene file's URL, for the files a scene names.
class SceneReader extends JsonReader {
    constructor(
        file: string,
        private readonly fileUrl: string,
    ) {
        super(file);
    }

    // An image named relative to the scene file, as a normalised URL.
    imageUrl(v: Json, where: string): string {
        return resolveAgainst(this.fileUrl, this.string(v, where));
    }
}

// The texture layer of an image; an image used twice shares its layer.
function textureLayer(scene: Scene, url: string): number {
    const i = scene.textures.indexOf(url);
    if (i >= 0) return i;
    scene.textures.push(url);
    return scene.textures.length - 1;
}

function materialType(r: JsonReader, m: Json, where: string): MaterialType {
    const type = has(m, 'type') ? r.string(at(m, 'type'), `${where}.type`) : 'plastic';
    const types: Record<string, MaterialType> = {
        plastic: MaterialType.Plastic,
        mirror: MaterialType.Mirror,
        glass: MaterialType.Glass,
        metal: MaterialType.Metal,
    };
    if (!Object.hasOwn(types, type)) r.fail(`${where}.type`, `unknown type "${type}" (plastic, mirror, glass or metal)`);
    return types[type]!;
}

// Materials get their indices in key order (the native std::map's).
function readMaterials(r: SceneReader, doc: Json, scene: Scene): void {
    if (!has(doc, 'materials')) return;
    const materials = at(doc, 'materials');
    if (!isObject(materials)) r.fail('materials', 'expected an object of named materials');
    for (const name of objectKeys(materials)) {
        const m = materials.get(name)!;
        const where = `materials.${name}`;
        r.allowOnly(m, where, ['ambient', 'diffuse', 'specular', 'shininess', 'type', 'ior', 'n', 'k', 'texture', 'normal_map']);
        const mat = defaultMaterial(name);
        mat.ambient = r.color(r.member(m, where, 'ambient'), `${where}.ambient`);
        mat.diffuse = r.color(r.member(m, where, 'diffuse'), `${where}.diffuse`);
        mat.specular = r.color(r.member(m, where, 'specular'), `${where}.specular`);
        mat.shininess = r.positive(r.member(m, where, 'shininess'), `${where}.shininess`);
        mat.type = materialType(r, m, where);
        if (mat.type === MaterialType.Glass) {
            mat.ior = r.positive(r.member(m, where, 'ior'), `${where}.ior`);
            if (mat.ior < 1 || mat.ior > 4) r.fail(`${where}.ior`, 'index of refraction must lie in [1, 4]');
        } else if (mat.type === MaterialType.Metal) {
            mat.n = r.vec3(r.member(m, where, 'n'), `${where}.n`);
            mat.k = r.vec3(r.member(m, where, 'k'), `${where}.k`);
            for (let c = 0; c < 3; ++c)
                if (mat.n[c]! <= 0 || mat.k[c]! < 0) r.fail(where, 'n must be positive and k not negative');
        }
        if (has(m, 'texture')) mat.texture = textureLayer(scene, r.imageUrl(at(m, 'texture'), `${where}.texture`));
        if (has(m, 'normal_map')) mat.normalMap = textureLayer(scene, r.imageUrl(at(m, 'normal_map'), `${where}.normal_map`));
        scene.materials.push(mat);
    }
}

function readLights(r: JsonReader, doc: Json, scene: Scene): void {
    r.optionalList(doc, 'lights').forEach((light, i) => {
        const where = `lights[${i}]`;
        r.allowOnly(light, where, ['position', 'color']);
        const position = r.vec3(r.member(light, where, 'position'), `${where}.position`);
        const color = r.color(r.member(light, where, 'color'), `${where}.color`);
        scene.lights.push({ position, color });
    });
}

// "sky_box": six image files, in the order +x, -x, +y, -y, +z, -z.
function readSkyBox(r: SceneReader, doc: Json, scene: Scene): void {
    if (!has(doc, 'sky_box')) return;
    const faces = at(doc, 'sky_box');
    if (!Array.isArray(faces) || faces.length !== 6) r.fail('sky_box', 'expected six image files: +x, -x, +y, -y, +z, -z');
    scene.skyBox = faces.map((face, i) => r.imageUrl(face, `sky_box[${i}]`));
}

function readGlow(r: JsonReader, doc: Json, scene: Scene): void {
    if (!has(doc, 'glow')) return;
    const g = at(doc, 'glow');
    r.allowOnly(g, 'glow', ['sphere', 'color', 'size']);
    const sphere = r.member(g, 'glow', 'sphere');
    if (!(sphere instanceof JsonNumber && sphere.isInteger) || sphere.value < 0 || sphere.value >= scene.spheres.length)
        r.fail('glow.sphere', `expected the index of a sphere (0..${scene.spheres.length - 1})`);
    scene.glow.sphere = sphere.value;
    if (has(g, 'color')) scene.glow.color = r.color(at(g, 'color'), 'glow.color');
    if (has(g, 'size')) scene.glow.size = r.positive(at(g, 'size'), 'glow.size');
}

// The scene in TEXT, the contents of the file at FILEURL (image paths are
// relative to it), named SHOWNNAME in messages and in the baked shader, as
// the native build shows it ("assets/scenes/lite.json"). Throws SceneError.
export function parseScene(text: string, fileUrl: string, shownName: string): Scene {
    const scene: Scene = {
        file: shownName,
        background: [0, 0, 0],
        camera: { position: [0, 0, 0], yawDeg: 0, pitchDeg: 0 },
        fovYDeg: 0,
        materials: [],
        lights: [],
        spheres: [],
        planes: [],
        discs: [],
        triangles: [],
        tori: [],
        textures: [],
        skyBox: null,
        glow: { sphere: -1, color: [1, f32(0.8), 0.5], size: 4 },
    };
    const doc = parseJsonText(text, shownName);
    const r: SceneReader = new SceneReader(shownName, fileUrl);
    if (!isObject(doc)) r.fail('scene', 'expected an object');
    if (doc.has('mesh') || doc.has('fur'))
        r.fail('scene', 'a fur scene (it has a mesh or fur): ray-tracing stages draw ray-tracing scenes (assets/scenes/*.json)');
    // Stage 08's OBJ meshes need buffer textures and a second file fetch:
    // the native build draws them, the page says so rather than drawing less.
    if (doc.has('meshes'))
        r.fail('meshes', 'OBJ meshes are drawn by the native build only (build/raylab), not in the web page');
    r.allowOnly(doc, '', ['background', 'camera', 'materials', 'lights', 'spheres', 'planes', 'discs', 'triangles', 'rectangles', 'boxes', 'tori', 'meshes', 'sky_box', 'glow']);
    scene.background = r.color(r.member(doc, 'scene', 'background'), 'background');
    const camera = readSceneCamera(r, doc);
    scene.camera = camera.pose;
    scene.fovYDeg = camera.fovYDeg;
    readMaterials(r, doc, scene);
    readLights(r, doc, scene);
    readShapes(r, doc, scene);
    readSkyBox(r, doc, scene);
    readGlow(r, doc, scene);
    return scene;
}
