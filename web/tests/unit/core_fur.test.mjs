// The fur track in the page comes from the C++ core (src/core/core.ts,
// framework/src/wasm/web_fur_stage.h): every fur scene opens for every fur
// stage with its mesh, edge adjacency and programs; every mistake in a fur
// scene file gives native's one-line message (a sample also checked against
// `raylab render` itself); a stage with fins gets its own fin.geom rewritten
// for WebGL 2 and lists its TODOs; key M's meshes are native's.
import assert from 'node:assert/strict';
import { readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { loadCore } from './core_support.mjs';
import { ROOT, runRaylab, shaderCommandMissing, tempDir } from './scene_support.mjs';

const FUR = 'assets/scenes/fur';
const FUR_STAGES = ['f1-mesh', 'f2-shells', 'f3-fins', 'f4-furshader'];

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


function openFur(core, request) {
    const handle = new core.FurStage(JSON.stringify(request));
    const error = handle.error();
    if (error) {
        handle.delete();
        return { error };
    }
    return { handle, info: JSON.parse(handle.info()) };
}

// TEXT written where SHOWN names it in the core's project tree.
function sceneAt(core, text) {
    core.FS.writeFile(`/raylab/${SHOWN}`, text);
    return `/raylab/${SHOWN}`;
}

test('every fur scene opens for every fur stage: mesh, adjacency, programs', async () => {
    const core = await loadCore();
    const files = readdirSync(path.join(ROOT, FUR)).filter((f) => f.endsWith('.json')).sort();
    assert.ok(files.length >= 7, files.join(' '));
    for (const stage of FUR_STAGES)
        for (const f of files) {
            const { handle, info, error } = openFur(core, { stage, scene: `/raylab/${FUR}/${f}` });
            assert.ok(!error, `${stage} ${f}: ${error}`);
            try {
                const n = handle.positions().length / 3;
                assert.equal(n, info.mesh.vertices);
                assert.equal(handle.indices().length, 3 * info.mesh.triangles);
                assert.equal(handle.normals().length, 3 * n);
                assert.equal(handle.uvs().length, 2 * n);
                assert.ok(handle.indices().every((i) => i < n), `${f}: an index past the vertices`);
                const edges = handle.adjacency().length / 4;
                if (stage === 'f1-mesh' || stage === 'f2-shells') assert.equal(edges, 0, 'no fins, no adjacency');
                else assert.ok(edges >= info.mesh.triangles, `${stage} ${f}: ${edges} edges for ${info.mesh.triangles} triangles`);
                assert.equal(Boolean(info.programs.fins), stage >= 'f3', `${stage}: fins`);
                assert.equal(Boolean(info.programs.strands), stage === 'f4-furshader', `${stage}: strands`);
                assert.ok(info.bounds.radius > 0);
                assert.equal(handle.modelMatrix(0).length, 16);
            } finally {
                handle.delete();
            }
        }
});

test('a closed sphere: every edge between two triangles (E = 3T/2)', async () => {
    const core = await loadCore();
    const { handle, info } = openFur(core, { stage: 'f3', scene: sceneAt(core, JSON.stringify(BASE)) });
    try {
        assert.equal(2 * (handle.adjacency().length / 4), 3 * info.mesh.triangles);
    } finally {
        handle.delete();
    }
});

test('fin.geom runs in the page: rewritten into a vertex shader that keeps its lines, fed by fin.vert', async () => {
    const core = await loadCore();
    const { handle, info } = openFur(core, { stage: 'f3', lab: '/raylab/labs' });
    try {
        const fins = info.programs.fins;
        assert.ok(fins.vertex.origin.some(([file]) => file === 'labs/f3-fins/fin.vert'));
        // The emulated shader's lines come from the student's fin.geom (and its includes) but for generated ones.
        const from = new Set(fins.geometry.origin.map(([file]) => file));
        assert.ok(from.has('labs/f3-fins/fin.geom'), [...from].join(', '));
        assert.ok([...from].every((f) => f === '<raylab>' || f.startsWith('labs/') || f.startsWith('framework/')), [...from].join(', '));
        const line = fins.geometry.text.split('\n').findIndex((l) => l.includes('raylab_geometryMain()') && !l.includes(';'));
        assert.equal(fins.geometry.origin[line][0], 'labs/f3-fins/fin.geom', 'main keeps its file and line');
        // lines_adjacency in, triangle strips of at most 4 out: 2 triangles of 3 corners per edge.
        assert.deepEqual([fins.emulation.input, fins.emulation.corners, fins.emulation.output, fins.emulation.slots], ['lines_adjacency', 4, 'triangles', 2]);
        assert.deepEqual(fins.emulation.captured, ['vWorldPos', 'vNormal', 'vUv', 'vLabTodo']);
        assert.ok(info.todos.some((t) => t.file.endsWith('.geom')), JSON.stringify(info.todos));
    } finally {
        handle.delete();
    }
});

test("key M's meshes: native's shapes, each with its own closed adjacency; 0 the scene's again", async () => {
    const core = await loadCore();
    const { FUR_MESHES } = await import(path.join(ROOT, 'web/dist/raytrace/render_settings.js'));
    const { handle, info } = openFur(core, { stage: 'f3', scene: sceneAt(core, variant('mesh.detail', 7)) });
    try {
        assert.deepEqual(info.shapes, FUR_MESHES);
        const edges = [handle.adjacency().length / 4];
        for (let i = 1; i <= FUR_MESHES.length; ++i) {
            handle.showMesh(i);
            const shown = JSON.parse(handle.info());
            assert.equal(shown.mesh.name.split('-')[0], FUR_MESHES[i - 1], JSON.stringify(shown.mesh));
            assert.equal(2 * (handle.adjacency().length / 4), 3 * shown.mesh.triangles, FUR_MESHES[i - 1]);
            edges.push(handle.adjacency().length / 4);
        }
        handle.showMesh(0);
        assert.equal(handle.adjacency().length / 4, edges[0]);
        assert.equal(new Set(edges).size, edges.length, `every mesh its own: ${edges}`);
    } finally {
        handle.delete();
    }
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
    ['mesh.shpe', 1, 'mesh.shpe: unknown key (known here: shape, detail, obj, fit, uvs)'],
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


test('every mistake in a fur scene gets native\'s message', async () => {
    const core = await loadCore();
    for (const [where, value, message] of BAD) {
        const { error } = openFur(core, { stage: 'f1', scene: sceneAt(core, variant(where, value)) });
        assert.equal(error, `${SHOWN}: ${message}`, `${where} = ${JSON.stringify(value)}`);
    }
});

test('a sample of them, given to raylab render, gets the same message', { skip: shaderCommandMissing() ?? false }, async () => {
    const core = await loadCore();
    const dir = tempDir();
    for (const [where, value] of [BAD[0], BAD[10], BAD[22], BAD[40]]) {
        const text = variant(where, value);
        const file = path.join(dir, 'test.json');
        core.FS.mkdirTree(dir);
        core.FS.writeFile(file, text);
        writeFileSync(file, text);
        const r = runRaylab(['render', '--stage', 'f1', '--solution', '--scene', file, '--out', path.join(dir, 'never.png')]);
        const native = r.stderr.split('\n').find((l) => l.startsWith('raylab: error: '))?.slice('raylab: error: '.length);
        const { error } = openFur(core, { stage: 'f1', scene: file });
        assert.equal(error, native, `${where}`);
    }
});
