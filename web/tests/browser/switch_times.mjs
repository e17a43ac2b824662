// How long switching stage takes, measured as a student meets it (a
// benchmark: printed, never asserted; the page's overlay and dimming while
// building are checked by render_views.mjs). In the page: the stage menu of
// the running page, from the choice to the new stage's first frame, once
// after the previous stage of the list and once right after the pro demo
// (its slow frames were what held switches up), each program compiled for
// the first time (the browser keeps compiled programs: the second column
// uses a fresh browser for every stage). Natively: `raylab render
// --stage X --solution` from start to the written picture (a new process:
// EGL, the scene, the program, one frame), the closest native equivalent.
// Usage: node tests/browser/switch_times.mjs [--raylab PATH] [--stages 01,f4]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { performance } from 'node:perf_hooks';

import { launchBrowser, openPage, projectRoot, startServer } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const raylab = resolve(option('--raylab', join(projectRoot, 'build/raylab')));
const only = option('--stages', '').split(',').filter(Boolean);

function nativeMs(stage) {
  const out = mkdtempSync(join(tmpdir(), 'raylab-switch-'));
  try {
    const t0 = performance.now();
    execFileSync(raylab, ['render', '--stage', stage, '--solution', '--size', '800x600', '--out', join(out, 'x.png')], { stdio: 'ignore' });
    return performance.now() - t0;
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}

// A page in a browser of its own (a fresh program cache: every program is
// compiled for the first time, as on a student's first visit), settled on
// its first stage.
async function freshPage(server) {
  const browser = await launchBrowser();
  const { page, problems } = await openPage(browser, server.url, '');
  await page.waitForFunction(() => !document.getElementById('view').classList.contains('building') &&
    /Ready|Unfinished/.test(document.getElementById('messages').textContent), { timeout: 120_000 });
  return { browser, page, problems };
}

const server = await startServer();
let first;
try {
  first = await freshPage(server);
  const { page } = first;
  const stages = (await page.evaluate(() => window.raylab.catalog)).stages.map((s) => s.info.id)
    .filter((id) => only.length === 0 || only.some((o) => id === o || id.startsWith(`${o}-`)));
  console.log('switching stage at 800x600, the solution: from the choice to the first frame (ms); every program compiled');
  console.log('for the first time (after the pro demo: a fresh browser that was showing the pro demo)');
  console.log('\n| stage | page, after the previous stage | page, after the pro demo | native (raylab render) |');
  console.log('|---|---:|---:|---:|');
  const slow = [];
  const cell = (r) => (Number.isNaN(r.ms) ? `no frame (${r.message.split('\n')[0]})` : r.ms.toFixed(0));
  for (const id of stages) {
    const next = await page.evaluate((req) => window.raylab.switchTo(req), { stage: id });
    const fresh = await freshPage(server);
    let afterPro;
    try {
      await fresh.page.evaluate((req) => window.raylab.switchTo(req), { demo: 'pro' });
      await new Promise((r) => setTimeout(r, 1500));  // a few demo frames
      afterPro = await fresh.page.evaluate((req) => window.raylab.switchTo(req), { stage: id });
    } finally {
      await fresh.browser.close();
    }
    const native = nativeMs(id);
    console.log(`| ${id} | ${cell(next)} | ${cell(afterPro)} | ${native.toFixed(0)} |`);
    if (!(next.ms < 2000) || !(afterPro.ms < 2000)) slow.push(id);
  }
  console.log(`\n${slow.length ? `over 2 s in the page: ${slow.join(', ')}` : 'every stage under 2 s in the page'}`);
  if (first.problems.length) console.log(`page problems: ${first.problems.join('; ')}`);
} finally {
  await first?.browser.close();
  server.stop();
}
