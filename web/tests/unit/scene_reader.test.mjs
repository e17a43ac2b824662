// Reading scene files (scene_reader.ts): the shipped scenes load; image
// paths become normalised URLs; and every kind of bad file is a SceneError
// "FILE: where: what" with the native build's words. With the native binary
// at hand the same bad files are also given to it, and the messages must be
// identical.
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { parseScene, sceneImageUrls, SceneError } from '../../dist/scene/scene_reader.js';
import { loadScene, meshSceneFiles, RAYLAB, ROOT, runRaylab, sceneFiles, tempScene } from './scene_support.mjs';

const GOOD = `{
  "background": [0.1, 0.2, 0.3],
  "camera": {"position": [0, 1, 5], "yaw": 10, "pitch": -5, "fov_y": 50},
  "materials": {"m": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 30}},
  "lights": [{"position": [0, 5, 0], "color": [1, 1, 1]}],
  "spheres": [
    {"center": [0, 1, 0], "radius": 1, "material": "m"},
    {"center": [2, 1, 0], "radius": 0.5, "color": [0, 1, 0], "motion": {"axis": [0, 1, 0], "amplitude": 2, "period": 4}}
  ]
}`;
const EARTH = path.join(ROOT, 'assets/textures/earth.png');

// GOOD with FROM replaced by TO (FROM must occur).
function replaced(from, to) {
    assert.ok(GOOD.includes(from), from);
    return GOOD.replace(from, to);
}
const withKey = (json) => replaced('"spheres": [', `${json}, "spheres": [`);

