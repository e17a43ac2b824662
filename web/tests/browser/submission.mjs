// "Download for submission" (issue: the browser as a student's whole
// workstation). Part of the `web_browser` test: a lab folder opened in the
// page (the browser's private file system, watched as a picked folder would
// be), the button pressed, the zip caught from the browser's downloads and
// graded natively as the course engines grade uploads: PrairieLearn keeps the
// zip as a file (`raylab prairielearn`), Gradescope unpacks it
// (`raylab gradescope`). Stage 01 solved scores full marks on both, the lab
// as handed out zero.
// Usage: node tests/browser/submission.mjs [--raylab PATH] [--labgen PATH]
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { allowDownloads, launchBrowser, openPage, projectRoot, startServer } from './browser.mjs';
import { checker, finishedDownload, gradePrairieLearn, toolPaths } from './downloads.mjs';

const { raylab, labgen } = toolPaths();
const STAGE = '01-raycast';

const { check, failures } = checker();
const shaderFiles = (dir) => Object.fromEntries(readdirSync(dir).filter((n) => /\.(glsl|vert|frag|geom)$/.test(n))
  .map((n) => [`${STAGE}/${n}`, readFileSync(join(dir, n), 'utf8')]));

function gradeGradescope(zip, root) {
  mkdirSync(join(root, 'submission'), { recursive: true });
  mkdirSync(join(root, 'source'), { recursive: true });
  writeFileSync(join(root, 'upload.zip'), zip);
  execFileSync('unzip', ['-q', join(root, 'upload.zip'), '-d', join(root, 'submission')]);  // as Gradescope does
  // The settings `raylab autograder` writes into its bundle (the stages, the seed).
  writeFileSync(join(root, 'source', 'raylab-autograder.json'), JSON.stringify({ stages: [STAGE], seed: 1234 }));
  const r = spawnSync(raylab, ['gradescope', '--root', root], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`raylab gradescope: ${r.stderr}`);
  return JSON.parse(readFileSync(join(root, 'results', 'results.json'), 'utf8'));
}

const work = mkdtempSync(join(tmpdir(), 'raylab-submit-'));
const server = await startServer();
let browser;
try {
  execFileSync(labgen, ['--solved', join(work, 'solved')], { stdio: 'pipe' });
  const downloads = join(work, 'downloads');
  mkdirSync(downloads);
  browser = await launchBrowser(undefined, { downloads });
  const { page, problems } = await openPage(browser, server.url, '');
  await allowDownloads(page, downloads);
  await page.evaluate((id) => window.raylab.switchTo({ stage: id }), STAGE);
  for (const [name, dir, full] of [['solved', join(work, 'solved', STAGE), true], ['as handed out', join(projectRoot, 'labs', STAGE), false]]) {
    await page.evaluate((files) => window.raylab.openFolder({ files }), shaderFiles(dir));
    await page.waitForFunction(() => /Your files/.test(document.getElementById('messages').textContent), { timeout: 120_000 });
    for (const f of readdirSync(downloads)) rmSync(join(downloads, f));
    await page.click('#submit');
    const zipPath = await finishedDownload(downloads);
    check(zipPath !== null, `${name}: the page downloads raylab-submission.zip`);
    if (!zipPath) continue;
    const zip = readFileSync(zipPath);
    const listed = execFileSync('unzip', ['-Z1', zipPath], { encoding: 'utf8' }).trim().split('\n');
    check(listed.every((p) => p.startsWith(`${STAGE}/`)) && listed.length === Object.keys(shaderFiles(dir)).length,
      `${name}: the zip holds the stage folder's ${listed.length} shader files (${listed.join(', ')})`);
    const pl = gradePrairieLearn(raylab, zip, join(work, `pl-${full}`), '01');
    check(pl.gradable && pl.score === (full ? 1 : 0), `${name}: raylab prairielearn scores it ${pl.score} (${pl.message})`);
    const gs = gradeGradescope(zip, join(work, `gs-${full}`));
    const points = gs.score ?? gs.tests?.reduce((a, t) => a + t.score, 0);
    const max = gs.tests?.reduce((a, t) => a + (t.max_score ?? 0), 0);
    check(full ? points > 0 && Math.abs(points - max) < 1e-6 : points === 0, `${name}: raylab gradescope scores it ${points} of ${max}`);
  }
  check(problems.length === 0, `no console errors, page errors or failed requests${problems.length ? `: ${problems.join('; ')}` : ''}`);
} finally {
  await browser?.close();
  server.stop();
  rmSync(work, { recursive: true, force: true });
}
if (failures.length) {
  console.log(`\n${failures.length} submission check(s) failed`);
  process.exit(1);
}
