// Shared by the scene tests: the project's paths, the scene files, and the
// native build (build/raylab) to compare with. Tests that need the native
// binary skip, saying why, when it is missing or lacks a command.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
export const RAYLAB = process.env.RAYLAB ?? path.join(ROOT, 'build/raylab');

// assets/scenes/*.json (not fur/), as the native build shows them.
export function sceneFiles() {
    return allSceneFiles();
}

function allSceneFiles() {
    return readdirSync(path.join(ROOT, 'assets/scenes'))
        .filter((f) => f.endsWith('.json'))
        .sort()
        .map((f) => `assets/scenes/${f}`);
}


export function runRaylab(args) {
    return spawnSync(RAYLAB, args, { cwd: ROOT, encoding: 'utf8', timeout: 60_000, maxBuffer: 64 << 20 });
}

let shaderReason;
// Why `raylab shader` cannot be used, or null when it can.
export function shaderCommandMissing() {
    if (shaderReason !== undefined) return shaderReason;
    if (!existsSync(RAYLAB)) shaderReason = `no native binary at ${RAYLAB}`;
    else if (runRaylab(['shader', '--help']).status !== 0) shaderReason = `${RAYLAB} has no "shader" command yet`;
    else shaderReason = null;
    return shaderReason;
}

// The native program for stage 08 specialised to FILE (a path under the
// root, or absolute): { text } or { error } (the one-line message).
export function nativeShader(file) {
    const r = runRaylab(['shader', '--stage', '08-full', '--solution', '--scene', file]);
    if (r.status === 0) return { text: r.stdout };
    const line = r.stderr.split('\n').find((l) => l.startsWith('raylab: error: '));
    return { error: line ? line.slice('raylab: error: '.length) : r.stderr.trim() };
}

// A new temporary folder, removed when the test process exits.
const temporary = [];
process.on('exit', () => temporary.forEach((d) => rmSync(d, { recursive: true, force: true })));
export function tempDir() {
    const dir = mkdtempSync(path.join(tmpdir(), 'raylab-web-test-'));
    temporary.push(dir);
    return dir;
}

// Writes TEXT to a new temporary file; returns its absolute path (what the
// native build shows for a file outside the project).
export function tempScene(text, name = 'scene.json') {
    const file = path.join(tempDir(), name);
    writeFileSync(file, text);
    return file;
}
