// The C++ core in WebAssembly (dist/core/raylab_core.js) under node, with the
// project's files in its file system as the page puts them there
// (src/core/core.ts): the tree under /raylab, the core's working folder
// /student. A scene outside the project is written at its own absolute path,
// so that messages name it as the native build does.
import { createRequire } from 'node:module';
import path from 'node:path';
import { readdirSync, readFileSync, statSync } from 'node:fs';

import { ROOT } from './scene_support.mjs';

const require = createRequire(import.meta.url);
let loaded;

function copyTree(core, rel, to = `/raylab/${rel}`) {
    core.FS.mkdirTree(to);
    for (const name of readdirSync(path.join(ROOT, rel))) {
        const r = `${rel}/${name}`;
        if (statSync(path.join(ROOT, r)).isDirectory()) copyTree(core, r, `${to}/${name}`);
        else core.FS.writeFile(`${to}/${name}`, readFileSync(path.join(ROOT, r)));
    }
}

export function loadCore() {
    loaded ??= require('../../dist/core/raylab_core.js')({
        preRun: [(m) => { m.ENV.RAYLAB_ROOT = '/raylab'; }],
    }).then((core) => {
        for (const d of ['framework/shaders', 'solution', 'labs', 'assets', 'web/shaders']) copyTree(core, d);
        core.FS.writeFile('/raylab/web/function_tables.json', readFileSync(path.join(ROOT, 'web/function_tables.json')));
        // The pictures also at their absolute host paths: made-up scenes in
        // temporary folders name them so.
        copyTree(core, 'assets', `${ROOT}/assets`);
        core.FS.mkdirTree('/student');
        core.FS.chdir('/student');
        return core;
    });
    return loaded;
}

// The core's path for FILE: under /raylab for a project path, else the
// absolute path itself (its text copied in).
export function coreScenePath(core, file) {
    if (!path.isAbsolute(file)) return `/raylab/${file}`;
    core.FS.mkdirTree(path.dirname(file));
    core.FS.writeFile(file, readFileSync(file));
    return file;
}

// REQUEST as the page sends it: { info, handle } or { error }.
export function openRayStage(core, request) {
    const handle = new core.RayStage(JSON.stringify(request));
    const error = handle.error();
    if (error) {
        handle.delete();
        return { error };
    }
    return { info: JSON.parse(handle.info()), handle };
}

// An assembled source as `raylab shader --origins` prints it.
export function withOrigins(source) {
    const lines = source.text.split('\n');
    return source.origin.map(([file, line], i) => `${file}:${line}\t${lines[i]}`).join('\n') + '\n';
}
