// `raylab web-bundle`: the students' hosted page (issue: the page as every
// student's whole workstation). Part of the `web_browser` test:
//  1. a bundle holds its released stages only and no answer: no file of
//     solution/ but stage.json (of its stages and those they build on, never a
//     later one), no lab, reference picture or shader variant of a stage it
//     does not release, no scene, picture or mesh its stages do not draw,
//     function tables of its stages' checks only, no page
//     test API, and no text of any stage's //@solution region (at the open
//     level also the code the guided level gives) or of an unreleased check's
//     stand-ins in any file, the WebAssembly core's strings included; the scan
//     is shown to catch a planted solution file and a planted stand-in;
//  2. served by a plain static server (python3 -m http.server), a bundle of
//     every single stage and ranges of both tracks, both levels, both carries
//     (each holding its stages only, as in 1) open with their stages only,
//     the Guide link shows the stage's guide rendered with its pictures and
//     naming nothing that needs the solution (a student repository's), and
//     the page's own Check button (no test hook: a bundle has none) gives a
//     verdict on a solved lab folder
//     picked through the browser's folder input (passes) and, for the first
//     stages of both tracks and the ranges, on the lab as handed out (fails),
//     with no failed request.
// Usage: node tests/browser/bundle.mjs [--raylab PATH] [--only TEXT]
import { execFileSync, spawn } from 'node:child_process';
import { appendFileSync, copyFileSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative, resolve } from 'node:path';
import { collectProblems, launchBrowser, projectRoot } from './browser.mjs';
import { filesUnder, leaksIn, projectTables, SHADER, solutionRegions } from '../answer_search.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const raylab = resolve(option('--raylab', join(projectRoot, 'build/raylab')));
const only = option('--only', '');  // the bundles whose name holds TEXT (while working on one)
const ALL_STAGES = readdirSync(join(projectRoot, 'solution')).filter((id) => existsSync(join(projectRoot, 'solution', id, 'stage.json'))).sort();

const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };

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
const bundleOf = (name, ...opts) => {
  const out = join(work, name);
  const made = execFileSync(raylab, ['web-bundle', ...opts, '--out', out], { encoding: 'utf8' });
  return { out, made };
};

// The page of a bundle as a student opens it; its console errors and failed requests collected.
// The folder input stands in for the folder picker (as in Firefox and Safari).
async function openBundle(browser, url) {
  const page = await browser.newPage();
  const problems = collectProblems(page);
  await page.evaluateOnNewDocument(() => { delete window.showDirectoryPicker; });
  await page.goto(`${url}/web/`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.getElementById('stage').options.length > 0, { timeout: 60_000 });
  return { page, problems };
}

const settled = (page) => page.waitForFunction(() => !document.getElementById('view').classList.contains('building') &&
  !/^building /.test(document.getElementById('messages').textContent), { timeout: 300_000 });

// Presses Check and waits for the report (or its one-line error).
// (The panel is emptied first, so that an earlier report is not taken for this one.)
async function pressCheck(page) {
  await settled(page);
  await page.$eval('#messages', (m) => { m.textContent = ''; });
  await page.click('#check');
  await page.waitForFunction(() => /\d+ passed, \d+ failed|^raylab check: /m.test(document.getElementById('messages').textContent), { timeout: 300_000 });
  return page.$eval('#messages', (m) => m.textContent);
}

const choose = (page, id, value) => page.evaluate((i, v) => {
  const sel = document.getElementById(i);
  sel.value = v;
  sel.dispatchEvent(new Event('change'));
}, id, value);

// FILE solved, as stage ID reads it: its own, or that of the stage it builds on that has it.
function solvedFile(id, file) {
  for (let at = id; at; at = JSON.parse(readFileSync(join(projectRoot, 'solution', at, 'stage.json'), 'utf8')).builds_on)
    if (existsSync(join(projectRoot, 'solution', at, file))) return join(projectRoot, 'solution', at, file);
  throw new Error(`no solution of ${file} for ${id}`);
}

// A student's labs/ folder with STAGE and the folders of the bundle's labs/
// beside it solved: each shader file the bundle hands out, from solution/.
function solvedFolder(bundle, name) {
  const root = join(work, `${name}-solved`, 'labs');
  for (const id of readdirSync(join(bundle, 'labs')).filter((n) => statSync(join(bundle, 'labs', n)).isDirectory())) {
    mkdirSync(join(root, id), { recursive: true });
    for (const f of readdirSync(join(bundle, 'labs', id)).filter((n) => SHADER.test(n)))
      copyFileSync(solvedFile(id, f), join(root, id, f));
  }
  return root;
}

