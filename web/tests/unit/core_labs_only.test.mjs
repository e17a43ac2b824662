// A project served without its solutions' code (tools/serve.mjs without
// --with-solutions: solution/<stage>/ holds its stage.json alone): every
// stage's lab still assembles, to the same program as with the solutions
// there, and a missing lab file is still named.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { loadCore, openRayStage } from './core_support.mjs';

async function programsOfEveryLab(core) {
    const out = new Map();
    for (const id of core.FS.readdir('/raylab/solution').filter((n) => /^\w+-/.test(n))) {
        const track = JSON.parse(core.FS.readFile(`/raylab/solution/${id}/stage.json`, { encoding: 'utf8' })).track;
        if (track === 'raytrace') {
            const r = openRayStage(core, { stage: id, lab: '/raylab/labs', maxBlockBytes: 65536 });
            assert.ok(!r.error, `${id}: ${r.error}`);
            r.handle.delete();
            out.set(id, r.info.fragment.text);
        } else {
            const h = new core.FurStage(JSON.stringify({ stage: id, lab: '/raylab/labs' }));
            assert.equal(h.error(), '', id);
            out.set(id, JSON.stringify(JSON.parse(h.info()).programs));
            h.delete();
        }
    }
    return out;
}

test('every lab assembles as before with the solutions\' code gone', async () => {
    const core = await loadCore();
    const before = await programsOfEveryLab(core);
    assert.equal(before.size, 12);
    for (const id of before.keys())
        for (const f of core.FS.readdir(`/raylab/solution/${id}`))
            if (f !== 'stage.json' && !f.startsWith('.')) core.FS.unlink(`/raylab/solution/${id}/${f}`);
    const after = await programsOfEveryLab(core);
    for (const [id, program] of before) assert.equal(after.get(id), program, id);
    // A lab file gone: its name and where it was looked for.
    core.FS.unlink('/raylab/labs/01-raycast/intersect_sphere.glsl');
    const r = openRayStage(core, { stage: '01', lab: '/raylab/labs', maxBlockBytes: 65536 });
    assert.match(r.error, /labs\/01-raycast\/main.frag:6: cannot find shader file "intersect_sphere.glsl" \(looked in web\/shaders, labs\/01-raycast, framework\/shaders\)/);
});
