// `raylab web-bundle`: the students' hosted page (issue: the browser as a
// student's whole workstation). Part of the `web_browser` test:
//  1. the bundle of stages 01-03 holds no solution: no file of solution/ but
//     the stage.json files, no variant file standing in for a student's
//     file, and no text file containing the code of any //@solution region
//     of a stage it holds (whitespace aside); the scan is shown to catch a
//     planted solution file; the same at the open level (--level open), where
//     the code an open region's guided part gives is an answer too (the
//     guided bundle holds it: the scan is shown to see it);
//  2. served by a plain static server (python3 -m http.server), the page
//     offers exactly those stages, labs only, and Check runs on each stage's
//     lab as handed out with native's report, with no failed request.
// Usage: node tests/browser/bundle.mjs [--raylab PATH]
import { execFileSync, spawn } from 'node:child_process';
import { copyFileSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative, resolve } from 'node:path';
import { launchBrowser, openPage, projectRoot } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const raylab = resolve(option('--raylab', join(projectRoot, 'build/raylab')));
const STAGES = ['01-raycast', '02-shading', '03-shadows'];

const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };
const squash = (text) => text.replace(/\s+/g, ' ').trim();

function filesUnder(dir) {
  return readdirSync(dir).flatMap((n) => (statSync(join(dir, n)).isDirectory() ? filesUnder(join(dir, n)) : [join(dir, n)]));
}

// The code of every //@solution region of STAGES' files (up to its //@stub),
// whitespace squashed; at the open level also every run of code an open
// region's guided part gives (the answer at that level), but for runs of
// under 40 characters and those the open stub holds too (a signature).
function solutionRegions(level = 'guided') {
  const regions = [];
  for (const stage of STAGES) {
    for (const file of filesUnder(join(projectRoot, 'solution', stage)).filter((f) => /\.(glsl|vert|frag|geom)$/.test(f))) {
      const lines = readFileSync(file, 'utf8').split('\n');
      const where = (i) => `${relative(projectRoot, file)}:${i + 1}`;
      let stub = '', run = [], runStart = 0, inOpen = false, inStub = false, inSolution = false;
      const endRun = () => {
        const code = squash(run.join('\n'));
        if (code.length >= 40 && !stub.includes(code)) regions.push({ where: where(runStart), code });
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

// What in BUNDLE gives a solution away: one line per finding.
function solutionsIn(bundle, regions) {
  const found = [];
  for (const file of filesUnder(bundle)) {
    const rel = relative(bundle, file);
    if (rel.startsWith('solution/') && !rel.endsWith('/stage.json')) found.push(`${rel}: a file of solution/`);
    if (!/\.(glsl|vert|frag|geom|json|md|html|js|mjs|css|txt)$/.test(file)) continue;
    const text = squash(readFileSync(file, 'utf8'));
    for (const r of regions) if (r.code && text.includes(r.code)) found.push(`${rel}: holds the solution region of ${r.where}`);
  }
  return found;
}

function serveStatically(dir) {
  const child = spawn('python3', ['-m', 'http.server', '0', '--bind', '127.0.0.1', '--directory', dir], { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((res, rej) => {
    let out = '';
    const seen = (d) => {
      out += d;
      const m = /port (\d+)/.exec(out);
      if (m) res({ url: `http://127.0.0.1:${m[1]}`, stop: () => child.kill() });
    };
    child.stdout.on('data', seen);
    child.stderr.on('data', seen);
    child.on('exit', (code) => rej(new Error(`python3 -m http.server stopped (exit ${code}): ${out}`)));
  });
}

const work = mkdtempSync(join(tmpdir(), 'raylab-bundle-'));
const bundle = join(work, 'bundle');
let server, browser;
try {
  const made = execFileSync(raylab, ['web-bundle', '--stages', '01-03', '--out', bundle], { encoding: 'utf8' });
  check(/wrote .* \(01-raycast, 02-shading, 03-shadows\)/.test(made), `raylab web-bundle: ${made.trim().split('\n').pop()}`);
  const regions = solutionRegions();
  check(regions.length >= 5, `${regions.length} solution regions of stages 01-03 to look for`);
  const found = solutionsIn(bundle, regions);
  check(found.length === 0, `the bundle holds no solution${found.length ? `: ${found.slice(0, 5).join('; ')}` : ''}`);
  // The scan catches a planted one.
  const planted = join(work, 'planted');
  execFileSync('cp', ['-r', bundle, planted]);
  copyFileSync(join(projectRoot, 'solution/02-shading/blinn_phong.glsl'), join(planted, 'labs/02-shading/notes.glsl'));
  const caught = solutionsIn(planted, regions);
  check(caught.some((f) => f.startsWith('labs/02-shading/notes.glsl')), `a planted solution file is found: ${caught[0] ?? 'not found'}`);

  // The open level (--level open): no solution region, and none of the code
  // the guided level gives and the open level takes away.
  const openBundle = join(work, 'open');
  execFileSync(raylab, ['web-bundle', '--stages', '01-03', '--level', 'open', '--out', openBundle], { encoding: 'utf8' });
  const openRegions = solutionRegions('open');
  check(openRegions.length > regions.length, `${openRegions.length - regions.length} runs of code the open level takes away, to look for`);
  const openFound = solutionsIn(openBundle, openRegions);
  check(openFound.length === 0, `the open bundle holds no answer of its level${openFound.length ? `: ${openFound.slice(0, 5).join('; ')}` : ''}`);
  const guidedHasThem = solutionsIn(bundle, openRegions).length;
  check(guidedHasThem > 0, `the guided bundle does hold the open level's answers (${guidedHasThem}): the scan sees them`);

  server = await serveStatically(bundle);
  browser = await launchBrowser();
  const { page, problems } = await openPage(browser, `${server.url}/web/`);
  const catalog = await page.evaluate(() => window.raylab.catalog);
  check(JSON.stringify(catalog.stages.map((s) => s.info.id)) === JSON.stringify(STAGES) && catalog.solutions === false,
    `the page offers ${catalog.stages.map((s) => s.info.id).join(', ')}, solutions ${catalog.solutions}`);
  for (const stage of STAGES) {
    const r = await page.evaluate((s) => window.raylab.check({ stage: s, source: 'lab' }), stage);
    check(r.ok && new RegExp(`^raylab check: stage ${stage}, lab labs/ against the reference pictures`, 'm').test(r.report) && r.failed > 0,
      `Check on ${stage} as handed out: ${r.ok ? r.report.trim().split('\n').pop() : r.error}`);
  }
  check(problems.length === 0, `no console errors, page errors or failed requests${problems.length ? `: ${problems.join('; ')}` : ''}`);
} finally {
  await browser?.close();
  server?.stop();
  rmSync(work, { recursive: true, force: true });
}
if (failures.length) {
  console.log(`\n${failures.length} bundle check(s) failed`);
  process.exit(1);
}
