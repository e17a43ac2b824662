// The search for answers in what students get, shared by the page's bundle
// test (browser/bundle.mjs) and the student repository's
// (tests/e2e/student_repo_test.cpp runs this file on one): every stage's
// //@solution regions, the checks' stand-ins, and in a student repository's
// C++ the reference tracer's code and the checks' references.
// Usage: node tests/answer_search.mjs --student-repo DIR
// (prints what it finds, one line each; exit 1 if anything).
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const projectRoot = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const SHADER = /\.(glsl|vert|frag|geom)$/;
const ALL_STAGES = readdirSync(join(projectRoot, 'solution')).filter((id) => existsSync(join(projectRoot, 'solution', id, 'stage.json'))).sort();
const squash = (text) => text.replace(/\s+/g, ' ').trim();

export function filesUnder(dir) {
  return readdirSync(dir).flatMap((n) => (statSync(join(dir, n)).isDirectory() ? filesUnder(join(dir, n)) : [join(dir, n)]));
}

// Where a release keeps the released stages' reference pictures and function tables.
export const BUNDLE = { references: 'tests/reference', tables: 'web/function_tables.json' };
export const STUDENT_REPO = { references: 'course/references', tables: 'course/function_tables.json' };

// The code of every //@solution region of every stage's files (up to its
// //@stub), whitespace squashed; at the open level also every run of code an
// open region's guided part gives (the answer at that level), but for runs of
// under 40 characters and those the open stub holds too (a signature).
export function solutionRegions(level = 'guided') {
  const regions = [];
  for (const stage of ALL_STAGES) {
    for (const file of filesUnder(join(projectRoot, 'solution', stage)).filter((f) => SHADER.test(f))) {
      const lines = readFileSync(file, 'utf8').split('\n');
      const where = (i) => `${relative(projectRoot, file)}:${i + 1}`;
      let stub = '', run = [], runStart = 0, inOpen = false, inStub = false, inSolution = false;
      const endRun = () => {
        const code = squash(run.join('\n'));
        if (code.length >= 40 && !squash(stub).includes(code)) regions.push({ where: where(runStart), code });
        run = [];
      };
      for (let i = 0; i < lines.length; ++i) {
        const t = lines[i].trim();
        if (t === '//@solution') {
          if (inOpen) endRun();
          const body = [];
          for (++i; i < lines.length && !lines[i].trim().startsWith('//@stub'); ++i) body.push(lines[i]);
          regions.push({ where: where(i - body.length), code: squash(body.join('\n')) });
          inSolution = true;
        } else if (t === '//@end') {
          inSolution = false;
          runStart = i + 1;
        } else if (t === '//@open') {
          inStub = true;
          stub = '';
        } else if (t === '//@guided') {
          inStub = false;
          inOpen = level === 'open';
          runStart = i + 1;
        } else if (t === '//@end-open') {
          if (inOpen) endRun();
          inOpen = false;
        } else if (inStub) {
          stub += ' ' + squash(t.replace(/^\/\/@ ?/, ''));
        } else if (inOpen && !inSolution && !t.startsWith('//@') && !t.startsWith('//')) {
          run.push(lines[i]);
        }
      }
    }
  }
  return regions;
}

// Every check's harness GLSL (stand-ins, helpers) from the project's tables,
// by function: a bundle may hold those of its released stages' checks only.
export const projectTables = JSON.parse(readFileSync(join(projectRoot, 'web/function_tables.json'), 'utf8')).functions;
export function standIns(released) {
  const allowed = new Set(released.flatMap((f) => [projectTables[f].prelude, projectTables[f].helpers]).map(squash));
  return Object.entries(projectTables).filter(([name]) => !released.includes(name))
    .flatMap(([name, t]) => [t.prelude, t.helpers].map((code) => ({ where: `${name}'s harness`, code: squash(code) })))
    .filter((r) => r.code.length >= 40 && !allowed.has(r.code));
}

