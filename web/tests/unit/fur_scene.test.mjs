// Fur scene files (fur_scene.ts): every file in assets/scenes/fur parses,
// files become normalised URLs, and each mistake gives the native build's
// one-line message (taken from framework/src/fur/mesh/fur_scene.cpp's
// loadFurScene on the same input). modelMatrix equals glm's bit for bit.
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

import { FurSceneError, furSceneFileUrls, modelMatrix, parseFurScene } from '../../dist/fur/mesh/fur_scene.js';
import { SceneError } from '../../dist/scene/json_reader.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const FUR = 'assets/scenes/fur';
const f32 = Math.fround;

function load(rel) {
    return parseFurScene(readFileSync(path.join(ROOT, rel), 'utf8'), `/${rel}`, rel);
}

const BASE = {
    background: [0.08, 0.09, 0.12],
    camera: { position: [0.0, 0.4, 3.6], yaw: 0.0, pitch: -6.0, fov_y: 45.0 },
    mesh: { shape: 'sphere', detail: 32 },
    transform: { translate: [0.3, -1.25, 2.0], rotate: [17.0, 20.0, -33.0], scale: [1.5, 0.6, 1.1], spin: 25.0 },
    light: { direction: [-0.5, 0.7, 0.6], color: [1.0, 0.97, 0.9], ambient: [0.18, 0.18, 0.22] },
    fur: {
        length: 0.18, shells: 30, pattern_scale: 6.0, shadow_intensity: 0.6,
        color_map: '../../textures/fur_color.png', pattern: '../../textures/fur_pattern.png', fin_map: '../../textures/fur_fin.png',
        gravity: 0.35, strand_density: 2500, strand_segments: 4,
    },
};
const SHOWN = 'assets/scenes/fur/test.json';

// BASE with the value at the dotted PATH replaced (undefined: removed).
function variant(pathText, value) {
    const doc = structuredClone(BASE);
    const keys = pathText.split('.');
    let o = doc;
    for (const k of keys.slice(0, -1)) o = o[k];
    if (value === undefined) delete o[keys.at(-1)];
    else o[keys.at(-1)] = value;
    return JSON.stringify(doc, null, 1);
}

const parseText = (text) => parseFurScene(text, `/${SHOWN}`, SHOWN);

const fileNames = readdirSync(path.join(ROOT, FUR)).filter((f) => f.endsWith('.json')).sort();

test('every fur scene file parses', () => {
    assert.ok(fileNames.length >= 7, fileNames.join(' '));
    for (const f of fileNames) {
        const s = load(`${FUR}/${f}`);
        assert.equal(s.file, `${FUR}/${f}`);
        assert.ok((s.mesh.shape === '') !== (s.mesh.obj === ''), f);
        for (const url of furSceneFileUrls(s)) assert.match(url, /^\/assets\/(textures|meshes)\/[a-z_]+\.(png|obj)$/, `${f}: ${url}`);
    }
});

test('values, defaults and URLs as the native reader gives them', () => {
    const blob = load(`${FUR}/blob.json`);
    assert.equal(blob.mesh.obj, '/assets/meshes/blob.obj');
    assert.equal(blob.mesh.shape, '');
    assert.equal(blob.fur.colorMap, '/assets/textures/fur_color.png');
    assert.equal(blob.fur.finMap, '/assets/textures/fur_fin.png');
    assert.deepEqual(furSceneFileUrls(blob), ['/assets/meshes/blob.obj', '/assets/textures/fur_color.png', '/assets/textures/fur_pattern.png', '/assets/textures/fur_fin.png']);
    assert.equal(blob.spinDegPerSecond, 20);
    assert.deepEqual(blob.rotateDeg, [0, 15, 0]);
    assert.deepEqual(blob.background, [f32(0.08), f32(0.09), f32(0.12)]);
    assert.equal(blob.fur.strandDensity, 2500);

    const coarse = load(`${FUR}/coarse.json`);
    assert.deepEqual(coarse.mesh, { shape: 'sphere', detail: 6, obj: '' });
    assert.equal(coarse.fovYDeg, 45);
    // Not in the file: fur_scene.h's defaults, as floats.
    assert.equal(coarse.fur.gravity, f32(0.3));
    assert.equal(coarse.fur.strandDensity, 600);
    assert.equal(coarse.fur.strandSegments, 4);
    assert.equal(coarse.spinDegPerSecond, 0);
    assert.deepEqual(coarse.scale, [1, 1, 1]);

    // The light direction is normalised in float (glm::normalize).
    const d = blob.lightDirection;
    assert.ok(Math.abs(Math.hypot(...d) - 1) < 1e-6);

    // A camera without fov_y: the course's default, not fur_scene.h's 45.
    const doc = JSON.parse(variant('camera.fov_y', undefined));
    assert.equal(parseText(JSON.stringify(doc)).fovYDeg, f32(36.87));
    // No transform at all, and the "comment" key anywhere: fine.
    const plain = JSON.parse(variant('transform', undefined));
    plain.comment = 'x';
    plain.mesh.comment = 'y';
    const s = parseText(JSON.stringify(plain));
    assert.deepEqual([s.translate, s.rotateDeg, s.scale], [[0, 0, 0], [0, 0, 0], [1, 1, 1]]);
});

