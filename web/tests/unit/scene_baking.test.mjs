// The baked scene (scene_baking.ts) is the native build's text, character
// for character: for every scene file the constants block and the #defines
// equal what `raylab shader` prints for stage 08. (When the native binary
// or its shader command is missing those tests skip; the checks below on
// known lines still run.)
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { bakedSceneDefines, bakedSceneGlsl, floatLiteral } from '../../dist/scene/scene_baking.js';
import { bakedParts, loadScene, nativeShader, sceneFiles, shaderCommandMissing } from './scene_support.mjs';

for (const file of sceneFiles()) {
    test(`${file}: baked GLSL and defines equal the native build's`, { skip: shaderCommandMissing() ?? false }, () => {
        const scene = loadScene(file);
        const native = nativeShader(file);
        assert.ok(native.text, `raylab shader failed: ${native.error}`);
        const { glsl, defines } = bakedParts(native.text);
        assert.ok(glsl, 'no baked block in the native shader');
        assert.equal(bakedSceneGlsl(scene, file), glsl);
        assert.deepEqual(bakedSceneDefines(scene), defines);
    });
}

test('the first line names the file as given, by default the scene\'s own name', () => {
    const scene = loadScene('assets/scenes/stage01.json');
    const first = (g) => g.split('\n')[0];
    assert.equal(first(bakedSceneGlsl(scene)), '// The scene, compiled in (framework/src/raytrace/scene/scene_baking.cpp): assets/scenes/stage01.json');
    assert.match(first(bakedSceneGlsl(scene, 'x/y.json')), /: x\/y\.json$/);
});

test('stage05: known lines (box corners turned by 30 degrees, plane as normal and distance)', () => {
    const g = bakedSceneGlsl(loadScene('assets/scenes/stage05.json'));
    assert.ok(g.includes('const vec4 uPlanes[1] = vec4[1](vec4(0.0, 1.0, 0.0, 0.0));\n'));
    assert.ok(g.includes('const vec3 uDiscNormals[1] = vec3[1](vec3(-0.328888685, 0.0939682052, 0.939682007));\n'));
    assert.ok(g.includes('vec3(-1.50262797, 0.0499999523, -0.402627945), vec3(-0.402627945, 0.0499999523, 1.50262797)'));
    assert.ok(g.includes('const int uTriangleCount = 14;\n'));
    assert.ok(g.endsWith('const int uGlowSphere = -1;\nconst vec3 uGlowColor = vec3(1.0, 0.800000012, 0.5);\nconst float uGlowSize = 4.0;\n'));
});

test('kinds a scene lacks still get one-element arrays; defines are at least 1', () => {
    const scene = loadScene('assets/scenes/pro.json');
    const g = bakedSceneGlsl(scene);
    assert.ok(g.includes('const int uPlaneCount = 0;\n'));
    assert.ok(g.includes('const vec4 uPlanes[1] = vec4[1](vec4(0.0));\n'));
    assert.ok(g.includes('const float uPlaneTileSize[1] = float[1](0.0);\n'));
    assert.ok(g.includes('const int uPlaneMaterial[1] = int[1](0);\n'));
    assert.ok(g.includes(`const int uSphereCount = ${scene.spheres.length};\n`));
    const d = bakedSceneDefines(scene);
    assert.equal(d[0], 'SCENE_BAKED');
    assert.ok(d.includes(`MAX_SPHERES ${scene.spheres.length}`));
    assert.ok(d.includes('MAX_PLANES 1'));
    assert.equal(d.length, 8);
});

test('float literals read back as the same float and are never ints', () => {
    for (const v of [0.1, 1 / 3, 12345.678, 1, 100, 1e-7, 3e38, -2.5, 16777217]) {
        const s = floatLiteral(v);
        assert.match(s, /[.e]/, s);
        assert.equal(Math.fround(Number(s)), Math.fround(v), s);
    }
    assert.equal(floatLiteral(1), '1.0');
    assert.equal(floatLiteral(-0), '-0.0');
    assert.equal(floatLiteral(0.1), '0.100000001');
    assert.equal(floatLiteral(1e-5), '9.99999975e-06');
    assert.equal(floatLiteral(1e10), '1e+10');
});