// [what, scene text, message after "FILE: "]
const ERRORS = [
    ['a missing key', replaced('"yaw": 10, ', ''), 'camera: missing "yaw"'],
    ['no spheres', '{"background": [0, 0, 0], "camera": {"position": [0, 0, 0], "yaw": 0, "pitch": 0}}', 'scene: missing "spheres"'],
    ['a misspelt key', replaced('"spheres"', '"spherez"'), 'spherez: unknown key (known here: background, camera, materials, lights, spheres, planes, discs, triangles, rectangles, boxes, tori, meshes, sky_box, glow)'],
    ['an unknown material', replaced('"material": "m"', '"material": "gold"'), 'spheres[0].material: unknown material "gold"'],
    ['a material that is no name', replaced('"material": "m"', '"material": 3'), 'spheres[0].material: expected the name of a material'],
    ['a wrong type', replaced('"center": [0, 1, 0]', '"center": [0, "1", 0]'), 'spheres[0].center[1]: expected a number'],
    ['a negative radius', replaced('"radius": 0.5', '"radius": -0.5'), 'spheres[1].radius: expected a positive number'],
    ['a colour out of range', replaced('"color": [0, 1, 0]', '"color": [3, 1, 0]'), 'spheres[1].color: colour components must lie in [0, 1]'],
    ['a short vector', replaced('"position": [0, 5, 0]', '"position": [0, 5]'), 'lights[0].position: expected [x, y, z]'],
    ['a zero period', replaced('"period": 4', '"period": 0'), 'spheres[1].motion.period: expected a positive number'],
    ['an unknown material type', replaced('"shininess": 30}', '"shininess": 30, "type": "wood"}'), 'materials.m.type: unknown type "wood" (plastic, mirror, glass or metal)'],
    ['glass without ior', replaced('"shininess": 30}', '"shininess": 30, "type": "glass"}'), 'materials.m: missing "ior"'],
    ['metal with a negative n', replaced('"shininess": 30}', '"shininess": 30, "type": "metal", "n": [1, -1, 1], "k": [0, 0, 0]}'), 'materials.m: n must be positive and k not negative'],
    ['a degenerate triangle', withKey('"triangles": [{"vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": "m"}]'), 'triangles[0]: degenerate: the corners lie on one line'],
    ['two bad corners (the first is named)', withKey('"triangles": [{"vertices": ["a", [0, 0, 0], "b"], "material": "m"}]'), 'triangles[0].vertices[0]: expected [x, y, z]'],
    ['bad JSON', '{ "background": [0, 0, 0],\n  oops }', 'line 2, column 3: JSON syntax error (Expected double-quoted property name)'],
    ['a number beyond a double', replaced('"yaw": 10', '"yaw": 1e500'), 'JSON number out of range (larger than a double can hold)'],
    ['a number beyond 1e30', replaced('"yaw": 10', '"yaw": 1e31'), 'camera.yaw: number out of range'],
    ['unknown keys (the first in sorted order)', withKey('"zz": 1, "aa": 2'), 'aa: unknown key (known here: background, camera, materials, lights, spheres, planes, discs, triangles, rectangles, boxes, tori, meshes, sky_box, glow)'],
    ['a misspelt sphere key', replaced('"radius": 1,', '"radiuss": 1,'), 'spheres[0].radiuss: unknown key (known here: center, radius, material, color, motion)'],
    ['a glow on no sphere', withKey('"glow": {"sphere": 2}'), 'glow.sphere: expected the index of a sphere (0..1)'],
    ['a glow index that is no integer', withKey('"glow": {"sphere": 0.5}'), 'glow.sphere: expected the index of a sphere (0..1)'],
    ['a texture on a triangle', replaced('"shininess": 30}', `"shininess": 30, "texture": ${JSON.stringify(EARTH)}}`).replace('"spheres": [', '"triangles": [{"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": "m"}], "spheres": ['), 'triangles[0].material: material "m" has a texture, but triangles have no texture coordinates (spheres, planes and discs do)'],
    ['a normal map on a plane', replaced('"shininess": 30}', `"shininess": 30, "normal_map": ${JSON.stringify(EARTH)}}`).replace('"spheres": [', '"planes": [{"point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}], "spheres": ['), 'planes[0].material: material "m" has a normal map, but only spheres take normal maps'],
    ['a fur scene', withKey('"mesh": {"shape": "sphere"}'), 'scene: a fur scene (it has a mesh or fur): ray-tracing stages draw ray-tracing scenes (assets/scenes/*.json)'],
    ['not an object', '[]', 'scene: expected an object'],
    ['a sphere that is no object', replaced('{"center": [0, 1, 0], "radius": 1, "material": "m"}', '3'), 'spheres[0]: expected an object'],
    ['a thick torus', withKey('"tori": [{"center": [0, 0, 0], "axis": [0, 1, 0], "major_radius": 1, "minor_radius": 1, "material": "m"}]'), 'tori[0]: minor_radius must be smaller than major_radius'],
    ['a flat box', withKey('"boxes": [{"center": [0, 0, 0], "size": [1, 0, 1], "material": "m"}]'), 'boxes[0].size: every side must be positive'],
    ['a zero normal', withKey('"planes": [{"point": [0, 0, 0], "normal": [0, 0, 0], "material": "m"}]'), 'planes[0].normal: expected a direction, not a zero vector'],
    ['a wide field of view', replaced('"fov_y": 50', '"fov_y": 170'), 'camera.fov_y: must be below 170 degrees'],
    ['five sky-box faces', withKey('"sky_box": ["a", "b", "c", "d", "e"]'), 'sky_box: expected six image files: +x, -x, +y, -y, +z, -z'],
    ['materials as a list', replaced('"materials": {"m": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 30}}', '"materials": []'), 'materials: expected an object of named materials'],
    ['planes as an object', withKey('"planes": {}'), 'planes: expected a list'],
];

function errorFor(text, file = 'scenes/bad.json') {
    try {
        parseScene(text, `/${file}`, file);
    } catch (e) {
        assert.ok(e instanceof SceneError, `not a SceneError: ${e}`);
        assert.equal(e.name, 'SceneError');
        return e.message;
    }
    return null;
}

test('the good scene loads, with floats and sorted materials', () => {
    const s = parseScene(GOOD, '/scenes/good.json', 'scenes/good.json');
    assert.equal(s.file, 'scenes/good.json');
    assert.equal(s.spheres.length, 2);
    assert.equal(s.spheres[1].radius, 0.5);
    assert.equal(s.fovYDeg, 50);
    assert.deepEqual(s.background, [Math.fround(0.1), Math.fround(0.2), Math.fround(0.3)]);
    assert.deepEqual(s.camera, { position: [0, 1, 5], yawDeg: 10, pitchDeg: -5 });
    assert.deepEqual(s.materials.map((m) => m.name), ['m', 'spheres[1]'], 'a flat colour is a material named after its object');
    assert.deepEqual(s.materials[1].diffuse, [0, 1, 0]);
    assert.deepEqual(s.spheres[1].motion, { axis: [0, 1, 0], amplitude: 2, periodSeconds: 4 });
    assert.deepEqual(s.glow, { sphere: -1, color: [1, Math.fround(0.8), 0.5], size: 4 });
    assert.equal(s.skyBox, null);
    assert.equal(parseScene(replaced(', "fov_y": 50', ''), '/a.json', 'a.json').fovYDeg, Math.fround(36.87));
});