test('file URLs resolve against the scene URL, absolute or not', () => {
    const text = variant('mesh', { obj: '../../meshes/./x/../blob.obj' });
    assert.equal(parseFurScene(text, 'http://host/a/scenes/fur/s.json', 'x').mesh.obj, 'http://host/a/meshes/blob.obj');
    assert.equal(parseFurScene(text, 'scenes/fur/s.json', 'x').mesh.obj, 'meshes/blob.obj');
    assert.equal(parseFurScene(variant('fur.fin_map', '/abs/fin.png'), '/a/b.json', 'x').fur.finMap, '/abs/fin.png');
});

// [path, value, message after "FILE: "], each checked against the native build.
const BAD = [
    ['mesh', undefined, 'scene: missing "mesh"'],
    ['fur', undefined, 'scene: missing "fur"'],
    ['light', undefined, 'scene: missing "light"'],
    ['camera', undefined, 'scene: missing "camera"'],
    ['background', undefined, 'scene: missing "background"'],
    ['camera.yaw', undefined, 'camera: missing "yaw"'],
    ['camera.yaw', null, 'camera.yaw: expected a number'],
    ['camera', 'x', 'camera: expected an object'],
    ['camera.fov_y', 170, 'camera.fov_y: must be below 170 degrees'],
    ['camera.fov_y', -1, 'camera.fov_y: expected a positive number'],
    ['mesh.shape', 'cone', "mesh.shape: unknown shape 'cone' (known: sphere, torus, cube)"],
    ['mesh.shape', 3, 'mesh.shape: expected a string'],
    ['mesh.detail', 1, 'mesh.detail: must be between 2 and 512'],
    ['mesh.detail', 513, 'mesh.detail: must be between 2 and 512'],
    ['mesh.detail', 2.5, 'mesh.detail: expected a whole number'],
    ['mesh.detail', '8', 'mesh.detail: expected a whole number'],
    ['mesh.obj', 'x.obj', 'mesh: give either "shape" (sphere, torus, cube) or "obj" (a file)'],
    ['mesh', 5, 'mesh: give either "shape" (sphere, torus, cube) or "obj" (a file)'],
    ['mesh.shpe', 1, 'mesh.shpe: unknown key (known here: shape, detail, obj)'],
    ['sphere', 1, 'sphere: unknown key (known here: background, camera, mesh, transform, light, fur)'],
    ['fur.length', 0, 'fur.length: expected a positive number'],
    ['fur.length', '1', 'fur.length: expected a number'],
    ['fur.length', 1e31, 'fur.length: number out of range'],
    ['fur.shells', 0, 'fur.shells: must be between 1 and 256'],
    ['fur.shadow_intensity', 1.5, 'fur.shadow_intensity: must be between 0 and 1'],
    ['fur.gravity', 2.5, 'fur.gravity: must be between 0 and 2'],
    ['fur.strand_density', 2e6, 'fur.strand_density: must be between 1 and 1e+06'],
    ['fur.strand_segments', 17, 'fur.strand_segments: must be between 1 and 16'],
    ['fur.color_map', undefined, 'fur: missing "color_map"'],
    ['fur.color_map', 1, 'fur.color_map: expected a string'],
    ['fur.colour', 1, 'fur.colour: unknown key (known here: length, shells, pattern_scale, shadow_intensity, color_map, pattern, fin_map, gravity, strand_density, strand_segments)'],
    ['fur', [1], 'fur: expected an object'],
    ['transform.scale', [1, 0, 1], 'transform.scale: every factor must be positive (a mirror would turn the triangles inside out)'],
    ['transform.scale', [1, 1], 'transform.scale: expected [x, y, z]'],
    ['transform.rotate', [1, 'a', 3], 'transform.rotate[1]: expected a number'],
    ['transform.spin', 'x', 'transform.spin: expected a number'],
    ['transform.shift', 1, 'transform.shift: unknown key (known here: translate, rotate, scale, spin)'],
    ['light.direction', [0, 0, 0], 'light.direction: expected a direction, not a zero vector'],
    ['light.color', [1.5, 0, 0], 'light.color: colour components must lie in [0, 1]'],
    ['light.pos', 1, 'light.pos: unknown key (known here: direction, color, ambient)'],
    ['background', [0, 0, 2], 'background: colour components must lie in [0, 1]'],
];