// The WebAssembly inside the core's script (a data URL) as text, for its strings.
function wasmStrings(coreJs) {
  const m = /data:application\/octet-stream;base64,([A-Za-z0-9+/=]+)/.exec(readFileSync(coreJs, 'utf8'));
  if (!m) throw new Error(`${coreJs}: no WebAssembly inside`);
  return Buffer.from(m[1], 'base64').toString('latin1').replace(/[^\x20-\x7e\n]+/g, '\n');
}

// The files under assets/ that the RELEASED stages draw: their scenes (each
// stage's own and its check views') and every .png or .obj a scene names
// (relative to the scene's folder), with assets/LICENSES.md and the scenes'
// README. Read from the scene files here, not from the C++ that writes the
// release, so that the two are checked against each other.
export function releasedAssets(released) {
  const files = new Set(['assets/LICENSES.md', 'assets/scenes/README.md']);
  const named = (value, out) => {
    if (typeof value === 'string') { if (/\.(png|obj)$/.test(value)) out.push(value); }
    else if (value && typeof value === 'object') for (const v of Object.values(value)) named(v, out);
    return out;
  };
  for (const id of released) {
    const stage = JSON.parse(readFileSync(join(projectRoot, 'solution', id, 'stage.json'), 'utf8'));
    for (const scene of [stage.scene, ...(stage.check_views ?? []).map((v) => v.scene).filter(Boolean)]) {
      const file = `assets/scenes/${scene}`;
      files.add(file);
      for (const p of named(JSON.parse(readFileSync(join(projectRoot, file), 'utf8')), []))
        files.add(relative(projectRoot, join(projectRoot, dirname(file), p)));
    }
  }
  return files;
}

// What in BUNDLE gives away an answer or holds a stage it does not release: one line per finding.
// CARRY: solved, where the earlier stages the bundle does not release come
// solved (their answers are the course's to give).
export function leaksIn(bundle, released, level, carry = 'own', layout = BUNDLE) {
  const found = [];
  const stagesHeld = new Set(released);
  for (const id of released)  // and those they build on
    for (let at = JSON.parse(readFileSync(join(projectRoot, 'solution', id, 'stage.json'), 'utf8')).builds_on; at;
      at = JSON.parse(readFileSync(join(projectRoot, 'solution', at, 'stage.json'), 'utf8')).builds_on) stagesHeld.add(at);
  const carried = carry === 'solved' ? [...stagesHeld].filter((id) => !released.includes(id)) : [];
  const functions = released.flatMap((id) => JSON.parse(readFileSync(join(projectRoot, 'solution', id, 'stage.json'), 'utf8')).function_checks ?? []);
  const assets = releasedAssets(released);
  const searched = [...solutionRegions(level).filter((r) => !carried.some((id) => r.where.startsWith(`solution/${id}/`))),
    ...standIns([...new Set(functions)])];
  for (const file of filesUnder(bundle)) {
    const rel = relative(bundle, file);
    const parts = rel.split('/');
    if (rel.startsWith('solution/') && !rel.endsWith('/stage.json')) found.push(`${rel}: a file of solution/`);
    if (parts[0] === 'solution' && !stagesHeld.has(parts[1])) found.push(`${rel}: a later stage's stage.json`);
    if (parts[0] === 'labs' && parts.length > 2 && !stagesHeld.has(parts[1])) found.push(`${rel}: a lab of a stage not handed out`);
    if (rel.startsWith(`${layout.references}/`) && !released.includes(parts[2])) found.push(`${rel}: a reference of a stage not released`);
    if (rel.startsWith('framework/shaders/variants/') && !stagesHeld.has(parts[4])) found.push(`${rel}: a variant of a stage not released`);
    if (/test_api/.test(rel)) found.push(`${rel}: the page's test API`);
    if (parts[0] === 'assets' && !assets.has(rel)) found.push(`${rel}: an asset no released stage draws`);
    if (!/\.(glsl|vert|frag|geom|json|md|html|js|mjs|css|txt|cpp|h|sh)$/.test(file)) continue;
    const text = squash(rel.endsWith('raylab_core.js') ? `${readFileSync(file, 'utf8')}\n${wasmStrings(file)}` : readFileSync(file, 'utf8'));
    for (const r of searched) if (r.code && text.includes(r.code)) found.push(`${rel}: holds ${r.where.endsWith('harness') ? 'the stand-ins of ' : 'the solution region of '}${r.where}`);
  }
  const tables = Object.keys(JSON.parse(readFileSync(join(bundle, layout.tables), 'utf8')).functions);
  for (const f of tables) if (!functions.includes(f)) found.push(`${layout.tables}: the table of ${f}, a check of a stage not released`);
  return found;
}