test('a scene with OBJ meshes is refused in one line', () => {
    const files = meshSceneFiles();
    assert.ok(files.includes('assets/scenes/mesh.json'), files.join(', '));
    for (const file of files)
        assert.throws(() => loadScene(file), (e) => /meshes: OBJ meshes are drawn by the native build only/.test(e.message) && !e.message.includes('\n'), file);
});

test('every shipped scene loads', () => {
    for (const file of sceneFiles()) assert.doesNotThrow(() => loadScene(file), file);
    const pro = loadScene('assets/scenes/pro.json');
    assert.equal(pro.spheres.length, 110);
    assert.equal(pro.triangles.length, 14, 'a mirror of 2 triangles and a cube of 12');
    assert.equal(pro.tori.length, 1);
});

test('materials get their indices in sorted key order, as in the native std::map', () => {
    const s = parseScene(
        replaced('"materials": {"m"', '"materials": {"zeta": {"ambient": [0, 0, 0], "diffuse": [0, 0, 1], "specular": [0, 0, 0], "shininess": 1}, "Beta": {"ambient": [0, 0, 0], "diffuse": [0, 0, 1], "specular": [0, 0, 0], "shininess": 1}, "m"'),
        '/a.json',
        'a.json',
    );
    assert.deepEqual(s.materials.map((m) => m.name), ['Beta', 'm', 'zeta', 'spheres[1]']);
    assert.equal(s.spheres[0].material, 1);
});

test('image paths become normalised URLs relative to the scene; a file used twice shares a layer', () => {
    const s = loadScene('assets/scenes/stage06.json');
    assert.deepEqual(s.textures.slice(0, 2), ['/assets/textures/earth.png', '/assets/textures/earth_normal.png']);
    assert.equal(s.skyBox.length, 6);
    assert.equal(s.skyBox[0], '/assets/textures/sky_px.png');
    assert.deepEqual(sceneImageUrls(s), [...s.textures, ...s.skyBox]);
    const earth = s.materials.find((m) => m.name === 'earth');
    assert.equal(s.textures[earth.texture], '/assets/textures/earth.png');
    assert.equal(s.textures[earth.normalMap], '/assets/textures/earth_normal.png');

    const twice = replaced('"shininess": 30}', '"shininess": 30, "texture": "./t/../x.png", "normal_map": "x.png"}');
    const t = parseScene(twice, 'https://host/a/scenes/s.json', 's.json');
    assert.deepEqual(t.textures, ['https://host/a/scenes/x.png']);
    assert.equal(t.materials[0].texture, 0);
    assert.equal(t.materials[0].normalMap, 0);
    const rel = parseScene(twice.replace('"x.png"', '"../../../y.png"'), 'scenes/s.json', 's.json');
    assert.deepEqual(rel.textures, ['scenes/x.png', '../../y.png']);
    const parseFaces = (faces) => parseScene(withKey(`"sky_box": ${JSON.stringify(faces)}`), '/assets/scenes/s.json', 's.json').skyBox;
    assert.deepEqual(parseFaces(['/abs/a.png', '../t/b.png', 'c.png', 'd.png', 'e.png', 'f.png']).slice(0, 3), ['/abs/a.png', '/assets/t/b.png', '/assets/scenes/c.png']);
});

test('bad scene files are SceneErrors "FILE: where: what"', () => {
    for (const [what, text, message] of ERRORS) assert.equal(errorFor(text), `scenes/bad.json: ${message}`, what);
});

test('bad scene files get the native build\'s messages', { skip: existsSync(RAYLAB) ? false : `no native binary at ${RAYLAB}` }, () => {
    for (const [what, text] of ERRORS) {
        const file = tempScene(text);
        const r = runRaylab(['trace', '--stage', '08', '--solution', '--scene', file, '--pixel', '0,0']);
        const line = r.stderr.split('\n').find((l) => l.startsWith('raylab: error: '));
        // The browser's JSON parser adds its own words to a syntax error.
        assert.equal(line, `raylab: error: ${errorFor(text, file).replace(/(JSON syntax error) \(.*\)$/, '$1')}`, what);
    }
});
