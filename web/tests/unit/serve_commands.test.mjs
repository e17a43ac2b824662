// web/README.md's "Run it" commands for the development server, run as
// written (each until it prints its address, then stopped): the plain one
// serves the labs only (no solution file, the catalog says so), with
// --with-solutions the solutions too, and on 0.0.0.0 it warns that anyone
// who can reach the port reads what it serves.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { ROOT } from './scene_support.mjs';

const serveLines = () => {
    const readme = readFileSync(path.join(ROOT, 'web/README.md'), 'utf8');
    const block = /## Run it\n\n```sh\n([\s\S]*?)```/.exec(readme)[1];
    return block.split('\n').filter((l) => l.startsWith('npm --prefix web run serve')).map((l) => l.replace(/\s+#.*$/, ''));
};

// LINE run from the project root until it prints its address: {url, out, err, stop}.
function start(line) {
    const child = spawn('bash', ['-c', `exec ${line}`], { cwd: ROOT, detached: true, stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '', err = '';
    child.stderr.on('data', (d) => { err += d; });
    return new Promise((resolve, reject) => {
        child.stdout.on('data', (d) => {
            out += d;
            const m = /(http:\/\/\S+\/web\/)/.exec(out);
            if (m && /\(--with-solutions|serving the solutions/.test(out)) {
                // Stopped and gone (the port free for the next line) before stop() resolves.
                const stop = () => new Promise((done) => { child.once('exit', done); process.kill(-child.pid); });
                setTimeout(() => resolve({ url: m[1], out, err, stop }), 200);
            }
        });
        child.once('exit', (code) => reject(new Error(`${line}: stopped (exit ${code}): ${out}${err}`)));
    });
}

test('the README\'s serve commands run as written', async () => {
    const lines = serveLines();
    assert.equal(lines.length, 3, lines.join('\n'));
    for (const line of lines) {
        const s = await start(line);
        try {
            const origin = s.url.replace('localhost', '127.0.0.1').replace(/\/web\/$/, '');
            const catalog = await (await fetch(`${origin}/web/dist/catalog.json`)).json();
            const solutionFile = await fetch(`${origin}/solution/01-raycast/intersect_sphere.glsl`);
            const withSolutions = line.includes('--with-solutions');
            assert.equal(catalog.solutions, withSolutions, line);
            assert.equal(solutionFile.status, withSolutions ? 200 : 404, line);
            assert.equal((await fetch(`${origin}/solution/01-raycast/stage.json`)).status, 200, line);
            if (line.includes('--port 9000')) assert.match(s.url, /:9000\/web\/$/);
            if (line.includes('0.0.0.0')) assert.match(s.err, /warning: listening on 0\.0\.0\.0: anyone who can reach port 9000/);
            else assert.equal(s.err, '', line);
        } finally {
            await s.stop();
        }
    }
});
