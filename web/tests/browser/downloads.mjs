// Shared by the tests that press "Download for submission" (submission.mjs,
// editor.mjs): the native tools' paths from the command line, the zip
// caught in the browser's downloads folder, and PrairieLearn's grade of it.
import { existsSync, mkdirSync, readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { join, resolve } from 'node:path';
import { projectRoot } from './browser.mjs';

// --raylab PATH, --labgen PATH (default: the build folder's).
export function toolPaths(args = process.argv.slice(2)) {
  const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
  return {
    raylab: resolve(option('--raylab', join(projectRoot, 'build/raylab'))),
    labgen: resolve(option('--labgen', join(projectRoot, 'build/raylab-labgen'))),
  };
}

// Prints each check; FAILURES lists the failed ones.
export function checker() {
  const failures = [];
  const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };
  return { check, failures };
}

// DOWNLOADS/NAME once finished: there, no NAME.part beside it (Firefox),
// and its size the same twice in a row (up to 20 s); its path, or null.
export async function finishedDownload(downloads, name = 'raylab-submission.zip') {
  const path = join(downloads, name);
  let size = -1;
  for (let i = 0; i < 200; ++i) {
    await new Promise((r) => setTimeout(r, 100));
    if (!existsSync(path) || readdirSync(downloads).some((f) => f.endsWith('.part'))) continue;
    const now = statSync(path).size;
    if (now > 0 && now === size) return path;
    size = now;
  }
  return existsSync(path) ? path : null;
}

// ZIP graded as PrairieLearn grades an upload (it keeps the zip as a file):
// `raylab prairielearn --stages STAGES` in ROOT; its results.json.
export function gradePrairieLearn(raylab, zip, root, stages) {
  mkdirSync(join(root, 'student'), { recursive: true });
  writeFileSync(join(root, 'student', 'raylab-submission.zip'), zip);
  const r = spawnSync(raylab, ['prairielearn', '--stages', stages, '--root', root], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`raylab prairielearn: ${r.stderr}`);
  return JSON.parse(readFileSync(join(root, 'results', 'results.json'), 'utf8'));
}
