// The browser's frame time next to the native one, measured side by side in
// one run on the same machine (a benchmark: printed, never asserted).
// Both draw the native demo's frames (the fly-through, 0.1 s apart) of the
// full solution with the demo's program (the same variant and levers on both
// sides: the page gets them from the C++ core), each frame waited for (native:
// glFinish; browser: reading one pixel back).
// Usage: node tests/browser/frame_times.mjs [--raylab PATH] [--size 800x600] [--frames 3] [--rounds 3] [--angle gl-egl|swiftshader] [--only TEXT]
// (--only: the rows whose name holds TEXT, e.g. `--only pro` while trying a lever)
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { launchBrowser, openPage, projectRoot, startServer } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const raylab = resolve(option('--raylab', join(projectRoot, 'build/raylab')));
const size = option('--size', '800x600');
const frames = Number(option('--frames', '3'));
const rounds = Number(option('--rounds', '3'));
const angle = option('--angle', 'gl-egl');
const only = option('--only', '');
const [width, height] = size.split('x').map(Number);

function nativeMedianMs(scene, bvh) {
  const out = mkdtempSync(join(tmpdir(), 'raylab-bench-'));
  try {
    const text = execFileSync(raylab, ['demo', '--headless', '--scene', scene, '--size', size, '--frames', String(frames), '--out', join(out, 'frames'), ...(bvh ? [] : ['--no-bvh'])], { encoding: 'utf8' });
    const m = /median ([\d.]+) ms/.exec(text);
    if (!m) throw new Error(`no frame time in raylab demo's output:\n${text}`);
    return { ms: Number(m[1]), line: text.split('\n')[0] };
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}

const server = await startServer();
let browser;
try {
  browser = await launchBrowser(angle);
  const { page, renderer } = await openPage(browser, server.url);
  const stage = (await page.evaluate(() => window.raylab.catalog)).stages.map((s) => s.info)
    .filter((s) => s.track === 'raytrace' && s.features.includes('demo')).pop();
  console.log(`frame times at ${size}, depth 8, shadows on, the demo's fly-through, stage ${stage.id} (solution)`);
  console.log(`browser: ${await browser.version()} --use-angle=${angle}, WebGL: ${renderer}`);
  // The machine is shared and noisy: ROUNDS rounds, native and browser
  // alternating within each, and the median of the rounds' medians.
  const cases = [
    { name: 'lite', scene: 'lite', bvh: false },
    { name: 'pro (BVH)', scene: 'pro', bvh: true },
    { name: 'pro (linear search)', scene: 'pro', bvh: false },
  ];
  const median = (xs) => [...xs].sort((a, b) => a - b)[xs.length >> 1];
  console.log(`${rounds} rounds of ${frames} frames each side, alternating; medians`);
  console.log('\n| scene | native llvmpipe (ms) | browser WebGL 2 (ms) | browser / native |');
  console.log('|---|---:|---:|---:|');
  // The fur track: the fur demo's sphere, both techniques (native: raylab
  // demo --track fur, which prints both medians per scene).
  const furNative = (text) => {
    const m = /shells\+fins \(\d+ shells\) ([\d.]+) ms\s+fur shader ([\d.]+) ms/.exec(text);
    if (!m) throw new Error(`no fur frame times in raylab demo's output:\n${text}`);
    return { shells_and_fins: Number(m[1]), fur_shader: Number(m[2]) };
  };
  const furCases = [
    { name: 'fur sphere (shells and fins)', technique: 'shells_and_fins' },
    { name: 'fur sphere (fur shader)', technique: 'fur_shader' },
  ];
  const furStage = (await page.evaluate(() => window.raylab.catalog)).stages.map((s) => s.info)
    .filter((s) => s.track === 'fur' && s.features.includes('demo')).pop();
  for (const c of cases.filter((x) => x.name.includes(only))) {
    const native = [], web = [];
    for (let r = 0; r < rounds; ++r) {
      native.push(nativeMedianMs(c.scene, c.bvh).ms);
      web.push((await page.evaluate((req) => window.raylab.timeFrames(req), { stage: stage.id, scene: `${c.scene}.json`, width, height, frames, bvh: c.bvh, demoLevers: true })).medianMs);
    }
    const n = median(native), w = median(web);
    console.log(`| ${c.name} | ${n.toFixed(1)} | ${w.toFixed(1)} | ${(w / n).toFixed(2)}x |`);
  }
  for (const c of furCases.filter((x) => x.name.includes(only))) {
    const native = [], web = [];
    for (let r = 0; r < rounds; ++r) {
      const out = mkdtempSync(join(tmpdir(), 'raylab-bench-'));
      try {
        const text = execFileSync(raylab, ['demo', '--headless', '--track', 'fur', '--scene', 'sphere', '--size', size, '--frames', String(frames), '--out', join(out, 'frames')], { encoding: 'utf8' });
        native.push(furNative(text)[c.technique]);
      } finally {
        rmSync(out, { recursive: true, force: true });
      }
      web.push((await page.evaluate((req) => window.raylab.timeFrames(req), { stage: furStage.id, scene: 'fur/sphere.json', width, height, frames, technique: c.technique })).medianMs);
    }
    const n = median(native), w = median(web);
    console.log(`| ${c.name} | ${n.toFixed(1)} | ${w.toFixed(1)} | ${(w / n).toFixed(2)}x |`);
  }
} finally {
  await browser?.close();
  server.stop();
}
