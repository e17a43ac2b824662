// The page as a student drives it (its own controls, not the test API's
// renderers), in Debian's Chromium (or Firefox ESR: RAYLAB_BROWSER=firefox);
// part of the `web_browser` test:
//  1. switching stage: the old picture stops, is dimmed and labelled with
//     what it is while the new stage builds; then the overlay names the new
//     one; the switch's time is printed (web/tests/browser/switch_times.mjs
//     measures every stage);
//  2. the f4 lab opens on the fur shader (its stage.json "technique"), its
//     TODOs listed one per entry, each title a whole sentence;
//  3. the fur track's Ready line leaves the shell count to the overlay,
//     [ changes it, and key M draws the procedural meshes,
//     which follows [ and ];
//  4. stage 08's scene menu offers every ray-tracing scene, the OBJ mesh
//     scene too; its View menu draws the depth view (the overlay names it
//     and its mapping), and hides on a fur stage; Trace a pixel and a click
//     on the picture print that pixel's path;
//  5. layout: at 1024x768 in a 1280x720 window the messages stay in view
//     beside the picture; on a 390x844 phone the overlay covers little of it;
//  6. a server started without --with-solutions: the page offers the labs
//     only (no solution in the Code menu, no demo buttons), draws the
//     student's work kept in the page (at first the lab as handed out:
//     tests/browser/editor.mjs tests the editor), and never asks for a
//     solution file;
//  7. Check (key C) on the lab of stage 01: `raylab check`'s report in the
//     messages, each failing view as yours / difference / reference; on the
//     solution every check passes and no view is shown.
// Usage: node tests/browser/page_ui.mjs   (exit status 1 on a failure)
import { launchBrowser, openPage, startServer } from './browser.mjs';

const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };

