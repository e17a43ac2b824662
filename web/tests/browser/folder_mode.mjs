// Folder mode without folder watching (the folder input, as in Firefox and
// Safari; in Chromium the picker's API is taken away so that the page falls
// back to it), driven as a student does, with no test hook. Part of the
// `web_browser` test:
//  1. a solved lab folder picked: Check passes;
//  2. a file changed on disk after that: Check and Download stop with one
//     line that says so (no raw browser error, no stale verdict, the previous
//     check's pictures gone, no zip);
//  3. Reload my files picks the folder again: Check gives the new verdict.
// Usage: node tests/browser/folder_mode.mjs
import { appendFileSync, copyFileSync, mkdirSync, mkdtempSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { browserName, collectProblems, launchBrowser, projectRoot, startServer } from './browser.mjs';

const STAGE = '01-raycast';
const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };

const work = mkdtempSync(join(tmpdir(), 'raylab-folder-'));
const folder = join(work, 'labs', STAGE);
mkdirSync(folder, { recursive: true });
for (const f of readdirSync(join(projectRoot, 'labs', STAGE)).filter((n) => /\.(glsl|vert|frag|geom)$/.test(n)))
  copyFileSync(join(projectRoot, 'solution', STAGE, f), join(folder, f));

const server = await startServer({ withSolutions: false });
let browser;
try {
  browser = await launchBrowser();
  const page = await browser.newPage();
  const problems = collectProblems(page);
  await page.evaluateOnNewDocument(() => { delete window.showDirectoryPicker; });
  await page.goto(server.url, { waitUntil: 'load' });
  await page.waitForFunction(() => document.getElementById('stage').options.length > 0, { timeout: 60_000 });
  const messages = () => page.$eval('#messages', (m) => m.textContent);
  const choose = (id, value) => page.evaluate((i, v) => {
    const sel = document.getElementById(i);
    sel.value = v;
    sel.dispatchEvent(new Event('change'));
  }, id, value);
  // The folder picked (TRIGGER opens the chooser) and loaded: the page says
  // so, or that the last version that compiled stays. (Cleared first: the
  // messages may already hold "Your files changed on disk", and a Check
  // pressed while the load still runs is ignored.)
  const pick = async (trigger) => {
    await page.$eval('#messages', (m) => { m.textContent = ''; });
    const [chooser] = await Promise.all([page.waitForFileChooser(), trigger()]);
    await chooser.accept([folder]);
    await page.waitForFunction(() => /Your files|still showing the last version that compiled/.test(document.getElementById('messages').textContent),
      { timeout: 120_000 });
  };
  const pressCheck = async () => {
    await page.waitForFunction(() => !document.getElementById('view').classList.contains('building'), { timeout: 120_000 });
    await page.$eval('#messages', (m) => { m.textContent = ''; });
    await page.click('#check');
    await page.waitForFunction(() => /\d+ passed, \d+ failed|^raylab check: |changed on disk/m.test(document.getElementById('messages').textContent), { timeout: 120_000 });
    return messages();
  };

  await choose('stage', STAGE);
  await pick(() => choose('source', 'disk'));
  const first = await pressCheck();
  check(/ 0 failed/.test(first), `a solved folder checks: ${first.match(/\d+ passed, \d+ failed/)?.[0] ?? first.split('\n')[0]}`);

  // Saved on disk after the page read it: a slip that would fail the check.
  appendFileSync(join(folder, 'find_closest.glsl'), '\n#error saved after the page read the folder\n');
  await page.evaluate(() => {
    // A failing view's pictures, as a previous check leaves them, must go.
    const stale = document.createElement('div');
    stale.className = 'check-view';
    document.getElementById('check-views').append(stale);
  });
  const stale = await pressCheck();
  check(/^(raylab check: )?Your files changed on disk since the page read them \(01-raycast\/find_closest\.glsl\): press Reload my files\.$/.test(stale.trim()),
    `Check after a save on disk: "${stale.trim()}"`);
  check(!/could not be read|NotReadable/i.test(stale), 'no raw browser error');
  check(await page.$$eval('#check-views > *', (v) => v.length) === 0, 'the previous check\'s pictures are gone');
  await page.$eval('#messages', (m) => { m.textContent = ''; });
  await page.click('#submit');
  await page.waitForFunction(() => document.getElementById('messages').textContent !== '', { timeout: 30_000 });
  const download = await messages();
  check(/changed on disk/.test(download) && !/\.zip/.test(download), `Download after a save on disk: "${download.trim()}"`);

  await pick(() => page.click('#reload'));
  const again = await pressCheck();
  check(/find_closest\.glsl:\d+/.test(again) && /saved after the page read the folder/.test(again),
    `after Reload my files, Check reads the new file: ${again.trim().split('\n').slice(0, 2).join(' / ')}`);
  check(problems.length === 0, `no console errors, page errors or failed requests${problems.length ? `: ${problems.join('; ')}` : ''}`);
} finally {
  await browser?.close();
  server.stop();
  rmSync(work, { recursive: true, force: true });
}
console.log(`(${browserName})`);
if (failures.length) {
  console.log(`\n${failures.length} folder-mode check(s) failed`);
  process.exit(1);
}
