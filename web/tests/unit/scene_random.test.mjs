// Random scenes against the native build: every number kind the printer
// meets (tiny, huge, negative zero, decimals of any length), boxes turned by
// angles where glibc's sinf/cosf are not correctly rounded (13, 19, 22
// degrees...), directions to normalise, many moving spheres. The baked text
// must equal `raylab shader`'s; a scene the native build refuses (a box so
// thin its corners coincide in float) must be refused with the same message.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { bakedSceneDefines, bakedSceneGlsl } from '../../dist/scene/scene_baking.js';
import { parseScene, SceneError } from '../../dist/scene/scene_reader.js';
import { randomScene } from './random_scene.mjs';
import { bakedParts, nativeShader, shaderCommandMissing, tempScene } from './scene_support.mjs';

const SEEDS = Array.from({ length: 24 }, (_, i) => i + 1);

test('random scenes bake to the native text, or fail with the native message', { skip: shaderCommandMissing() ?? false }, () => {
    let compared = 0;
    for (const seed of SEEDS) {
        const file = tempScene(randomScene(seed), `random${seed}.json`);
        const text = readFileSync(file, 'utf8');
        const native = nativeShader(file);
        let mine;
        try {
            mine = parseScene(text, file, file);
        } catch (e) {
            assert.ok(e instanceof SceneError, `seed ${seed}: ${e}`);
            assert.equal(e.message, native.error, `seed ${seed}: the native build accepted what we refused`);
            continue;
        }
        assert.ok(native.text, `seed ${seed}: the native build refused what we accepted: ${native.error}`);
        const { glsl, defines } = bakedParts(native.text);
        assert.equal(bakedSceneGlsl(mine, file), glsl, `seed ${seed}`);
        assert.deepEqual(bakedSceneDefines(mine), defines, `seed ${seed}`);
        ++compared;
    }
    assert.ok(compared >= SEEDS.length / 2, `only ${compared} scenes were valid`);
});