let browser;
const servers = [];
try {
  // 1. What a bundle holds.
  const guided = bundleOf('guided', '--stages', '01-03');
  check(/wrote .* \(01-raycast, 02-shading, 03-shadows\)/.test(guided.made), `raylab web-bundle: ${guided.made.trim().split('\n').pop()}`);
  const released = ['01-raycast', '02-shading', '03-shadows'];
  check(solutionRegions().length >= 30, `${solutionRegions().length} solution regions of all ${ALL_STAGES.length} stages to look for`);
  const found = leaksIn(guided.out, released, 'guided');
  check(found.length === 0, `the 01-03 bundle holds nothing of 04-08 and f1-f4 and no answer${found.length ? `: ${found.slice(0, 6).join('; ')}` : ''}`);
  // The scan catches a planted solution, a planted stand-in and a later stage's table.
  const planted = join(work, 'planted');
  execFileSync('cp', ['-r', guided.out, planted]);
  copyFileSync(join(projectRoot, 'solution/02-shading/blinn_phong.glsl'), join(planted, 'labs/02-shading/notes.glsl'));
  writeFileSync(join(planted, 'web/dist/notes.txt'), projectTables.lightVisibleFast.prelude);
  copyFileSync(join(projectRoot, 'assets/scenes/pro.json'), join(planted, 'assets/scenes/pro.json'));
  const tables = JSON.parse(readFileSync(join(planted, 'web/function_tables.json'), 'utf8'));
  tables.functions.trace = projectTables.trace;
  writeFileSync(join(planted, 'web/function_tables.json'), JSON.stringify(tables));
  const caught = leaksIn(planted, released, 'guided');
  for (const what of ['labs/02-shading/notes.glsl: holds the solution region', "web/dist/notes.txt: holds the stand-ins of lightVisibleFast's", 'web/function_tables.json: the table of trace', 'assets/scenes/pro.json: an asset no released stage draws'])
    check(caught.some((f) => f.startsWith(what)), `planted, found: ${caught.find((f) => f.startsWith(what)) ?? `not found (${what})`}`);
  // The open level: none of the code the guided level gives and the open level takes away.
  const open = bundleOf('open', '--stages', '01-03', '--level', 'open');
  const openFound = leaksIn(open.out, released, 'open');
  check(openFound.length === 0, `the open bundle holds no answer of its level${openFound.length ? `: ${openFound.slice(0, 5).join('; ')}` : ''}`);
  const guidedHasThem = leaksIn(guided.out, released, 'open').length;
  check(guidedHasThem > 0, `the guided bundle does hold the open level's answers (${guidedHasThem}): the scan sees them`);

  // 2. Bundles of single stages and ranges, both tracks, levels and carries:
  // each opens with its stages only and checks the lab as handed out and a solved one.
  // Every stage alone (levels and carries alternating, so that each occurs on
  // both tracks) and ranges of both tracks.
  const sets = [
    ...ALL_STAGES.map((id, i) => ({
      name: `${id}-${i % 2 ? 'open' : 'guided'}-${i % 4 < 2 ? 'own' : 'solved'}`,
      opts: ['--stages', id.split('-')[0], '--level', i % 2 ? 'open' : 'guided', '--carry', i % 4 < 2 ? 'own' : 'solved'],
      stages: [id],
    })),
    { name: '03-04-guided-own', opts: ['--stages', '03-04'], stages: ['03-shadows', '04-recursion'], earlierSlip: '01-raycast/intersect_sphere.glsl' },
    { name: 'f1-f2-open-own', opts: ['--stages', 'f1-f2', '--level', 'open'], stages: ['f1-mesh', 'f2-shells'] },
  ];
  // The lab as handed out must fail in a bundle's Check too (a Check that
  // passes everything would pass the solved labs): shown on both tracks, both
  // levels and carries, and the ranges. Every stage's lab failing its checks is
  // check_parity's (the same page, every catalogued mistake); here each stage
  // alone shows that its bundle has what its Check needs.
  const failsHandedOut = (set) => set.stages.length > 1 || /^(01|02|03|f1|f2)-/.test(set.name);
  browser = await launchBrowser();
  for (const set of sets.filter((x) => x.name.includes(only))) {
    const b = bundleOf(set.name, ...set.opts);
    const level = set.opts.includes('open') ? 'open' : 'guided';
    const leaks = leaksIn(b.out, set.stages, level, set.opts.includes('solved') ? 'solved' : 'own');
    check(leaks.length === 0, `${set.name}: holds its stages only, no answer${leaks.length ? `: ${leaks.slice(0, 4).join('; ')}` : ''}`);
    const server = await serveStatically(b.out);
    servers.push(server);
    const { page, problems } = await openBundle(browser, server.url);
    const offered = await page.$$eval('#stage option', (os) => os.map((o) => o.value));
    check(JSON.stringify(offered) === JSON.stringify(set.stages), `${set.name}: the page offers ${offered.join(', ')}`);
    const stage = set.stages[set.stages.length - 1];
    await choose(page, 'stage', stage);
    // The stage's guide, from the page's Guide link: rendered, its pictures loaded, the page's words first.
    const guideUrl = await page.$eval('#guide-link', (a) => a.href);
    const guide = await browser.newPage();
    const guideProblems = collectProblems(guide);
    await guide.goto(guideUrl, { waitUntil: 'networkidle0' });
    const shown = await guide.evaluate(() => ({
      heading: document.querySelector('#guide h1')?.textContent ?? '',
      pictures: [...document.images].map((i) => i.naturalWidth > 0),
      note: document.getElementById('in-the-page').textContent,
      text: document.getElementById('guide').textContent,
    }));
    check(/^Lab \S+ - /.test(shown.heading) && shown.pictures.length >= 2 && shown.pictures.every(Boolean) &&
      /Check is raylab check/.test(shown.note.replace(/\s+/g, ' ')) && /Trace a pixel/.test(shown.note) && guideProblems.length === 0,
      `${set.name}: the Guide link shows "${shown.heading}" with ${shown.pictures.filter(Boolean).length}/${shown.pictures.length} pictures${guideProblems.length ? `; ${guideProblems.join('; ')}` : ''}`);
    // A student's guide, as in a student repository: nothing that needs the solution.
    const needsSolution = shown.text.match(/--solution|--reference|raylab demo|solution\//g) ?? [];
    check(needsSolution.length === 0 && !/own tracer/.test(shown.note),
      `${set.name}: the guide names nothing that needs the solution${needsSolution.length ? ` (it names ${[...new Set(needsSolution)].join(', ')})` : ''}`);
    await guide.close();
    if (failsHandedOut(set)) {
      await choose(page, 'source', 'lab');
      const handedOut = await pressCheck(page);
      check(new RegExp(`^raylab check: stage ${stage}, lab labs/ against the reference pictures`, 'm').test(handedOut) && /\d+ passed, [1-9]\d* failed/.test(handedOut),
        `${set.name}: Check on ${stage} as handed out: ${handedOut.match(/\d+ passed, \d+ failed/)?.[0] ?? handedOut.split('\n')[0]}`);
    }
    const folder = solvedFolder(b.out, set.name);
    const [chooser] = await Promise.all([page.waitForFileChooser(), choose(page, 'source', 'disk')]);
    await chooser.accept([folder]);
    // The picked folder's line (the work kept in the browser, which a
    // bundle opens on, says "Your files" too).
    await page.waitForFunction(() => /Your files: .*\(Reload my files after editing\)/.test(document.getElementById('messages').textContent), { timeout: 300_000 });
    const solved = await pressCheck(page);
    check(/ 0 failed/.test(solved), `${set.name}: Check on ${stage} solved: ${solved.match(/\d+ passed, \d+ failed/)?.[0] ?? solved.split('\n').slice(0, 3).join(' / ')}` +
      solved.split('\n').filter((l) => /^ {2}FAIL|^ {7}/.test(l)).slice(0, 4).map((l) => `\n    ${l.trim()}`).join(''));
    if (set.earlierSlip) {
      // A slip in an earlier stage's folder: named there, as natively, not in the stage's own.
      const file = set.earlierSlip;
      appendFileSync(join(folder, file), '\n#error a slip in an earlier stage\n');
      const [again] = await Promise.all([page.waitForFileChooser(), page.click('#reload')]);
      await again.accept([folder]);
      const named = await page.waitForFunction(() => /slip in an earlier stage/.test(document.getElementById('messages').textContent), { timeout: 300_000 })
        .then(() => page.$eval('#messages', (m) => m.textContent));
      check(named.includes(`labs/${file}:`), `${set.name}: a slip in ${file} is named there: ${named.split('\n').find((l) => /slip/.test(l))?.trim()}`);
    }
    check(problems.length === 0, `${set.name}: no console errors, page errors or failed requests${problems.length ? `: ${problems.join('; ')}` : ''}`);
    await page.close();
  }
} finally {
  await browser?.close();
  for (const s of servers) s.stop();
  rmSync(work, { recursive: true, force: true });
}
if (failures.length) {
  console.log(`\n${failures.length} bundle check(s) failed`);
  process.exit(1);
}
