// What the editor marks at a line of a file: an unfinished TODO (the
// renderer's todos, as the messages list them) and compile errors (the
// messages' "my-work/01-raycast/intersect_sphere.glsl:18: error: ..." lines:
// the core maps the driver's log to the student's file and line, natively's
// mapCompilerLog). Files are matched by name: a stage reads one file of each
// name (its own folder's, else the newest earlier stage's), so a name is a file.
import type { OpenTodo } from '../core/core.js';

export interface LineNote {
  line: number;  // 1-based
  severity: 'error' | 'warning';
  message: string;
}

const baseName = (path: string) => path.slice(path.lastIndexOf('/') + 1);
const FILE_LINE = /(\S+\.(?:glsl|vert|frag|geom)):(\d+)(?::\d+)?:?[ \t]*(.*)/g;

// Per file name: its TODOs and the errors MESSAGE names.
export function lineNotes(todos: OpenTodo[], message: string): Map<string, LineNote[]> {
  const out = new Map<string, LineNote[]>();
  const add = (path: string, note: LineNote) => out.set(baseName(path), [...(out.get(baseName(path)) ?? []), note]);
  for (const t of todos) add(t.file, { line: t.line, severity: 'warning', message: `Unfinished TODO: ${t.title}` });
  for (const m of message.matchAll(FILE_LINE)) add(m[1]!, { line: Number(m[2]), severity: 'error', message: m[3]!.trim() || 'error' });
  return out;
}