const server = await startServer();
let browser;
try {
  browser = await launchBrowser();
  const { page, problems } = await openPage(browser, server.url, '');
  await page.setViewport({ width: 1280, height: 720 });
  const settled = () => page.waitForFunction(() => !document.getElementById('view').classList.contains('building') &&
    /Ready|Unfinished|error/i.test(document.getElementById('messages').textContent), { timeout: 120_000 });
  await settled();
  const choose = (id, value) => page.evaluate((i, v) => {
    const sel = document.getElementById(i);
    sel.value = v;
    sel.dispatchEvent(new Event('change'));
  }, id, value);
  const text = (id) => page.$eval(`#${id}`, (e) => e.textContent);

  // 1. Switching from the running demo stage to 05.
  const first = await text('overlay');
  const r = await page.evaluate(() => window.raylab.switchTo({ stage: '05' }));
  check(r.dimmed, 'while 05 builds, the old picture is dimmed');
  check(/^building 05-primitives \(solution\) on /.test(r.overlayWhileBuilding) && r.overlayWhileBuilding.includes(`showing ${first.split('  ')[0]}`),
    `the overlay says what is built and what is shown: ${JSON.stringify(r.overlayWhileBuilding)}`);
  check(Number.isFinite(r.ms) && r.overlay.startsWith('05-primitives (solution) on '),
    `after ${r.ms.toFixed(0)} ms the overlay names the new stage: ${JSON.stringify(r.overlay.split('\n')[0])}`);

  // 2. The f4 lab.
  await choose('source', 'lab');
  await page.evaluate(() => window.raylab.switchTo({ stage: 'f4' }));
  await settled();
  const overlay = await text('overlay'), messages = await text('messages');
  check(overlay.includes('technique fur_shader'), `the f4 lab opens on the fur shader: ${JSON.stringify(overlay)}`);
  const entries = messages.split(/\n\n|\n(?=• )/).filter((e) => e.startsWith('• '));
  check(entries.length >= 3, `its TODOs are listed one per entry (${entries.length})`);
  check(entries.every((e) => /[.!?:]$/.test(e.trim())), `each TODO title is a whole sentence:\n${entries.join('\n')}`);

  // 3. f2's Ready line and the shell count.
  await choose('source', 'solution');
  await page.evaluate(() => window.raylab.switchTo({ stage: 'f2' }));
  await settled();
  const ready = await text('messages');
  check(/^Ready: \d+ triangles, \d+ vertices\./.test(ready) && !/shells/.test(ready.split('\n')[0]), `f2's Ready line: ${JSON.stringify(ready.split('\n')[0])}`);
  const shellsRow = async () => (await text('overlay')).split('\n').find((l) => l.startsWith('shells '));
  const before = await shellsRow();
  await page.focus('#view');
  await page.keyboard.press('[');
  await new Promise((res) => setTimeout(res, 300));
  const after = await shellsRow();
  check(before && after && before !== after, `[ changes the overlay's shell count: ${before} -> ${after}`);
  // Key M: the next procedural mesh, drawn (native: the window's key M).
  const meshRow = async () => (await text('overlay')).split('\n').join('  ').match(/mesh [^ ]+( [^ ]+)?/)?.[0];
  const shot = async () => Buffer.from(await (await page.$('#view')).screenshot()).toString('base64');
  const scenePicture = await shot();
  await page.keyboard.press('m');
  await page.keyboard.press('m');
  await new Promise((res) => setTimeout(res, 500));
  const torusRow = await meshRow();
  const meshPicture = await shot();
  check(torusRow === 'mesh torus' && scenePicture !== meshPicture, `M M shows the torus mesh (overlay: ${torusRow}; the picture ${scenePicture !== meshPicture ? 'changed' : 'did not change'})`);

  // 4. Stage 08's scene menu.
  await page.evaluate(() => window.raylab.switchTo({ stage: '08' }));
  await settled();
  const scenes = await page.$$eval('#scene option', (os) => os.map((o) => o.value));
  check(scenes.includes('mesh.json') && scenes.includes('pro.json'), `08's scenes: ${scenes.join(', ')}`);
  // The View menu: a debug view drawn by the stage's own files, its mapping in the overlay.
  await choose('view-mode', 'depth');
  await settled();
  const depthOverlay = await text('overlay');
  check(/, depth view/.test(depthOverlay) && /depth [0-9.]+\.\.[0-9.]+ mapped to white\.\.grey/.test(depthOverlay),
    `View depth: the overlay names the view and its mapping: ${JSON.stringify(depthOverlay.split('\n').filter((l) => /depth/.test(l)))}`);
  await choose('view-mode', 'color');
  await settled();
  // Trace a pixel: the button, then a click on the picture prints its path.
  await page.click('#trace');
  const canvasBox = await (await page.$('#view')).boundingBox();
  await page.mouse.click(canvasBox.x + canvasBox.width / 2, canvasBox.y + canvasBox.height / 2);
  await page.waitForFunction(() => /^(your shader's path|rays traced)/m.test(document.getElementById('messages').textContent) ||
    /error/i.test(document.getElementById('messages').textContent), { timeout: 60000 });
  const traced = await text('messages');
  // (The middle of the box, as the browser rounds it: 400,300 give or take one.)
  check(/^your shader's path at pixel (399|400|401),(299|300|301) /.test(traced) && /^ray 1 \(main|^ray 1 \(trace/m.test(traced) && /^rays traced: \d+/m.test(traced),
    `Trace a pixel, then a click on the middle of the picture: ${JSON.stringify(traced.split('\n').slice(0, 2))}`);
  await page.evaluate(() => window.raylab.switchTo({ stage: 'f1' }));
  await settled();
  check(await page.$eval('#view-mode-label', (l) => l.hidden), 'the View menu hides on a fur stage (no debug views there)');
  await page.evaluate(() => window.raylab.switchTo({ stage: '08' }));
  await settled();

  // 5. Layout.
  await choose('size', '1024x768');
  const box = await page.evaluate(() => {
    const m = document.getElementById('messages').getBoundingClientRect(), c = document.getElementById('view').getBoundingClientRect();
    return { messagesTop: m.top, messagesLeft: m.left, canvasBottom: c.bottom, canvasRight: c.right };
  });
  check(box.messagesTop < 720 && box.canvasBottom <= 720 && box.messagesLeft >= box.canvasRight,
    `1024x768 in a 1280x720 window: messages beside the picture and in view (${JSON.stringify(box)})`);
  await page.setViewport({ width: 390, height: 844, isMobile: true, hasTouch: true });
  await choose('size', '800x600');
  await new Promise((res) => setTimeout(res, 500));
  const share = await page.evaluate(() => {
    const o = document.getElementById('overlay').getBoundingClientRect(), c = document.getElementById('view').getBoundingClientRect();
    return (o.width * o.height) / (c.width * c.height);
  });
  check(share < 0.2, `on a 390x844 phone the overlay covers ${(100 * share).toFixed(0)}% of the picture`);
  check(problems.length === 0, `no console errors, page errors or failed requests${problems.length ? `: ${problems.join('; ')}` : ''}`);

  // 7. Check, as a student presses it.
  await page.setViewport({ width: 1280, height: 720 });
  await choose('source', 'lab');
  await settled();
  await page.evaluate(() => window.raylab.switchTo({ stage: '01' }));
  await settled();
  const checked = async () => {
    await page.focus('#view');
    await page.keyboard.press('c');
    await page.waitForFunction(() => /\d+ passed, \d+ failed/.test(document.getElementById('messages').textContent), { timeout: 120_000 });
    return page.evaluate(() => ({
      report: document.getElementById('messages').textContent,
      views: [...document.querySelectorAll('#check-views .check-view')].map((v) => ({ view: v.dataset.view, pictures: v.querySelectorAll('canvas').length })),
    }));
  };
  const labCheck = await checked();
  check(/^raylab check: stage 01-raycast, lab labs\/ against the reference pictures/m.test(labCheck.report) &&
    /FAIL intersectSphere +0\/36 cases; first failure: .*reaches an unfinished TODO/.test(labCheck.report) &&
    /0 passed, 8 failed/.test(labCheck.report), `Check on the 01 lab: native's report (${JSON.stringify(labCheck.report.split('\n').slice(-1)[0])})`);
  check(labCheck.views.length === 6 && labCheck.views.every((v) => v.pictures === 3),
    `Check shows each failing view as three pictures: ${labCheck.views.map((v) => v.view).join(', ')}`);
  await choose('source', 'solution');
  await settled();
  const solutionCheck = await checked();
  check(/8 passed, 0 failed/.test(solutionCheck.report) && solutionCheck.views.length === 0,
    `Check on the 01 solution: every check passes, no view shown (${solutionCheck.views.length})`);

  // 6. Labs only.
  const labsOnly = await startServer({ withSolutions: false });
  try {
    const lab = await openPage(browser, labsOnly.url, '');
    await lab.page.waitForFunction(() => !document.getElementById('view').classList.contains('building') &&
      /Ready|Unfinished|error/i.test(document.getElementById('messages').textContent), { timeout: 120_000 });
    const seen = await lab.page.evaluate(() => ({
      options: [...document.getElementById('source').options].map((o) => o.value),
      demos: ['demo-lite', 'demo-pro', 'demo-fur'].filter((id) => !document.getElementById(id).hidden),
      overlay: document.getElementById('overlay').textContent,
    }));
    check(!seen.options.includes('solution') && seen.options[0] === 'work' && seen.options.includes('lab'), `labs only: the Code menu offers ${seen.options.join(', ')}`);
    check(seen.demos.length === 0, `labs only: no demo button shown (${seen.demos.join(', ') || 'none'})`);
    check(/\(my work\) on /.test(seen.overlay), `labs only: the page draws the student's work, the lab as handed out at first: ${JSON.stringify(seen.overlay.split('\n')[0])}`);
    check(lab.problems.length === 0, `labs only: no console errors or failed requests${lab.problems.length ? `: ${lab.problems.join('; ')}` : ''}`);
    const status = await lab.page.evaluate(async () => (await fetch('../solution/01-raycast/intersect_sphere.glsl')).status);
    check(status === 404, `labs only: a solution file is not served (HTTP ${status})`);
  } finally {
    labsOnly.stop();
  }
} finally {
  await browser?.close();
  server.stop();
}
if (failures.length) {
  console.log(`\n${failures.length} page check(s) failed`);
  process.exit(1);
}
