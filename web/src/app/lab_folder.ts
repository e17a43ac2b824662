// A student's lab opened from disk (<input type="file" webkitdirectory>,
// which Chrome, Edge, Firefox and Safari support): either their whole labs/
// folder (one sub-folder per stage) or one stage folder. Only shader files
// are read; nothing is uploaded anywhere.
import type { Sources } from '../course/catalog.js';

const SHADER = /\.(glsl|vert|frag|geom)$/;

export async function labFromFiles(files: FileList | File[], stageId: string): Promise<Sources> {
  const list = Array.from(files);
  if (list.length === 0) throw new Error('the folder is empty');
  const root = (list[0].webkitRelativePath || list[0].name).split('/')[0];
  const byPath = new Map(list.map((f) => [f.webkitRelativePath || f.name, f]));
  // labs/<stage>/<file> inside the picked folder, or <file> directly in it.
  const nested = [...byPath.keys()].some((p) => p.startsWith(`${root}/${stageId}/`));
  const prefix = nested ? `${root}/${stageId}/` : `${root}/`;
  const files2 = new Map<string, string>();
  for (const [path, file] of byPath) {
    if (!path.startsWith(prefix)) continue;
    const name = path.slice(prefix.length);
    if (!name.includes('/') && SHADER.test(name)) files2.set(name, await file.text());
  }
  if (files2.size === 0)
    throw new Error(`${root}/ has no shader files for stage ${stageId} (open your labs/ folder or labs/${stageId}/)`);
  return { kind: 'disk', shown: nested ? `${root}/${stageId}` : root, files: files2 };
}
