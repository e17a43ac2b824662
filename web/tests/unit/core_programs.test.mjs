// The page's programs come from the C++ core (src/core/core.ts): for every
// ray-tracing stage (solution and lab) and every scene with stage 08, with
// and without the demo's levers, the program the core assembles for the page
// is `raylab shader --es --origins [--demo]`'s, line for line and
// file:line for file:line: one implementation, not two kept equal.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { coreScenePath, loadCore, openRayStage, withOrigins } from './core_support.mjs';
import { runRaylab, sceneFiles, shaderCommandMissing } from './scene_support.mjs';

const skip = shaderCommandMissing() ?? false;

function native(args) {
    const r = runRaylab(['shader', '--es', '--origins', ...args]);
    assert.equal(r.status, 0, `raylab shader ${args.join(' ')}: ${r.stderr}`);
    return r.stdout;
}

const RAY_STAGES = ['01-raycast', '02-shading', '03-shadows', '04-recursion', '05-primitives', '06-textures', '07-normalmaps', '08-full'];

test('every ray-tracing stage, solution and lab, assembles as natively', { skip }, async () => {
    const core = await loadCore();
    for (const stage of RAY_STAGES) {
        for (const lab of ['', '/raylab/labs']) {
            const { info, handle, error } = openRayStage(core, { stage, lab, maxBlockBytes: 65536 });
            assert.ok(!error, `${stage} ${lab}: ${error}`);
            handle.delete();
            const args = ['--stage', stage, ...(lab ? [] : ['--solution'])];
            assert.equal(withOrigins(info.fragment), native(args), `${stage} ${lab || 'solution'}: fragment`);
            assert.equal(withOrigins(info.vertex), native([...args, '--vertex']), `${stage}: vertex`);
        }
    }
});

test('stage 08 with every scene, with and without the demo\'s levers, assembles as natively', { skip }, async () => {
    const core = await loadCore();
    let levers = 0;
    for (const scene of sceneFiles()) {
        for (const demoLevers of [false, true]) {
            const { info, handle, error } = openRayStage(core, {
                stage: '08', scene: coreScenePath(core, scene), demoLevers, maxBlockBytes: 65536,
            });
            assert.ok(!error, `${scene}: ${error}`);
            handle.delete();
            const args = ['--stage', '08', '--solution', '--scene', scene, ...(demoLevers ? ['--demo'] : [])];
            assert.equal(withOrigins(info.fragment), native(args), `${scene}${demoLevers ? ' --demo' : ''}`);
            if (info.levers.includes('light buffer')) ++levers;
        }
    }
    assert.ok(levers >= 2, 'the demo scenes got the light buffer');
});

test('the demo\'s program on pro carries every lever and its buffers', { skip }, async () => {
    const core = await loadCore();
    const { info, handle } = openRayStage(core, {
        stage: '08', scene: '/raylab/assets/scenes/pro.json', demoLevers: true, maxBlockBytes: 65536,
    });
    try {
        assert.deepEqual(info.levers, ['BVH, eye cells', 'light buffer', 'tori hidden from the lights', 'shared work', 'weight cut']);
        assert.ok(handle.bvhNodes().length > 0 && handle.lightCells().length === 4 * (info.lightBuffer.everyCell + 1));
        const first = handle.placeEye(0, 1, 5);
        assert.equal(first.eyeCellsMoved, true);
        const cells = handle.eyeCells();
        assert.equal(cells.length, 2 * 6 * info.eyeCellsSize ** 2);
        assert.equal(handle.placeEye(0, 1, 5).eyeCellsMoved, false, 'the same eye builds nothing');
        // Every cell's list lies in the item texture, after the tree's items.
        const items = handle.bvhItems();
        for (let c = 0; c < cells.length; c += 2) assert.ok(cells[c] + cells[c + 1] <= items.length);
    } finally {
        handle.delete();
    }
});

test('the levers are for the solution only: a lab with them is refused in one line', async () => {
    const core = await loadCore();
    const { error } = openRayStage(core, { stage: '08', lab: '/raylab/labs', demoLevers: true });
    assert.equal(error, 'the demo\'s levers replace files students write: only for the solution');
});