// In a student repository's C++ (framework/src, written by `raylab
// student-repo`): no line of the reference tracer or the fur references
// (fur_reference and silhouette: TODO f3.a's answer in C++) (30
// characters or more, not a comment, found nowhere else in the project's
// framework/src), no line of any check's stand-ins (they come as data, in
// course/function_tables.json; lines that compute: an assignment or a
// return, not a signature or a declaration), and no reference or stand-in left in a
// RAYLAB_REFERENCE, RAYLAB_REFERENCE_FUNCTION or RAYLAB_HARNESS_GLSL call.
function referenceLines() {
  const src = join(projectRoot, 'framework/src');
  const isReference = (f) => f.includes('/raytrace/reference/') || /\/(fur_reference|silhouette)\.(h|cpp)$/.test(f);
  const code = (text) => text.split('\n').map((l) => l.trim()).filter((l) => l.length >= 30 && !l.startsWith('//') && !l.startsWith('#'));
  const files = filesUnder(src).filter((f) => /\.(h|cpp)$/.test(f));
  const elsewhere = new Set(files.filter((f) => !isReference(f)).flatMap((f) => code(readFileSync(f, 'utf8'))));
  return [...new Set(files.filter(isReference).flatMap((f) => code(readFileSync(f, 'utf8'))))].filter((l) => !elsewhere.has(l));
}

function standInLines() {
  return [...new Set(Object.values(projectTables).flatMap((t) => `${t.prelude}\n${t.helpers}`.split('\n')))]
    .map((l) => l.trim()).filter((l) => l.length >= 25 && !l.startsWith('//') && /=|\breturn\b/.test(l));
}

export function cppLeaksIn(repo) {
  const found = [];
  const refs = referenceLines(), stand = standInLines();
  for (const file of filesUnder(join(repo, 'framework'))) {
    if (!/\.(h|cpp)$/.test(file)) continue;
    const rel = relative(repo, file);
    const text = readFileSync(file, 'utf8');
    const lines = new Set(text.split('\n').map((l) => l.trim()));
    for (const l of refs) if (lines.has(l)) { found.push(`${rel}: holds the reference tracer's line "${l}"`); break; }
    for (const l of stand) if (text.includes(l)) { found.push(`${rel}: holds the stand-in line "${l}"`); break; }
    for (const line of text.split('\n')) {
      if (/^\s*(#|\/\/)/.test(line)) continue;
      if (/RAYLAB_REFERENCE\(\s*\w+\s*,\s*(?!\s|nullptr\))/.test(line) || /RAYLAB_REFERENCE_FUNCTION\((?!nullptr\))/.test(line) ||
        /RAYLAB_HARNESS_GLSL\((?!""\))/.test(line)) found.push(`${rel}: a reference or stand-in left in "${line.trim()}"`);
    }
  }
  return found;
}

// A student repository: its releases's leaks (as a bundle's) and its C++'s.
export function studentRepoLeaks(repo) {
  const manifest = JSON.parse(readFileSync(join(repo, 'course/student-repo.json'), 'utf8'));
  return [...leaksIn(repo, manifest.stages, manifest.level, manifest.carry, STUDENT_REPO), ...cppLeaksIn(repo)];
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const at = args.indexOf('--student-repo');
  if (at < 0 || !args[at + 1]) {
    console.error('usage: node tests/answer_search.mjs --student-repo DIR');
    process.exit(2);
  }
  const found = studentRepoLeaks(args[at + 1]);
  for (const f of found) console.log(f);
  console.log(`${found.length} finding${found.length === 1 ? '' : 's'}: ${solutionRegions().length} solution regions, ${standInLines().length} stand-in lines and ${referenceLines().length} reference lines searched`);
  process.exit(found.length ? 1 : 0);
}
