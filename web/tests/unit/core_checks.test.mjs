// The checks' CPU side in the page's core (src/wasm/check_bindings.cpp): the
// function checks' harness programs are `raylab shader --function NAME --es
// --origins`'s, line for line; their scoring is native's (a lab's stubs give
// `raylab check`'s first failure to the letter, wrong answers fail); a check
// view is judged with native's comparison (`raylab compare`'s verdict and
// figures). The harness itself runs in WebGL in the browser tests.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import { crc32, deflateSync } from 'node:zlib';

import { loadCore, withOrigins } from './core_support.mjs';
import { RAYLAB, ROOT, runRaylab, shaderCommandMissing } from './scene_support.mjs';

const skip = shaderCommandMissing() ?? false;
const STAGES_WITH_FUNCTIONS = ['01-raycast', '02-shading', '03-shadows', '05-primitives', '06-textures',
    '07-normalmaps', '08-full', 'f2-shells', 'f3-fins', 'f4-furshader'];

function openChecks(core, request) {
    const handle = new core.FunctionChecks(JSON.stringify(request));
    const error = handle.error();
    if (error) {
        handle.delete();
        return { error };
    }
    return { list: JSON.parse(handle.list()), handle };
}

test('every function check\'s harness, solution and lab, assembles as natively', { skip }, async () => {
    const core = await loadCore();
    let functions = 0;
    for (const stage of STAGES_WITH_FUNCTIONS) {
        for (const lab of ['', '/raylab/labs']) {
            const { list, handle, error } = openChecks(core, { stage, lab });
            assert.ok(!error, `${stage}: ${error}`);
            handle.delete();
            assert.ok(list.length > 0, `${stage} lists its function checks`);
            for (const f of list) {
                assert.ok(!f.error, `${stage} ${f.name}: ${f.error}`);
                const args = ['shader', '--es', '--origins', '--stage', stage, '--function', f.name,
                    ...(lab ? [] : ['--solution'])];
                const r = runRaylab(args);
                assert.equal(r.status, 0, `raylab ${args.join(' ')}: ${r.stderr}`);
                assert.equal(withOrigins(f.fragment), r.stdout, `${stage} ${f.name} ${lab || 'solution'}`);
                const v = runRaylab([...args, '--vertex']);
                assert.equal(withOrigins(f.vertex), v.stdout, `${stage} ${f.name}: vertex`);
                ++functions;
            }
        }
    }
    // Every function check of every stage.json, for the solution and the lab.
    const listed = STAGES_WITH_FUNCTIONS.map((s) =>
        JSON.parse(readFileSync(path.join(ROOT, 'solution', s, 'stage.json'), 'utf8')).function_checks.length);
    assert.equal(functions, 2 * listed.reduce((a, b) => a + b), 'every harness compared');
});

// `raylab check`'s function lines for the untouched lab: name -> first failure.
function nativeFirstFailures(stage) {
    const r = runRaylab(['check', '--stage', stage]);
    const out = new Map();
    for (const m of r.stdout.matchAll(/^ {2}FAIL (\w+) +\d+\/\d+ cases; first failure: (.*)$/gm)) out.set(m[1], m[2]);
    return out;
}

test('stubs score as `raylab check` scores the untouched lab, to the letter', { skip }, async () => {
    const core = await loadCore();
    for (const stage of ['01-raycast', 'f2-shells']) {
        const native = nativeFirstFailures(stage);
        const { list, handle } = openChecks(core, { stage, lab: '/raylab/labs' });
        try {
            assert.equal(native.size, list.length, `${stage}: native failed every function`);
            for (const f of list) {
                // What a harness writes where every call reaches a labTodo() stub.
                const results = new Float32Array(4 * f.cases).map((_, i) => (i % 4 === 3 ? -12345 : 0));
                const s = JSON.parse(handle.score(f.name, results));
                assert.equal(s.passed, 0, `${f.name}`);
                assert.equal(s.total, f.cases);
                assert.equal(s.firstFailure, native.get(f.name), `${stage} ${f.name}`);
            }
        } finally { handle.delete(); }
    }
});