for (const [where, value, message] of BAD)
    test(`bad input: ${where} = ${JSON.stringify(value)}`, () => {
        assert.throws(() => parseText(variant(where, value)), (e) => {
            assert.ok(e instanceof FurSceneError && e instanceof SceneError, String(e));
            assert.equal(e.message, `${SHOWN}: ${message}`);
            return true;
        });
    });

test('bad documents: not an object, a ray-tracing scene, bad JSON', () => {
    const fails = (text, pattern) =>
        assert.throws(() => parseText(text), (e) => e instanceof FurSceneError && pattern.test(e.message) && !e.message.includes('\n'));
    fails('[1, 2]', /^assets\/scenes\/fur\/test\.json: scene: expected an object$/);
    fails(JSON.stringify({ ...BASE, mesh: undefined, spheres: [] }), /^assets\/scenes\/fur\/test\.json: scene: a ray-tracing scene \(it has spheres or materials, no mesh\): fur stages draw fur scenes \(assets\/scenes\/fur\/\)$/);
    fails('{\n  "background": [0.1, 0.1,, 0.1]\n}', /^assets\/scenes\/fur\/test\.json: .*JSON syntax error/);
    fails('', /^assets\/scenes\/fur\/test\.json: .*JSON syntax error/);
    fails('{"background": 1e500}', /^assets\/scenes\/fur\/test\.json: JSON number out of range/);
    // A transform that is not an object is ignored natively (contains() is false on it).
    assert.deepEqual(parseText(variant('transform', 3)).scale, [1, 1, 1]);
});

// The native matrices (glm, raylab's FurScene::modelMatrix) as float bits, column-major.
function bits(m) {
    return [...new Uint32Array(Float32Array.from(m).buffer)].map((u) => u.toString(16).padStart(8, '0')).join(' ');
}

test('modelMatrix: glm\'s floats bit for bit', () => {
    assert.equal(bits(modelMatrix(load(`${FUR}/sphere.json`), 1.5)),
        '3f098c77 00000000 bf57e881 00000000 00000000 3f800000 00000000 00000000 3f57e881 00000000 3f098c77 00000000 00000000 00000000 00000000 3f800000');
    // Translate, three rotations, a non-uniform scale and a spin.
    assert.equal(bits(modelMatrix(parseText(JSON.stringify(BASE)), 1.5)),
        '3ef2eeb0 bf4800c0 bf983bea 00000000 3e996d52 3ef661ca be49466d 00000000 3f631f19 bea4a9eb 3f10b13c 00000000 3e99999a bfa00000 40000000 3f800000');
});

test('modelMatrix: the order is translate * rotY(y + spin t) * rotX * rotZ * scale', () => {
    const s = parseText(JSON.stringify({ ...BASE, transform: { translate: [1, 2, 3], rotate: [0, 90, 0], scale: [2, 3, 4], spin: 90 } }));
    const at0 = modelMatrix(s, 0);
    // Rotating by 90 degrees about y sends x to -z; scale 2 first; translation last.
    const close = (a, b) => a.every((x, i) => Math.abs(x - b[i]) < 1e-6);
    assert.ok(close([...at0.slice(0, 4)], [0, 0, -2, 0]), String(at0));
    assert.ok(close([...at0.slice(4, 8)], [0, 3, 0, 0]), String(at0));
    assert.ok(close([...at0.slice(8, 12)], [4, 0, 0, 0]), String(at0));
    assert.deepEqual([...at0.slice(12)], [1, 2, 3, 1]);
    // One second of spin adds another 90 degrees: x now goes to -x.
    assert.ok(close([...modelMatrix(s, 1).slice(0, 4)], [-2, 0, 0, 0]));
});
