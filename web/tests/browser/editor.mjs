// The page as a student's whole workstation (the editor in the page, the
// work kept in the browser), driven as a student drives it: clicks and
// keystrokes, no test API (a students' bundle has none). Part of the
// `web_browser` test. A server without --with-solutions (a labs-only page,
// as a bundle is), a fresh browser profile:
//  1. the first screen says where to start; Code is "my work (in this page)";
//     the first stage opens with its files as tabs, the TODO's file marked;
//  2. keyboard only: Tab from the button before it into the editor, type, Tab
//     out again (the editor does not keep Tab);
//  3. stage 01's fix typed into the editor (each file that differs from the
//     solved lab: select all, type the solved text); the picture follows
//     (no TODO left); Check (key C): the button says "checking…" and is
//     disabled while it runs, C meanwhile starts no second check; the report
//     says every check passed; the Stage menu marks 01 with a ✓;
//  4. the page reloaded: the edit is still in the editor;
//  5. "Download for submission": the zip caught from the browser's
//     downloads (WebKit: from the page's own link, as WebDriver has no
//     downloads), graded natively by `raylab prairielearn`: score 1;
//  6. a file reset to the handout (the confirmation accepted): its TODO is
//     back;
//  7. the downloaded zip imported into the page again: the fix is back;
//  8. layouts at 390x844 and 1024x768: no horizontal scrolling, the
//     picture and the editor in view, the editor under the picture on the
//     phone.
// Usage: node tests/browser/editor.mjs [--raylab PATH] [--labgen PATH]
// (RAYLAB_BROWSER=firefox|webkit as the other browser tests; webkit under
// xvfb-run -a).
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { allowDownloads, browserName, launchBrowser, projectRoot, startServer } from './browser.mjs';
import { checker, finishedDownload, gradePrairieLearn, toolPaths } from './downloads.mjs';

const { raylab, labgen } = toolPaths();
const STAGE = '01-raycast';

const { check, failures } = checker();
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

