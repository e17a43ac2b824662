// `raylab check` in the page against native's verdicts (issue: the browser as
// a student's whole workstation). For each stage of both tracks:
//  - the solution passes every check the page runs;
//  - the lab as handed out fails;
//  - each catalogued mistake (tests/mistakes/<stage>/*.json: text
//    replacements in a solved lab, "caught_by" the exact set of checks native
//    `raylab check` fails, which tests/e2e/stage_checks_test.cpp holds it to)
//    fails exactly the same checks in the page, with no exception: the
//    student's geometry shaders (fin.geom, strand.geom) run in the page
//    (emulated: framework/src/core/geometry_emulation.h) and the fin count
//    is counted there.
// For the first mistake of each stage the page's hints and score line must
// also be native's, word for word (native `raylab check` run on the same
// files).
// Default: the first two mistakes of each stage, for trying a change;
// --all: every mistake (ctest web_parity, labels web and web-parity);
// --every N [--offset K]: of all mistakes in course order, those whose index
// is K modulo N (the second and third engines' parity: Chromium runs every
// mistake, Firefox and WebKit each a different sixth; every engine still
// checks every stage's solution and untouched lab).
// Usage: node tests/browser/check_parity.mjs [--all | --every N [--offset K]] [--stages 01,f3] [--labgen PATH]
import { execFileSync } from 'node:child_process';
import { cpSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { launchBrowser, openPage, projectRoot, startServer } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const every = Number(option('--every', '0'));
const offset = Number(option('--offset', '0'));
if (args.includes('--every') && !(Number.isInteger(every) && every >= 1 && offset >= 0 && offset < every)) {
  console.error('check_parity.mjs: --every needs a whole number N >= 1 and --offset one below N');
  process.exit(2);
}
const all = args.includes('--all') || every >= 1;
const labgen = resolve(option('--labgen', join(projectRoot, 'build/raylab-labgen')));
const onlyStages = option('--stages', '').split(',').filter(Boolean);
const raylab = join(projectRoot, 'build/raylab');

// The hint and score lines of a report, as both print them.
const verdictLines = (report) => report.split('\n').filter((l) => /^\s+(hint|note|score): /.test(l)).map((l) => l.trim());
// Native `raylab check` of STAGE on a solved lab whose STAGE files are LABFILES.
function nativeReport(stage, labFiles) {
  const lab = mkdtempSync(join(tmpdir(), 'raylab-parity-'));
  try {
    cpSync(solved, lab, { recursive: true });
    for (const [name, text] of Object.entries(labFiles)) writeFileSync(join(lab, stage.id, name), text);
    try {
      return execFileSync(raylab, ['check', '--stage', stage.id, '--lab', lab], { encoding: 'utf8', stdio: 'pipe' });
    } catch (e) {
      return e.stdout ?? '';  // exit 1: a check failed
    }
  } finally {
    rmSync(lab, { recursive: true, force: true });
  }
}

const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };
const sorted = (xs) => [...xs].sort();
const same = (a, b) => JSON.stringify(sorted(a)) === JSON.stringify(sorted(b));

const solved = mkdtempSync(join(tmpdir(), 'raylab-solved-'));
execFileSync(labgen, ['--solved', solved], { stdio: 'pipe' });
const server = await startServer();
let browser;
const started = Date.now();
let mistakesChecked = 0;
let mistakesSeen = 0;  // in course order, for --every
const scoreGaps = [];  // |page - native| of each compared score
try {
  browser = await launchBrowser();
  const { page, problems } = await openPage(browser, server.url);
  const stages = (await page.evaluate(() => window.raylab.catalog)).stages.map((s) => s.info)
    .filter((s) => !onlyStages.length || onlyStages.some((id) => s.id === id || s.id.startsWith(`${id}-`)));
  const runCheck = (req) => page.evaluate((r) => window.raylab.check(r), req);
  for (const stage of stages) {
    const solution = await runCheck({ stage: stage.id, source: 'solution' });
    check(solution.ok && solution.failed === 0, `${stage.id}: the solution passes${solution.ok ? ` (${solution.passed} checks)` : `: ${solution.error}`}` +
      (solution.ok && solution.failed ? `\n${solution.report}` : ''));
    const lab = await runCheck({ stage: stage.id, source: 'lab' });
    check(lab.ok && lab.failed > 0, `${stage.id}: the lab as handed out fails (${lab.ok ? `${lab.failed} checks` : lab.error})`);
    const dir = join(projectRoot, 'tests/mistakes', stage.id);
    const files = readdirSync(dir).filter((n) => n.endsWith('.json')).sort();
    const solvedFiles = Object.fromEntries(readdirSync(join(solved, stage.id))
      .filter((n) => /\.(glsl|vert|frag|geom)$/.test(n))
      .map((n) => [n, readFileSync(join(solved, stage.id, n), 'utf8')]));
    const chosen = !all ? files.slice(0, 2)
      : files.filter(() => (mistakesSeen++ % (every || 1)) === (every ? offset : 0));
    for (const file of chosen) {
      const m = JSON.parse(readFileSync(join(dir, file), 'utf8'));
      const labFiles = { ...solvedFiles };
      for (const [from, to] of m.replace) {
        if (!labFiles[m.file].includes(from)) throw new Error(`${file}: '${from}' is not in ${stage.id}/${m.file}`);
        labFiles[m.file] = labFiles[m.file].replace(from, to);
      }
      // The score (and the handed-out lab's pictures it needs) only where compared.
      const compared = file === files[0];
      const r = await runCheck({ stage: stage.id, labFiles, score: compared });
      const expected = m.caught_by;
      if (r.ok && compared) {
        // The hint and note lines word for word; the score within a quarter
        // point: the page's pictures differ from native's within the
        // tolerance, and a view's credit falls continuously with its share
        // of differing pixels.
        const native = verdictLines(nativeReport(stage, labFiles)), mine = verdictLines(r.report);
        const score = (lines) => Number((lines.find((l) => l.startsWith('score: ')) ?? '').match(/^score: ([0-9.]+)/)?.[1] ?? NaN);
        const words = (lines) => JSON.stringify(lines.filter((l) => !l.startsWith('score: ')));
        const gap = Math.abs(score(native) - score(mine));
        const agree = words(native) === words(mine) && gap <= 0.25;
        scoreGaps.push(gap);
        check(agree, `${stage.id}/${file}: the page's hints are native's, its score ${score(mine)}, native's ${score(native)}` +
          (agree ? '' : `\n  native: ${native.join('\n          ')}\n  page:   ${mine.join('\n          ')}`));
      }
      check(r.ok && same(r.failedChecks, expected),
        `${stage.id}/${file}: the page fails ${r.ok ? `[${sorted(r.failedChecks).join(', ')}]` : r.error}, native [${sorted(m.caught_by).join(', ')}]` +
        (r.ok && !same(r.failedChecks, expected) ? `\n${r.report}` : ''));
      ++mistakesChecked;
    }
  }
  check(problems.length === 0, `no console errors, page errors or failed requests${problems.length ? `: ${problems.join('; ')}` : ''}`);
} finally {
  await browser?.close();
  server.stop();
  rmSync(solved, { recursive: true, force: true });
}
console.log(`\n${mistakesChecked} mistakes checked in ${((Date.now() - started) / 1000).toFixed(0)} s`);
const finite = scoreGaps.filter((g) => Number.isFinite(g));
if (finite.length) console.log(`scores compared with native: ${finite.length}, largest gap ${Math.max(...finite).toFixed(2)} points`);
if (failures.length) {
  console.log(`\n${failures.length} parity check(s) failed`);
  process.exit(1);
}
