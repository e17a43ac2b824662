// The page's Check next to native `raylab check`, stage by stage, measured
// side by side in one run on the same machine (a benchmark: printed, never
// asserted; the table goes into web/README.md). Native: the command's wall
// time (`raylab check --stage S --solution`, process start and GL context
// included, as a student waits for it); page: the Check of the same code in
// the same browser page, from the press to the report (the core and the
// project files loaded once before, as after the page's first Check).
// Shader caches are off on both sides (Mesa's disk cache, Chromium's program
// caches): a student checks code that just changed, which no cache holds.
// Usage: node tests/browser/check_times.mjs [--raylab PATH] [--rounds 3] [--stages 01,04,f3] [--source solution|lab]
// (--source lab: the labs as handed out, where views fail and the score's
// rule draws the handed-out lab too, natively as in the page.)
import { spawnSync } from 'node:child_process';
import { join, resolve } from 'node:path';
import { launchBrowser, openPage, projectRoot, startServer } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const raylab = resolve(option('--raylab', join(projectRoot, 'build/raylab')));
const rounds = Number(option('--rounds', '3'));
const source = option('--source', 'solution');
const only = option('--stages', '')?.split(',').filter(Boolean);

function nativeSeconds(stage) {
  const t0 = performance.now();
  const r = spawnSync(raylab, ['check', '--stage', stage, ...(source === 'solution' ? ['--solution'] : [])], { encoding: 'utf8' });
  const s = (performance.now() - t0) / 1000;
  const verdict = /(\d+) passed, (\d+) failed/.exec(r.stdout);
  if (!verdict) throw new Error(`raylab check --stage ${stage}: no verdict\n${r.stdout}${r.stderr}`);
  return { s, verdict: verdict[0] };
}

process.env.MESA_SHADER_CACHE_DISABLE = 'true';  // native, and Chromium's GPU process (it inherits it)
const median = (xs) => [...xs].sort((a, b) => a - b)[xs.length >> 1];
const server = await startServer();
let browser;
try {
  browser = await launchBrowser(undefined, { extraArgs: ['--disable-gpu-program-cache', '--disable-gpu-shader-disk-cache'] });
  const { page, renderer } = await openPage(browser, server.url);
  const stages = (await page.evaluate(() => window.raylab.catalog)).stages.map((s) => s.info.id)
    .filter((id) => !only.length || only.some((o) => id === o || id.split('-')[0] === o));
  console.log(`Check of each stage's ${source === 'solution' ? 'solution' : 'lab as handed out'}, page against native, side by side`);
  console.log(`browser: ${await browser.version()}, WebGL: ${renderer}`);
  console.log(`${rounds} rounds, native and page alternating within each; medians`);
  // Warm the page: the core and the project files are loaded by the first Check.
  await page.evaluate((s, src) => window.raylab.check({ stage: s, source: src }), stages[0], source);
  console.log('\n| stage | native `raylab check` (s) | page Check (s) | page / native | verdict |');
  console.log('|---|---:|---:|---:|---|');
  const ratios = [];
  for (const stage of stages) {
    const native = [], web = [];
    let verdict = '';
    for (let i = 0; i < rounds; ++i) {
      const n = nativeSeconds(stage);
      native.push(n.s);
      const r = await page.evaluate(async (s, src) => {
        const t0 = performance.now();
        const run = await window.raylab.check({ stage: s, source: src });
        return { s: (performance.now() - t0) / 1000, run };
      }, stage, source);
      if (!r.run.ok) throw new Error(`page Check of ${stage}: ${r.run.error}`);
      web.push(r.s);
      const pageVerdict = `${r.run.passed} passed, ${r.run.failed} failed`;
      verdict = pageVerdict === n.verdict ? pageVerdict : `page ${pageVerdict}, native ${n.verdict}`;
    }
    const ratio = median(web) / median(native);
    ratios.push(ratio);
    console.log(`| ${stage} | ${median(native).toFixed(2)} | ${median(web).toFixed(2)} | ${ratio.toFixed(2)}x | ${verdict} |`);
  }
  console.log(`\nlargest page / native: ${Math.max(...ratios).toFixed(2)}x`);
} finally {
  await browser?.close();
  server.stop();
}