test('wrong answers fail, a short result is an error, inputs are the tables\' own', async () => {
    const core = await loadCore();
    const { list, handle } = openChecks(core, { stage: '01' });
    try {
        const sphere = list.find((f) => f.name === 'intersectSphere');
        const texels = handle.texels('intersectSphere');
        assert.equal(texels.length, 4 * 4 * sphere.cases, 'four RGBA rows, one texel per case');
        assert.ok(texels.every(Number.isFinite));
        // A hit at t = 1 everywhere (w = 1: no stub reached) is wrong for most cases.
        const everywhereOne = new Float32Array(4 * sphere.cases).map((_, i) => (i % 4 === 0 || i % 4 === 3 ? 1 : 0));
        const s = JSON.parse(handle.score('intersectSphere', everywhereOne));
        assert.ok(s.passed < s.total / 2, `${s.passed}/${s.total} passed`);
        assert.match(s.firstFailure, /expected|got/);
        assert.match(JSON.parse(handle.score('intersectSphere', new Float32Array(4))).error,
            /intersectSphere: 1 results for \d+ cases/);
        assert.match(JSON.parse(handle.score('blinnPhong', everywhereOne)).error, /has no function check 'blinnPhong'/);
    } finally { handle.delete(); }
    assert.match(openChecks(core, { stage: '99' }).error, /99/);
});

// A PNG of RGBA bytes (8-bit, no filter), for `raylab compare`.
function png(width, height, rgba) {
    const chunk = (type, data) => {
        const len = Buffer.alloc(4);
        len.writeUInt32BE(data.length);
        const body = Buffer.concat([Buffer.from(type, 'ascii'), data]);
        const crc = Buffer.alloc(4);
        crc.writeUInt32BE(crc32(body));
        return Buffer.concat([len, body, crc]);
    };
    const header = Buffer.alloc(13);
    header.writeUInt32BE(width, 0);
    header.writeUInt32BE(height, 4);
    header.set([8, 6, 0, 0, 0], 8);
    const rows = Buffer.alloc(height * (1 + 4 * width));
    for (let y = 0; y < height; ++y) rows.set(rgba.subarray(4 * width * y, 4 * width * (y + 1)), y * (1 + 4 * width) + 1);
    return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', header),
        chunk('IDAT', deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
}

function picture(width, height, shade) {
    const rgba = new Uint8Array(4 * width * height);
    for (let y = 0; y < height; ++y) {
        for (let x = 0; x < width; ++x) rgba.set([...shade(x, y), 255], 4 * (y * width + x));
    }
    return rgba;
}

test('a check view is judged as `raylab compare` judges it', { skip }, async () => {
    const core = await loadCore();
    const w = 40, h = 30;
    const expected = picture(w, h, (x, y) => [6 * x, 8 * y, 100]);
    const cases = {
        same: expected,
        'a corner off': picture(w, h, (x, y) => (x < 8 && y < 6 ? [255, 0, 0] : [6 * x, 8 * y, 100])),
        dark: picture(w, h, (x, y) => [2 * x, 3 * y, 30]),
        black: picture(w, h, () => [0, 0, 0]),
    };
    const dir = mkdtempSync(path.join(tmpdir(), 'raylab-compare-'));
    try {
        writeFileSync(path.join(dir, 'expected.png'), png(w, h, expected));
        for (const [name, mine] of Object.entries(cases)) {
            const file = path.join(dir, 'mine.png');
            writeFileSync(file, png(w, h, mine));
            const r = spawnSync(RAYLAB, ['compare', file, path.join(dir, 'expected.png')], { encoding: 'utf8' });
            const v = JSON.parse(core.compareView(mine, expected, w, h, JSON.stringify({ stage: '02' })));
            assert.equal(v.passed, r.status === 0, `${name}: ${r.stdout}`);
            assert.ok(r.stdout.includes(`(${v.description};`), `${name}: ${r.stdout} vs ${v.description}`);
            assert.equal(v.hint === '', v.passed, `${name}: a failing view gets a hint here (${v.hint})`);
            assert.equal(core.heatMap(mine, expected, w, h).length, 4 * w * h);
        }
        const dark = JSON.parse(core.compareView(cases.dark, expected, w, h, JSON.stringify({ stage: '02' })));
        assert.match(dark.hint, /dark/);
        assert.match(JSON.parse(core.compareView(expected, expected, w, h + 1, '{"stage":"02"}')).error, /40x31 needs 4960 bytes, got 4800/);
    } finally { rmSync(dir, { recursive: true, force: true }); }
});
