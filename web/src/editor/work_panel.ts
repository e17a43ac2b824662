// The page's side of "my work (in this page)": the editor panel under or
// beside the picture (code_editor.ts) on the student's files (my_work.ts),
// so that page.ts only asks it for a stage's sources and tells it what a
// load or a Check found. Every edit is kept at once; the picture follows
// 0.7 s after the last keystroke (the page's reload: the camera stays, a
// compile error keeps the last picture that compiled), or at once on
// Ctrl/Cmd-S. The Reset button puts the shown file back as handed out;
// "Import a zip…" takes a submission zip back (from another device).
import type { OpenTodo } from '../core/core.js';
import type { Catalog, Sources } from '../course/catalog.js';
import type { ZipEntry } from '../app/submission_zip.js';
import { CodeEditor } from './code_editor.js';
import { lineNotes } from './diagnostics.js';
import { MyWork } from './my_work.js';
import { markStages } from './stage_marks.js';
import { readZip } from './zip_reader.js';

const RELOAD_AFTER_MS = 700;

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

export class WorkPanel {
  private opening: Promise<MyWork> | null = null;
  private opened: MyWork | null = null;  // once open: edits are kept without waiting
  private editor: CodeEditor | null = null;
  private stageShown = '';
  private timer: ReturnType<typeof setTimeout> | undefined;
  private askedToKeep = false;

  // RELOAD: draw the stage again from the files (a reload); FAILED: say what went wrong.
  constructor(private catalog: Catalog, private reload: () => void, private failed: (message: string) => void) {
    $('reset-file').onclick = () => void this.resetShown();
    $('import-zip').onclick = () => $('zip-file').click();
    $<HTMLInputElement>('zip-file').onchange = (e) => {
      const input = e.target as HTMLInputElement;
      if (input.files?.[0]) void this.importZip(input.files[0]);
      input.value = '';  // the same file again is a change
    };
    // An edit typed a moment ago may not be stored yet: the browser asks first.
    addEventListener('beforeunload', (e) => { if (this.opened && !this.opened.saved) e.preventDefault(); });
  }

  // The work, opened once (the browser's storage), the Stage menu marked.
  private work(): Promise<MyWork> {
    this.opening ??= MyWork.open(this.catalog).then((w) => {
      this.opened = w;
      markStages($<HTMLSelectElement>('stage'), (id) => w.verdict(id));
      return w;
    });
    this.opening.catch(() => (this.opening = null));
    return this.opening;
  }

  // The editor shown (the source is "my work") or not.
  show(on: boolean): void {
    $('editor').hidden = !on;
    document.querySelector('main')!.classList.toggle('editing', on);
  }

  // STAGEID's code for the core: the stage's folder and the EARLIER stages'
  // files it lacks (newest first); the editor shows them.
  async sources(stageId: string, earlier: string[]): Promise<Sources> {
    const work = await this.work();
    await work.ensure([stageId, ...earlier]);
    if (this.stageShown !== stageId) {
      clearTimeout(this.timer);  // an edit's pending redraw: the new stage is drawn anyway
      const files = work.files(stageId, earlier);
      this.editor ??= new CodeEditor($('editor-host'), $('editor-tabs'), (f, text) => this.edited(f.owner, f.name, text),
        () => this.reloadNow());
      this.editor.open(files, files.map((f) => work.text(f)), stageId);
      this.stageShown = stageId;
    }
    return work.sources(stageId, earlier);
  }

  private edited(owner: string, name: string, text: string): void {
    // The first edit asks the browser to keep the page's storage for good
    // (else it may clear it when short of space, and Safari may after
    // seven days of use without a visit): Firefox asks the student.
    if (!this.askedToKeep) void navigator.storage?.persist?.().catch(() => false);
    this.askedToKeep = true;
    this.opened!.write(owner, name, text).catch((e: Error) =>
      this.failed(`Your edit of ${owner}/${name} could not be kept in this browser: ${e.message}`));
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.reload(), RELOAD_AFTER_MS);
  }

  private reloadNow(): void {
    clearTimeout(this.timer);
    this.reload();
  }

  // What a load found: TODOS, or an error MESSAGE naming files and lines.
  loaded(todos: OpenTodo[], message: string): void {
    if (!this.editor || $('editor').hidden) return;
    this.editor.mark(lineNotes(todos, message));
  }

  private async resetShown(): Promise<void> {
    const file = this.editor?.active();
    if (!file) return;
    if (!confirm(`Reset ${file.owner}/${file.name} to the file as handed out? Your changes to it are lost.`)) return;
    try {
      this.editor!.replace(await (await this.work()).handedOut(file));
      this.reloadNow();
    } catch (e) {
      this.failed(`Reset ${file.name}: ${(e as Error).message}`);
    }
  }

  // A Check's verdict on the work: kept, and shown in the Stage menu.
  async checked(stageId: string, passed: boolean): Promise<void> {
    const work = await this.work();
    await work.setVerdict(stageId, passed);
    markStages($<HTMLSelectElement>('stage'), (id) => work.verdict(id));
  }

  async submission(): Promise<ZipEntry[]> {
    return (await this.work()).submission();
  }

  // The shader files of ENTRIES (a lab folder's, a zip's) kept in place
  // of the page's copies once the student agrees; false if they did not.
  async import(entries: ZipEntry[], from: string): Promise<boolean> {
    const work = await this.work();
    const kept = work.importable(entries);
    if (kept.length === 0) throw new Error(`${from} holds no shader file in a folder of this page's stages (${this.catalog.stages.map((s) => s.info.id).join(', ')})`);
    const stages = [...new Set(kept.map((e) => e.path.split('/')[0]))];
    if (!confirm(`Keep the ${kept.length} shader files of ${stages.join(', ')} from ${from} in the page, in place of the page's copies?`)) return false;
    await work.import(kept);
    this.stageShown = '';  // the editor reads the files again
    return true;
  }

  private async importZip(file: File): Promise<void> {
    try {
      if (await this.import(await readZip(new Uint8Array(await file.arrayBuffer())), file.name)) this.reloadNow();
    } catch (e) {
      this.failed(`Import ${file.name}: ${(e as Error).message}`);
    }
  }
}
