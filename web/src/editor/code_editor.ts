// The page's code editor: CodeMirror 6 (dist/vendor/codemirror.js), the
// stage's files as tabs, each with its own text and undo history; TODOs and
// compile errors marked at their lines (diagnostics.ts). Tab is left to the
// browser (no indentWithTab), so keyboard users tab into the editor and out
// of it again; Ctrl-] and Ctrl-[ (Cmd on a Mac) indent. Ctrl/Cmd-S asks
// for the picture at once; every other edit is reported as it happens.
import {
  bracketMatching, cpp, defaultHighlightStyle, defaultKeymap, drawSelection, EditorState, EditorView, highlightActiveLine,
  highlightActiveLineGutter, history, historyKeymap, indentOnInput, indentUnit, keymap, lineNumbers, lintGutter, lintKeymap,
  setDiagnostics, syntaxHighlighting, type Diagnostic, type Extension, type Text,
} from '../vendor/codemirror.js';
import type { LineNote } from './diagnostics.js';
import type { WorkFile } from './my_work.js';

const key = (f: WorkFile) => `${f.owner}/${f.name}`;

function toDiagnostics(doc: Text, notes: LineNote[]): Diagnostic[] {
  return notes.map((n) => {
    const line = doc.line(Math.min(Math.max(n.line, 1), doc.lines));
    return { from: line.from, to: line.to, severity: n.severity, message: n.message };
  });
}

export class CodeEditor {
  private view: EditorView;
  private states = new Map<string, EditorState>();  // per file, kept across stages (undo history)
  private files: WorkFile[] = [];
  private current: WorkFile | null = null;
  private extensions: Extension[];

  // ONEDIT: a file's text changed (typed, pasted, reset); ONSAVE: Ctrl/Cmd-S.
  constructor(host: HTMLElement, private tabs: HTMLElement,
    onEdit: (file: WorkFile, text: string) => void, onSave: () => void) {
    this.extensions = [
      lineNumbers(), highlightActiveLineGutter(), history(), drawSelection(), indentOnInput(), bracketMatching(),
      highlightActiveLine(), syntaxHighlighting(defaultHighlightStyle, { fallback: true }), cpp(), lintGutter(),
      // The labs indent by four spaces; long comments wrap (a phone shows about 35 characters).
      indentUnit.of('    '), EditorView.lineWrapping,
      keymap.of([{ key: 'Mod-s', run: () => { onSave(); return true; } }, ...defaultKeymap, ...historyKeymap, ...lintKeymap]),
      EditorView.contentAttributes.of({ 'aria-label': 'shader code' }),
      EditorView.updateListener.of((u) => {
        if (u.docChanged && this.current) onEdit(this.current, u.state.doc.toString());
      }),
    ];
    this.view = new EditorView({ parent: host, state: EditorState.create({ extensions: this.extensions }) });
  }

  // FILES as tabs, with their TEXTS; the file shown stays if it is among them.
  open(files: WorkFile[], texts: string[], stageId: string): void {
    this.keepCurrent();
    this.files = files;
    files.forEach((f, i) => {
      const kept = this.states.get(key(f));
      if (!kept || kept.doc.toString() !== texts[i]) this.states.set(key(f), EditorState.create({ doc: texts[i], extensions: this.extensions }));
    });
    this.tabs.replaceChildren(...files.map((f) => {
      const b = document.createElement('button');
      b.type = 'button';
      b.setAttribute('role', 'tab');
      b.dataset.file = key(f);
      b.textContent = f.owner === stageId ? f.name : `${f.name} (${f.owner})`;
      b.title = f.owner === stageId ? `${stageId}/${f.name}` : `${f.owner}/${f.name}: ${stageId} reads it from the earlier stage's folder`;
      b.onclick = () => this.show(f);
      return b;
    }));
    // The file shown stays if it is the stage's own (another stage opens on its own first file).
    const again = this.current && this.current.owner === stageId && files.find((f) => key(f) === key(this.current!));
    this.current = null;
    if (files.length) this.show(again || files[0]!);
  }

  private keepCurrent(): void {
    if (this.current) this.states.set(key(this.current), this.view.state);
  }

  show(file: WorkFile): void {
    this.keepCurrent();
    this.current = file;
    this.view.setState(this.states.get(key(file))!);
    for (const b of this.tabs.children as HTMLCollectionOf<HTMLElement>)
      b.setAttribute('aria-selected', String(b.dataset.file === key(file)));
  }

  active(): WorkFile | null {
    return this.current;
  }

  // The shown file's whole text replaced by TEXT (a reset: undo brings it back).
  replace(text: string): void {
    this.view.dispatch({ changes: { from: 0, to: this.view.state.doc.length, insert: text } });
  }

  // NOTES per file name, at their lines; a tab with notes is marked.
  mark(notes: Map<string, LineNote[]>): void {
    this.keepCurrent();
    for (const f of this.files) {
      const own = notes.get(f.name) ?? [];
      const state = this.states.get(key(f))!;
      const spec = setDiagnostics(state, toDiagnostics(state.doc, own));
      if (f === this.current) this.view.dispatch(spec);
      else this.states.set(key(f), state.update(spec).state);
      const tab = [...this.tabs.children].find((b) => (b as HTMLElement).dataset.file === key(f));
      tab?.classList.toggle('has-error', own.some((n) => n.severity === 'error'));
      tab?.classList.toggle('has-todo', own.some((n) => n.severity === 'warning'));
    }
  }

  focus(): void {
    this.view.focus();
  }
}