const work = mkdtempSync(join(tmpdir(), 'raylab-editor-'));
const downloads = join(work, 'downloads');
mkdirSync(downloads);
const server = await startServer({ withSolutions: false });
let browser;
try {
  execFileSync(labgen, ['--solved', join(work, 'solved')], { stdio: 'pipe' });
  browser = await launchBrowser(undefined, { downloads });
  const page = await browser.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('dialog', (d) => void d.accept());  // Reset's confirmation (WebDriver: accepted by its session)
  if (browserName !== 'webkit') await allowDownloads(page, downloads);
  await page.setViewport({ width: 1280, height: 800 });
  await page.goto(server.url, { waitUntil: 'load' });

  const messages = () => page.evaluate(() => document.getElementById('messages').textContent);
  // The stage drawn (or refused) and no reload pending: the messages say what it found.
  const settled = (what = /Ready|Unfinished|error/i) => page.waitForFunction((re) =>
    !document.getElementById('view').classList.contains('building') && new RegExp(re, 'i').test(document.getElementById('messages').textContent),
  { timeout: 120_000 }, what.source).catch(async (e) => {
    throw new Error(`waiting for the messages to match ${what}: ${e.message}; they say ${JSON.stringify(await messages())}`);
  });
  const tabs = () => page.evaluate(() => [...document.querySelectorAll('#editor-tabs button')].map((b) => ({
    name: b.textContent, file: b.dataset.file, todo: b.classList.contains('has-todo'), selected: b.getAttribute('aria-selected') === 'true',
  })));
  const editorText = () => page.evaluate(() => [...document.querySelectorAll('#editor-host .cm-line')].map((l) => l.textContent).join('\n'));
  const focusInEditor = () => page.evaluate(() => document.getElementById('editor-host').contains(document.activeElement));
  const openTab = async (name) => {
    await page.click(`#editor-tabs button[data-file="${STAGE}/${name}"]`);
    await page.waitForFunction((f) => document.querySelector(`#editor-tabs button[data-file="${f}"]`).getAttribute('aria-selected') === 'true',
      {}, `${STAGE}/${name}`);
  };

  // 1. The first screen.
  await settled();
  const first = await messages();
  check(/^Start here: pick your stage, edit its files in the editor/.test(first) && /kept in this browser/.test(first),
    `the first screen says where to start: ${JSON.stringify(first.split('\n')[0])}`);
  const chosen = await page.evaluate(() => ({ source: document.getElementById('source').value, stage: document.getElementById('stage').value }));
  check(chosen.source === 'work' && chosen.stage === STAGE, `it opens on my work, stage ${chosen.stage} (Code: ${chosen.source})`);
  const shown = await tabs();
  const labNames = readdirSync(join(projectRoot, 'labs', STAGE)).filter((n) => /\.(glsl|vert|frag|geom)$/.test(n)).sort();
  check(JSON.stringify(shown.map((t) => t.name).sort()) === JSON.stringify(labNames), `its files as tabs: ${shown.map((t) => t.name).join(', ')}`);
  check(shown.find((t) => t.name === 'intersect_sphere.glsl')?.todo && /my-work\/01-raycast\/intersect_sphere\.glsl:\d+/.test(first),
    'the TODO\'s file is marked, and the messages name it in the page\'s folder');

  // 2. Keyboard only: into the editor with Tab, a comment typed, out with Tab.
  await openTab('main.frag');
  await page.focus('#import-zip');  // the last control before the editor
  await page.keyboard.press('Tab');
  const inside = await focusInEditor();
  await page.keyboard.down('Control');
  await page.keyboard.press('End');
  await page.keyboard.up('Control');
  await page.keyboard.type('\n// typed with the keyboard only');
  await page.keyboard.press('Tab');
  const outside = !(await focusInEditor());
  check(inside && outside && (await editorText()).endsWith('// typed with the keyboard only'),
    `Tab goes into the editor (${inside}), the keys type there, Tab leaves it again (${outside})`);

  // 3. The fix typed, the picture follows, Check passes.
  const solvedDir = join(work, 'solved', STAGE);
  for (const name of labNames) {
    const solved = readFileSync(join(solvedDir, name), 'utf8');
    if (solved === readFileSync(join(projectRoot, 'labs', STAGE, name), 'utf8')) continue;
    await openTab(name);
    await page.click('#editor-host .cm-content');
    await page.keyboard.down('Control');
    await page.keyboard.press('a');
    await page.keyboard.up('Control');
    // Each line's indentation is the editor's (it indents after Enter).
    await page.keyboard.type(solved.trimEnd().split('\n').map((l) => l.trimStart()).join('\n'));
    console.log(`     typed the solved ${name} (${solved.length} characters)`);
  }
  await settled(/Ready: /);
  check(!(await tabs()).some((t) => t.todo), 'the picture follows the edits: no TODO left, no tab marked');
  // What the student sees and does, in order: each C pressed on the picture
  // (and whether a check was running then), each time the Check button turns
  // disabled (a check begins; with its label) or back.
  await page.evaluate(() => {
    window.seen = [];
    const button = document.getElementById('check');
    document.addEventListener('keydown', (e) => {
      if (e.key.toLowerCase() === 'c' && e.target.id === 'view') window.seen.push({ c: true, running: button.disabled });
    }, true);
    new MutationObserver(() => window.seen.push({ disabled: button.disabled, label: button.textContent }))
      .observe(button, { attributes: true, attributeFilter: ['disabled'] });
  });
  // C starts a check; C again at once starts none while it runs (the
  // Firefox page checks 01 in about 0.2 s: some presses may come after it).
  await page.focus('#view');
  for (let i = 0; i < 4; ++i) await page.keyboard.press('c');
  await page.waitForFunction(() => /\d+ passed, \d+ failed/.test(document.getElementById('messages').textContent) &&
    !document.getElementById('check').disabled, { timeout: 300_000 });
  const report = await messages();
  const seen = await page.evaluate(() => window.seen);
  const starts = seen.filter((e) => e.disabled), idle = seen.filter((e) => e.c && !e.running), busy = seen.filter((e) => e.c && e.running);
  check(starts.length > 0 && starts.every((e) => e.label === 'checking…') && seen.at(-1).disabled === false && seen.at(-1).label === 'Check',
    `while a check runs the button says ${JSON.stringify(starts[0]?.label)} and is disabled, then Check again`);
  check(busy.length > 0 && starts.length === idle.length,
    `C during a check does nothing: ${seen.filter((e) => e.c).length} presses, ${busy.length} during a check, ${starts.length} checks run`);
  check(/^raylab check: stage 01-raycast, lab my-work\//m.test(report) && /\d+ passed, 0 failed/.test(report),
    `Check passes: ${JSON.stringify(report.trim().split('\n').slice(-2).join(' / '))}`);
  // The mark follows the verdict's save to the browser's storage (work_panel.ts
  // checked()), which may end after the button is enabled again.
  await page.waitForFunction((id) => document.querySelector(`#stage option[value="${id}"]`).textContent.startsWith('✓'),
    { timeout: 10_000 }, STAGE).catch(() => {});
  const mark = await page.evaluate((id) => document.querySelector(`#stage option[value="${id}"]`).textContent, STAGE);
  check(mark.startsWith('✓'), `the Stage menu marks the passed stage: ${JSON.stringify(mark)}`);
  await openTab('find_closest.glsl');
  const typed = await editorText();

  // 4. Reloaded: the work is still there.
  await page.goto(server.url, { waitUntil: 'load' });
  await settled(/Ready: /);
  await openTab('find_closest.glsl');
  const again = await editorText();
  check(again === typed && again.includes('hit = Hit(t, i)'), 'after a reload the editor holds the edit');
  await openTab('main.frag');
  check((await editorText()).endsWith('// typed with the keyboard only'), 'and the keyboard\'s edit of another file');

  // 5. Download for submission, graded natively.
  for (const f of readdirSync(downloads)) rmSync(join(downloads, f));
  let zipPath;
  if (browserName === 'webkit') {
    // WebDriver has no downloads: the page's own link's file, read in the page.
    await page.evaluate(() => {
      const click = HTMLAnchorElement.prototype.click;
      HTMLAnchorElement.prototype.click = function () {
        if (this.download === 'raylab-submission.zip') fetch(this.href).then((r) => r.arrayBuffer()).then((b) => { window.caughtZip = [...new Uint8Array(b)]; });
        else click.call(this);
      };
    });
    await page.click('#submit');
    await page.waitForFunction(() => window.caughtZip !== undefined);
    zipPath = join(downloads, 'raylab-submission.zip');
    writeFileSync(zipPath, Buffer.from(await page.evaluate(() => window.caughtZip)));
  } else {
    await page.click('#submit');
    zipPath = await finishedDownload(downloads);
  }
  check(zipPath !== null, 'the page downloads raylab-submission.zip');
  if (zipPath) {
    const listed = execFileSync('unzip', ['-Z1', zipPath], { encoding: 'utf8' }).trim().split('\n').sort();
    check(JSON.stringify(listed) === JSON.stringify(labNames.map((n) => `${STAGE}/${n}`)), `the zip holds the page's stage folder: ${listed.join(', ')}`);
    const result = gradePrairieLearn(raylab, readFileSync(zipPath), join(work, 'pl'), '01');
    check(result.gradable && result.score === 1, `raylab prairielearn scores it ${result.score} (${result.message})`);
  }

  // 6. Reset a file to the handout.
  await openTab('find_closest.glsl');
  await page.click('#reset-file');
  await settled(/Unfinished/);
  const handout = readFileSync(join(projectRoot, 'labs', STAGE, 'find_closest.glsl'), 'utf8').trimEnd();
  check((await editorText()).trimEnd() === handout && (await tabs()).find((t) => t.name === 'find_closest.glsl').todo,
    'Reset file puts the handout back: its TODO is marked again');

  // 7. The downloaded zip imported again (as from another device): the fix is back.
  if (zipPath) {
    if (browserName === 'chromium') {
      // The button, and the file picked in the browser's file chooser.
      const [chooser] = await Promise.all([page.waitForFileChooser(), page.click('#import-zip')]);
      await chooser.accept([zipPath]);
    } else if (browserName === 'webkit') {
      await page.uploadFile('#zip-file', zipPath);  // WebDriver: the button's file input given the file
    } else {
      await (await page.$('#zip-file')).uploadFile(zipPath);
    }
    await settled(/Ready: /);
    check((await editorText()).includes('hit = Hit(t, i)') && !(await tabs()).some((t) => t.todo),
      'Import a zip… (the downloaded submission, the confirmation accepted) brings the fix back');
  }

  // 8. Layouts.
  for (const [width, height] of [[390, 844], [1024, 768]]) {
    await page.setViewport({ width, height });
    await sleep(500);
    const box = await page.evaluate(() => {
      const c = document.getElementById('view').getBoundingClientRect(), e = document.getElementById('editor-host').getBoundingClientRect();
      return { scrollWidth: document.documentElement.scrollWidth, innerWidth, canvas: [c.left, c.right, c.top, c.bottom], editor: [e.left, e.right, e.top, e.bottom] };
    });
    const inWidth = (r) => r[0] >= 0 && r[1] <= box.innerWidth && r[1] - r[0] > 100 && r[3] - r[2] > 100;
    check(box.scrollWidth <= box.innerWidth && inWidth(box.canvas) && inWidth(box.editor) && (width > 900 || box.editor[2] >= box.canvas[3]),
      `${width}x${height}: nothing wider than the window, the picture and the editor in view${width > 900 ? '' : ', the editor under the picture'} (${JSON.stringify(box)})`);
  }
  check(problems.length === 0, `no console errors or page errors${problems.length ? `: ${problems.join('; ')}` : ''}`);
} finally {
  await browser?.close();
  server.stop();
  rmSync(work, { recursive: true, force: true });
}
if (failures.length) {
  console.log(`\n${failures.length} editor check(s) failed`);
  process.exit(1);
}
