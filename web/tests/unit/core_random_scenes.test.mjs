// Random scenes against the native build: every number kind the printer
// meets (tiny, huge, negative zero, decimals of any length), boxes turned by
// angles where glibc's sinf/cosf are not correctly rounded (13, 19, 22
// degrees...), directions to normalise, many moving spheres. The program the
// core assembles must equal `raylab shader`'s; a scene the native build refuses (a box so
// thin its corners coincide in float) must be refused with the same message.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { coreScenePath, loadCore, openRayStage, withOrigins } from './core_support.mjs';
import { randomScene } from './random_scene.mjs';
import { runRaylab, shaderCommandMissing, tempScene } from './scene_support.mjs';

const SEEDS = Array.from({ length: 24 }, (_, i) => i + 1);

test('random scenes assemble in the core as natively, or fail with the native message', { skip: shaderCommandMissing() ?? false }, async () => {
    const core = await loadCore();
    let compared = 0;
    for (const seed of SEEDS) {
        const file = tempScene(randomScene(seed), `random${seed}.json`);
        const native = runRaylab(['shader', '--stage', '08', '--solution', '--es', '--origins', '--scene', file]);
        const mine = openRayStage(core, { stage: '08', scene: coreScenePath(core, file), maxBlockBytes: 65536 });
        if (mine.error) {
            assert.notEqual(native.status, 0, `seed ${seed}: the native build accepted what the core refused: ${mine.error}`);
            assert.equal(`raylab: error: ${mine.error}`, native.stderr.trim().split('\n')[0], `seed ${seed}`);
            continue;
        }
        mine.handle.delete();
        assert.equal(native.status, 0, `seed ${seed}: the native build refused what the core accepted: ${native.stderr}`);
        assert.equal(withOrigins(mine.info.fragment), native.stdout, `seed ${seed}`);
        ++compared;
    }
    assert.ok(compared >= SEEDS.length / 2, `only ${compared} scenes were valid`);
});
