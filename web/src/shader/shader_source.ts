// Assembles one GLSL shader from files by the native rules
// (framework/src/core/shader_source.cpp): `#include "name"` resolved through
// a search path (first folder wins, each file once), the defines after the
// version line, the shared constants and a prelude (the baked scene), and a
// record of where every assembled line came from, so that compiler errors
// name the student's file and line.
import { constantsGlsl } from './shader_constants.js';
import type { SourceFolder } from './source_folder.js';

export const GENERATED = '<raylab>';

export interface SourceLine {
  file: string;
  line: number;
}

export interface ShaderSource {
  text: string;
  origin: SourceLine[];  // origin[i]: where assembled line i + 1 came from
  files: { folder: SourceFolder; name: string }[];
}

export class ShaderError extends Error {}

// The line parsers follow the native ones (which document the regex each replaces).
const INCLUDE = /^\s*#\s*include\s*(["<])([^">]*)[">]\s*(\/\/[^\r]*)?$/;
const VERSION = /^\s*#\s*version\b[^\r]*$/;

function escapes(name: string): boolean {
  return name.startsWith('/') || name.split('/').includes('..') || name.includes('\\');
}

export async function assembleShader(
  entry: string,
  search: SourceFolder[],
  defines: string[],
  prelude = '',
): Promise<ShaderSource> {
  const out: ShaderSource = { text: '', origin: [], files: [] };
  const included = new Set<string>();
  const emit = (text: string, file: string, line: number) => {
    out.text += text + '\n';
    out.origin.push({ file, line });
  };
  const resolve = (name: string, fromFile: string, fromLine: number): SourceFolder => {
    if (name === '' || escapes(name))
      throw new ShaderError(
        `${fromFile}:${fromLine}: #include "${name}" is not allowed: name a file inside the ` +
          'stage folder (no "..", no absolute path)',
      );
    for (const folder of search) if (folder.has(name)) return folder;
    const where = fromFile ? `${fromFile}:${fromLine}: ` : '';
    throw new ShaderError(
      `${where}cannot find shader file "${name}" (looked in ${search.map((f) => f.shown).join(', ')})`,
    );
  };
  const include = async (folder: SourceFolder, name: string): Promise<void> => {
    const shown = `${folder.shown}/${name}`;
    if (included.has(shown)) return;  // once per program: no include guards needed
    included.add(shown);
    out.files.push({ folder, name });
    const text = await folder.read(name);
    // A NUL byte ends the text for the GL compiler ("lacks main"): say so (as natively).
    const nul = text.indexOf('\0');
    if (nul >= 0)
      throw new ShaderError(
        `${shown}:${text.slice(0, nul).split('\n').length}: the file holds NUL bytes (not plain text: ` +
          'saved as UTF-16, or a binary file?); save it as UTF-8 text',
      );
    const lines = text.split('\n');
    if (lines.length > 0 && lines[lines.length - 1] === '') lines.pop();  // getline: no last empty line
    for (let n = 1; n <= lines.length; ++n) {
      let line = lines[n - 1];
      if (line.endsWith('\r')) line = line.slice(0, -1);
      const inc = INCLUDE.exec(line);
      if (inc) await include(resolve(inc[2], shown, n), inc[2]);
      else if (VERSION.test(line)) emit('', shown, n);  // the framework sets the version
      else emit(line, shown, n);
    }
  };

  emit('#version 330 core', GENERATED, 1);
  let n = 2;
  for (const d of defines) emit(`#define ${d}`, GENERATED, n++);
  const ext = entry.slice(entry.lastIndexOf('.'));
  const stage = { '.vert': 'RAYLAB_VERTEX_SHADER', '.geom': 'RAYLAB_GEOMETRY_SHADER', '.frag': 'RAYLAB_FRAGMENT_SHADER' }[ext];
  if (stage) emit(`#define ${stage}`, GENERATED, n++);
  const generated = (constantsGlsl() + prelude).split('\n');
  if (generated[generated.length - 1] === '') generated.pop();
  for (const line of generated) emit(line, GENERATED, n++);
  await include(resolve(entry, '', 0), entry);
  return out;
}

// WebGL 2's dialect: `#version 300 es` and precision lines in place of the
// version line; the line mapping is kept (native: asGlslEs300).
const ES_PRELUDE = [
  '#version 300 es',
  'precision highp float;',
  'precision highp int;',
  'precision highp sampler2DArray;',
  'precision highp isampler2D;',
  'precision highp samplerCube;',
];

export function asGlslEs300(s: ShaderSource): ShaderSource {
  const firstLineEnd = s.text.indexOf('\n');
  const text = ES_PRELUDE.join('\n') + '\n' + (firstLineEnd < 0 ? '' : s.text.slice(firstLineEnd + 1));
  const origin = ES_PRELUDE.map((_, i) => ({ file: GENERATED, line: i + 1 }));
  return { ...s, text, origin: origin.concat(s.origin.slice(1)) };
}

export function where(s: ShaderSource, assembledLine: number): SourceLine {
  return s.origin[assembledLine - 1] ?? { file: GENERATED, line: assembledLine };
}

// A browser's compiler log ("ERROR: 0:12: 'x' : syntax error", the form
// ANGLE and every WebGL implementation print) with file:line in place of the
// assembled line number.
export function mapCompilerLog(log: string, s: ShaderSource): string {
  return log
    .split('\n')
    .filter((line) => line.trim() !== '' && line !== '\0')
    .map((line) => {
      const m = /^\s*(ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$/.exec(line);
      if (!m) return line;
      const at = where(s, Number(m[2]));
      return `${at.file}:${at.line}: ${m[1] === 'ERROR' ? 'error' : 'warning'}: ${m[3]}`;
    })
    .join('\n');
}
