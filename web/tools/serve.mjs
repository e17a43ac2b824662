// Serves the web build locally:
//   npm run serve [-- --port N] [-- --host H] [-- --with-solutions]
// Only what the page reads is served (web/ without node_modules, the
// shaders, labs/, assets/, each stage's stage.json, the check views'
// reference pictures), read-only, from the
// project root, so the page loads the very files the native build compiles.
// The solutions (solution/'s code, and the variant files that replace a file
// students write) only with --with-solutions: the page then also draws the
// solution and the demos. Anywhere but on loopback it warns, since anyone who
// can reach the port reads what it serves.
import { createServer } from 'node:http';
import { createReadStream, existsSync, readFileSync, realpathSync, statSync } from 'node:fs';
import { pipeline } from 'node:stream';
import { extname, join, normalize, sep, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const realRoot = realpathSync(root);
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && args[i + 1] ? args[i + 1] : fallback;
};
const port = Number(option('--port', process.env.PORT ?? '8080'));
const host = option('--host', '127.0.0.1');
const withSolutions = args.includes('--with-solutions');
if (!Number.isInteger(port) || port < 0 || port > 65535) {
  console.error(`serve: --port ${option('--port')}: expected a port number 0..65535`);
  process.exit(2);
}
if (!existsSync(join(root, 'web/dist/app/main.js'))) {
  console.error('serve: web/dist is missing: run `npm run build` in web/ first');
  process.exit(2);
}

// tests/reference/: the check views' pictures, which the page's Check compares with.
const ALLOWED = ['web/', 'framework/shaders/', 'solution/', 'labs/', 'assets/', 'tests/reference/'];

// Whether students write FILE as stage STAGE reads it: its solved form (the
// newest of the stage's chain in solution/) has regions a lab takes away (as
// raylab web-bundle decides, cmd_web_bundle.cpp).
function studentsWrite(stage, file) {
  for (let at = stage; at; at = JSON.parse(readFileSync(join(root, 'solution', at, 'stage.json'), 'utf8')).builds_on) {
    const path = join(root, 'solution', at, file);
    if (existsSync(path)) return /\/\/@(solution|open)\b/.test(readFileSync(path, 'utf8'));
  }
  return false;
}

// A solution's file: solution/'s code (its stage.json files are data the
// page needs), or a variant file under framework/shaders/variants/<v>/<stage>/
// that stands in for a file students write (the demo's levers are written in
// solved code; a variant of a provided file, surface_at.glsl with meshes, is
// no answer).
function isSolution(relPath) {
  const parts = relPath.split('/');
  if (parts[0] === 'solution') return parts.length !== 3 || parts[2] !== 'stage.json';
  if (parts.slice(0, 3).join('/') === 'framework/shaders/variants' && parts.length === 6)
    return !existsSync(join(root, 'solution', parts[4], 'stage.json')) || studentsWrite(parts[4], parts[5]);
  return false;
}

// The catalog without the solutions: the page then offers labs only.
function catalogWithoutSolutions(text) {
  const catalog = JSON.parse(text);
  catalog.solutions = false;
  for (const s of catalog.stages) s.solutionFiles = [];
  for (const [folder, names] of Object.entries(catalog.variants))
    catalog.variants[folder] = names.filter((n) => !isSolution(`framework/shaders/variants/${folder}/${n}`));
  return JSON.stringify(catalog);
}
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.css': 'text/css',
  '.json': 'application/json', '.map': 'application/json', '.png': 'image/png', '.md': 'text/markdown; charset=utf-8',
  '.glsl': 'text/plain; charset=utf-8', '.vert': 'text/plain; charset=utf-8', '.frag': 'text/plain; charset=utf-8',
  '.geom': 'text/plain; charset=utf-8', '.obj': 'text/plain; charset=utf-8',
};

const server = createServer((req, res) => {
  let path;
  try {
    path = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
  } catch {
    res.writeHead(400).end('bad request');
    return;
  }
  if (path === '' || path === 'web') {
    res.writeHead(302, { Location: '/web/' }).end();
    return;
  }
  if (path.endsWith('/')) path += 'index.html';
  const rel = normalize(path);
  const file = join(root, rel);
  const allowed = !rel.startsWith('..') && ALLOWED.some((p) => rel.split(sep).join('/').startsWith(p)) &&
    !rel.split(sep).includes('node_modules');
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    res.writeHead(405).end();
    return;
  }
  // A symbolic link must not lead out of the project (students' lab folders
  // are theirs; with --host 0.0.0.0 others can ask too).
  let real = '';
  try {
    real = realpathSync(file);
  } catch {}
  if (!allowed || !real || !real.startsWith(realRoot + sep) || !statSync(real).isFile()) {
    res.writeHead(404, { 'Content-Type': 'text/plain' }).end(`not found: /${path}`);
    return;
  }
  const relPath = rel.split(sep).join('/');
  if (!withSolutions && isSolution(relPath)) {
    res.writeHead(404, { 'Content-Type': 'text/plain' })
      .end(`not served: /${path} is a solution (start the server with --with-solutions to serve them)`);
    return;
  }
  const type = TYPES[extname(file)] ?? 'application/octet-stream';
  if (!withSolutions && relPath === 'web/dist/catalog.json') {
    let body;
    try {
      body = catalogWithoutSolutions(readFileSync(real, 'utf8'));
    } catch (e) {
      res.writeHead(500, { 'Content-Type': 'text/plain' }).end(`web/dist/catalog.json: ${e.message}`);
      return;
    }
    res.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-cache' });
    return void res.end(req.method === 'HEAD' ? undefined : body);
  }
  res.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-cache' });
  if (req.method === 'HEAD') return void res.end();
  // pipeline: a file that cannot be read, or a client that goes away, ends
  // this response only (and closes the file), never the server.
  pipeline(createReadStream(real), res, () => {});
});
server.on('error', (e) => {
  console.error(`serve: cannot listen on ${host}:${port}: ${e.code === 'EADDRINUSE' ? 'the port is in use (try --port N)' : e.message}`);
  process.exit(2);
});
server.listen(port, host, () => {
  const { port: actual } = server.address();
  console.log(`RayLab web: http://${host === '0.0.0.0' ? 'localhost' : host}:${actual}/web/  (Ctrl+C stops)`);
  console.log(withSolutions ? 'serving the solutions too (--with-solutions)'
    : 'labs only: the solutions are not served (--with-solutions serves them)');
  if (!['127.0.0.1', 'localhost', '::1'].includes(host)) {
    console.warn(`serve: warning: listening on ${host}: anyone who can reach port ${actual} reads what this serves` +
      (withSolutions ? ', every stage\'s solution included' : ', labs/ included (it holds the earlier stages solved)'));
  }
});
