// The grading report as an instructor reads it (issue: instructors at 200
// students), in a real browser. Part of the `web_browser` test: a class of
// four graded natively (`raylab grade`, stage 01: two solved, one untouched,
// one with a compile error), then report.html opened from disk: the class
// table sorted by keyboard alone (a column's button, Enter) with aria-sort
// saying so, each row's link opening the student's page, whose pictures load
// and say in their alt text whose picture of which stage and view they are.
// Usage: node tests/browser/grade_report.mjs [--raylab PATH] [--labgen PATH]
import { execFileSync } from 'node:child_process';
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { collectProblems, launchBrowser, projectRoot } from './browser.mjs';
import { checker, toolPaths } from './downloads.mjs';

const { raylab, labgen } = toolPaths();
const { check, failures } = checker();
const work = mkdtempSync(join(tmpdir(), 'raylab-report-'));
let browser;
try {
  execFileSync(labgen, ['--solved', join(work, 'solved')], { stdio: 'pipe' });
  const stage = (name, from) => cpSync(join(from, '01-raycast'), join(work, 'class', name, '01-raycast'), { recursive: true });
  stage('ada', join(work, 'solved'));
  stage('bea', join(work, 'solved'));
  stage('cid', join(projectRoot, 'labs'));
  stage('dan', join(work, 'solved'));
  const broken = join(work, 'class', 'dan', '01-raycast', 'intersect_sphere.glsl');
  writeFileSync(broken, readFileSync(broken, 'utf8').replace('    return', '    float = 1.0;\n    return'));
  execFileSync(raylab, ['grade', '--submissions', join(work, 'class'), '--stages', '01', '--out', join(work, 'graded'), '--seed', '5'], { stdio: 'pipe' });

  browser = await launchBrowser();
  const page = await browser.newPage();
  const problems = collectProblems(page);
  await page.goto(pathToFileURL(join(work, 'graded', 'report.html')).href, { waitUntil: 'load' });
  const rows = () => page.$$eval('table.sortable tbody tr', (trs) => trs.map((tr) => tr.cells[0].textContent.trim()));
  check((await rows()).join(' ') === 'ada bea cid dan', `the table opens in the folders' order: ${await rows()}`);

  // Sort by the total with the keyboard: Tab to the column's button, Enter.
  const headers = await page.$$eval('table.sortable thead th', (ths) => ths.map((th) => th.textContent.trim()));
  const total = headers.indexOf('Total');
  check(total > 0, `a Total column: ${headers}`);
  await page.focus(`table.sortable thead th:nth-child(${total + 1}) button`);
  await page.keyboard.press('Enter');
  const ascending = await rows();
  check(['cid', 'dan'].includes(ascending[0]) && ascending.slice(2).sort().join(' ') === 'ada bea',
    `Enter sorts by the total, lowest first: ${ascending}`);
  const sortState = await page.$eval(`table.sortable thead th:nth-child(${total + 1})`, (th) => th.getAttribute('aria-sort'));
  check(sortState === 'ascending', `aria-sort says how it is sorted: ${sortState}`);
  await page.keyboard.press('Enter');
  check((await rows()).slice(0, 2).sort().join(' ') === 'ada bea', `Enter again reverses: ${await rows()}`);

  // A row's link opens the student's page; its pictures load, with alt text.
  await Promise.all([page.waitForNavigation({ waitUntil: 'load' }), page.click('a[href="students/cid/report.html"]')]);
  await page.evaluate(async () => {
    for (const img of document.images) { img.loading = 'eager'; if (!img.complete) await new Promise((r) => { img.onload = img.onerror = r; }); }
  });
  const images = await page.$$eval('img', (imgs) => imgs.map((i) => ({ alt: i.alt, width: i.naturalWidth })));
  check(images.length >= 3, `the student's page shows the pictures: ${images.length}`);
  check(images.every((i) => i.width > 0), `every picture loads: ${JSON.stringify(images.filter((i) => !i.width))}`);
  check(images.some((i) => i.alt.startsWith("cid's picture of 01-raycast, view ")), `alt text says whose: ${images[0]?.alt}`);
  check(images.some((i) => i.alt.startsWith('the reference picture of 01-raycast, view ')), 'and the reference\'s');
  const back = await page.$eval('a[href="../../report.html"]', (a) => a.textContent);
  check(back.includes('class table'), 'a way back to the class table');
  check(problems.length === 0, `no errors: ${problems.join('; ')}`);

  // The control: dan's compile error is on his page, named by file and line.
  await page.goto(pathToFileURL(join(work, 'graded', 'students', 'dan', 'report.html')).href, { waitUntil: 'load' });
  const log = await page.$eval('pre.log', (pre) => pre.textContent);
  check(/dan\/01-raycast\/intersect_sphere\.glsl:\d+/.test(log), `the compile error names the file: ${log.slice(0, 120)}`);
  check(!log.includes(work), 'and no folder of the grading machine');
} finally {
  await browser?.close();
  rmSync(work, { recursive: true, force: true });
}
if (failures.length) {
  console.error(`grade_report: ${failures.length} failed:\n  ${failures.join('\n  ')}`);
  process.exit(1);
}
console.log('grade_report: the class table sorts by keyboard; the students\' pages show their pictures with alt text');
