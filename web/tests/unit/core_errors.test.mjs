// The page shows native's messages to the letter: bad scenes, scenes past a
// stage's limits, a missing lab file, an unknown stage - each given to the
// core and to `raylab shader`, the one-line messages equal.
import assert from 'node:assert/strict';
import path from 'node:path';
import { test } from 'node:test';

import { coreScenePath, loadCore, openRayStage } from './core_support.mjs';
import { runRaylab, shaderCommandMissing, tempDir, tempScene } from './scene_support.mjs';

const skip = shaderCommandMissing() ?? false;

// The first error line of `raylab COMMAND ARGS` (shader by default; render
// checks a scene against the stage's limits, as the page does).
function nativeError(args, command = 'shader') {
    const out = command === 'render' ? ['--out', path.join(tempDir(), 'never.png')] : ['--es'];
    const r = runRaylab([command, ...out, ...args]);
    assert.notEqual(r.status, 0, `raylab shader ${args.join(' ')} succeeded`);
    const line = r.stderr.split('\n').find((l) => l.startsWith('raylab: error: '));
    return line ? line.slice('raylab: error: '.length) : r.stderr.trim();
}

const BAD_SCENES = {
    'syntax.json': '{ "spheres": [ { "center": [0, 0, 0], } ] }',
    'unknown-material.json': '{ "camera": { "position": [0, 0, 3] }, "lights": [], "spheres": [ { "center": [0, 0, 0], "radius": 1, "material": "gold" } ] }',
    'negative-radius.json': '{ "camera": { "position": [0, 0, 3] }, "materials": { "m": { "diffuse": [1, 0, 0] } }, "spheres": [ { "center": [0, 0, 0], "radius": -1, "material": "m" } ] }',
    'missing-texture.json': '{ "camera": { "position": [0, 0, 3] }, "materials": { "m": { "diffuse": [1, 0, 0], "texture": "nowhere.png" } }, "spheres": [ { "center": [0, 0, 0], "radius": 1, "material": "m" } ] }',
    'fur.json': '{ "mesh": { "shape": "sphere" }, "fur": {} }',
};

test('bad scenes get native\'s message', { skip }, async () => {
    const core = await loadCore();
    for (const [name, text] of Object.entries(BAD_SCENES)) {
        const file = tempScene(text, name);
        const { error } = openRayStage(core, { stage: '08', scene: coreScenePath(core, file) });
        assert.ok(error, `${name}: the core accepted it`);
        assert.equal(error, nativeError(['--stage', '08', '--solution', '--scene', file]), name);
    }
});

test('a scene past a stage\'s limits, and an unknown stage, get native\'s message', { skip }, async () => {
    const core = await loadCore();
    let { error } = openRayStage(core, { stage: '01', scene: '/raylab/assets/scenes/pro.json' });
    assert.equal(error, nativeError(['--stage', '01', '--solution', '--scene', 'assets/scenes/pro.json'], 'render'));
    assert.match(error, /^assets\/scenes\/pro\.json: spheres: 110 spheres, but stage 01-raycast supports at most \d+$/);
    ({ error } = openRayStage(core, { stage: '09' }));
    assert.equal(error, nativeError(['--stage', '09', '--solution']));
});

test('a scene with more spheres than the browser\'s uniform block holds is refused in one line', async () => {
    const core = await loadCore();
    const { error } = openRayStage(core, { stage: '08', scene: '/raylab/assets/scenes/pro.json', maxBlockBytes: 1024 });
    assert.equal(error, 'assets/scenes/pro.json: spheres: 110 spheres, but this browser\'s uniform blocks hold at most 64 ' +
        '(MAX_UNIFORM_BLOCK_SIZE 1024 bytes, 16 per sphere)');
});
