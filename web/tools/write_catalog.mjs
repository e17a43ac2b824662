// Writes dist/catalog.json: what the page may fetch from the project - every
// stage.json with the names of its solution files, the framework's and the
// web's shader folders, the variant folders, the labs shipped in labs/ and the
// scene files. The page never asks the server for a file that is not listed,
// so a missing file is an error message of ours, not a 404 in the console.
// Run by `npm run build`; `raylab web-bundle` runs it on its bundle:
//   node tools/write_catalog.mjs [--root DIR] [--stages 01-raycast,...] [--no-solutions] [--bundle]
// (--root: a tree laid out like the project's; --stages: only those stages in
// the page's menu; --no-solutions: the page offers the labs only; --bundle:
// a students' bundle, which has no test API.)
import { readdirSync, readFileSync, statSync, writeFileSync, mkdirSync, renameSync } from 'node:fs';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const args = process.argv.slice(2);
const option = (name) => (args.includes(name) ? args[args.indexOf(name) + 1] : undefined);
const root = option('--root') ?? join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const only = option('--stages')?.split(',');
const solutions = !args.includes('--no-solutions');
const isDir = (p) => { try { return statSync(p).isDirectory(); } catch { return false; } };
const filesIn = (dir) => (isDir(dir) ? readdirSync(dir).filter((n) => !isDir(join(dir, n))).sort() : []);
const shaderFiles = (dir) => filesIn(dir).filter((n) => /\.(glsl|vert|frag|geom)$/.test(n));

const stageIds = readdirSync(join(root, 'solution'))
  .filter((id) => isDir(join(root, 'solution', id)) && filesIn(join(root, 'solution', id)).includes('stage.json'))
  .sort();
const entry = (id) => ({
  info: JSON.parse(readFileSync(join(root, 'solution', id, 'stage.json'), 'utf8')),
  solutionFiles: solutions ? shaderFiles(join(root, 'solution', id)) : [],
  labFiles: shaderFiles(join(root, 'labs', id)),
});
const stages = stageIds.filter((id) => !only || only.includes(id)).map(entry);
// A bundle's stages that the released ones build on (it holds their
// stage.json, and with --carry own their folders as handed out): not in the
// page's menu, but the core reads them for builds_on and the page for the
// folders a stage reads.
const earlier = stageIds.filter((id) => only && !only.includes(id)).map(entry);

const variants = {};
const variantRoot = join(root, 'framework/shaders/variants');
for (const variant of (isDir(variantRoot) ? readdirSync(variantRoot) : []).filter((n) => isDir(join(variantRoot, n))))
  for (const stage of readdirSync(join(variantRoot, variant)))
    variants[`${variant}/${stage}`] = shaderFiles(join(variantRoot, variant, stage));

const catalog = {
  // The solutions are listed (tools/serve.mjs without --with-solutions
  // serves this file with false here and no solution files).
  solutions,
  bundle: args.includes('--bundle'),
  stages,
  earlier,
  framework: shaderFiles(join(root, 'framework/shaders')),
  web: shaderFiles(join(root, 'web/shaders')),
  variants,
  // The pictures and meshes scenes name (the core's scene reader checks that they exist).
  assets: ['textures', 'meshes'].flatMap((d) => filesIn(join(root, 'assets', d)).map((n) => `${d}/${n}`)),
  // Ray-tracing scenes at the top, fur scenes under fur/.
  scenes: [
    ...filesIn(join(root, 'assets/scenes')).filter((n) => n.endsWith('.json')),
    ...filesIn(join(root, 'assets/scenes/fur')).filter((n) => n.endsWith('.json')).map((n) => `fur/${n}`),
  ],
};
const out = join(root, 'web/dist/catalog.json');
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out + '.tmp', JSON.stringify(catalog, null, 1));
renameSync(out + '.tmp', out);
console.log(`web: wrote dist/catalog.json (${stages.length} stages, ${catalog.scenes.length} scenes)`);
