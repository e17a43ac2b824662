// The TODO blocks of a lab that still hold their stub (native:
// findOpenTodos in shader_source.cpp): a `labTodo();` call outside a comment,
// titled by the `// TODO(id): title` line above it.
import type { ShaderSource } from './shader_source.js';

export interface OpenTodo {
  file: string;
  line: number;
  title: string;
}

const TODO_TITLE = /^\s*\/\/\s*(TODO\([^)]*\):?[^\r]*)$/;
const STUB_CALL = /^[^/]*\blabTodo\s*\(\s*\)\s*;/;

export async function findOpenTodos(source: ShaderSource): Promise<OpenTodo[]> {
  const todos: OpenTodo[] = [];
  for (const { folder, name } of source.files) {
    const shown = `${folder.shown}/${name}`;
    if (shown.startsWith('framework/') || shown.startsWith('web/')) continue;
    let title = '';
    (await folder.read(name)).split('\n').forEach((line, i) => {
      const t = TODO_TITLE.exec(line);
      if (t) title = t[1];
      else if (STUB_CALL.test(line)) todos.push({ file: shown, line: i + 1, title: title || 'TODO' });
    });
  }
  return todos;
}
