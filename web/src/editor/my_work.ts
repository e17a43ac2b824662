// "my work (in this page)": the student's lab folders as the page keeps
// them (work_store.ts), laid out as a handout's labs/ folder is: one folder
// per stage, <stage>/<file>. A stage's folder starts as the course handed it
// out (fetched from labs/<stage>/, no download); a stage that builds on
// earlier ones reads the files its own folder lacks from theirs, newest
// first, as a handout's stage folder does natively (lab_folder.ts,
// labFromFiles). The files are held here too, so that the picture's reloads
// read what the editor holds without waiting for the storage.
import { ROOT, type Catalog, type Sources } from '../course/catalog.js';
import type { ZipEntry } from '../app/submission_zip.js';
import { WorkStore } from './work_store.js';

const SHADER = /\.(glsl|vert|frag|geom)$/;

// The folder the page's messages name: my-work/01-raycast/intersect_sphere.glsl:18.
export const WORK_FOLDER = 'my-work';

// One file the editor shows for a stage: NAME, kept in OWNER's folder (the
// stage's own, or an earlier stage's that the stage reads).
export interface WorkFile {
  name: string;
  owner: string;
}

export class MyWork {
  private unsaved = new Map<string, string>();  // path -> text not yet stored
  private saving: Promise<void> | null = null;

  private constructor(private catalog: Catalog, private store: WorkStore,
    private texts: Map<string, string>, private passed: Map<string, boolean>) {}

  static async open(catalog: Catalog): Promise<MyWork> {
    const store = await WorkStore.open();
    const [texts, passed] = await Promise.all([store.files(), store.verdicts()]);
    return new MyWork(catalog, store, texts, passed);
  }

  private labFiles(stageId: string): string[] {
    return this.catalog.stages.find((s) => s.info.id === stageId)?.labFiles ?? [];
  }

  // The handout's copy of STAGEID's file NAME.
  private async handout(stageId: string, name: string): Promise<string> {
    const r = await fetch(`${ROOT}/labs/${stageId}/${name}`);
    if (!r.ok) throw new Error(`labs/${stageId}/${name}: HTTP ${r.status}`);
    return r.text();
  }

  // Every file of STAGEIDS' folders that the page does not keep yet, copied
  // from the handout (a new student; a stage released since; a file a
  // republished bundle added).
  async ensure(stageIds: string[]): Promise<void> {
    const missing = stageIds.flatMap((id) => this.labFiles(id).filter((n) => !this.texts.has(`${id}/${n}`)).map((n) => [id, n] as const));
    const texts = await Promise.all(missing.map(([id, n]) => this.handout(id, n)));
    // Not over a copy another call kept (and the student began editing) meanwhile.
    await Promise.all(missing.map(([id, n], i) => (this.texts.has(`${id}/${n}`) ? undefined : this.write(id, n, texts[i]!))));
  }

  // STAGEID's files and, after them, those of EARLIER (newest first) its
  // own folder lacks: a stage's own file wins over an earlier one of the
  // same name.
  files(stageId: string, earlier: string[]): WorkFile[] {
    const out: WorkFile[] = [];
    const seen = new Set<string>();
    for (const owner of [stageId, ...earlier])
      for (const name of this.namesIn(owner))
        if (!seen.has(name)) {
          seen.add(name);
          out.push({ name, owner });
        }
    return out;
  }

  private namesIn(stageId: string): string[] {
    return [...this.texts.keys()].filter((p) => p.startsWith(`${stageId}/`)).map((p) => p.slice(stageId.length + 1)).sort();
  }

  text(file: WorkFile): string {
    return this.texts.get(`${file.owner}/${file.name}`) ?? '';
  }

  // Kept at once (the picture's next reload reads it) and written to the
  // browser's storage: one transaction at a time, with the latest text of
  // each file changed meanwhile (typing faster than the storage commits
  // skips the texts in between, never the last). Done when TEXT is stored.
  write(owner: string, name: string, text: string): Promise<void> {
    this.texts.set(`${owner}/${name}`, text);
    this.unsaved.set(`${owner}/${name}`, text);
    this.saving ??= this.saveAll();
    return this.saving;
  }

  // False while an edit is not yet stored (the page asks before it closes).
  get saved(): boolean {
    return this.saving === null;
  }

  private async saveAll(): Promise<void> {
    try {
      while (this.unsaved.size) {
        const batch = [...this.unsaved];
        this.unsaved.clear();
        try {
          await this.store.putFiles(batch);
        } catch (e) {
          for (const [path, text] of batch) if (!this.unsaved.has(path)) this.unsaved.set(path, text);
          throw e;
        }
      }
    } finally {
      this.saving = null;
    }
  }

  // FILE as the course handed it out (a reset: the editor keeps it, as any edit).
  handedOut(file: WorkFile): Promise<string> {
    return this.handout(file.owner, file.name);
  }

  // What the core draws and checks: the files of files() in their stages'
  // folders (my-work/<stage>), the way labFromFiles gives a lab folder from disk.
  sources(stageId: string, earlier: string[]): Sources {
    const kept = this.files(stageId, earlier);
    const files = new Map(kept.map((f) => [f.name, this.text(f)]));
    if (files.size === 0) throw new Error(`the page keeps no files of ${stageId}`);
    const owners = new Map(kept.filter((f) => f.owner !== stageId).map((f) => [f.name, f.owner]));
    return { kind: 'disk', shown: `${WORK_FOLDER}/${stageId}`, files, owners };
  }

  // Every stage folder the page keeps, as submission_zip.ts zips it.
  submission(): ZipEntry[] {
    const encoder = new TextEncoder();
    return [...this.texts].sort(([a], [b]) => (a < b ? -1 : 1)).map(([path, text]) => ({ path, data: encoder.encode(text) }));
  }

  // The shader files of ENTRIES that sit directly in a stage's folder
  // (<stage>/<file>, as a submission holds them, or below a folder such as
  // labs/<stage>/<file>), of the stages this page offers, as <stage>/<file>.
  importable(entries: ZipEntry[]): ZipEntry[] {
    const ids = new Set(this.catalog.stages.map((s) => s.info.id));
    return entries.flatMap((e) => {
      const parts = e.path.split('/');
      const stage = parts.at(-2);
      return stage && ids.has(stage) && SHADER.test(parts.at(-1)!) ? [{ path: `${stage}/${parts.at(-1)}`, data: e.data }] : [];
    });
  }

  // ENTRIES (importable()) kept in place of the page's copies.
  async import(entries: ZipEntry[]): Promise<void> {
    const decoder = new TextDecoder();
    await Promise.all(entries.map((e) => this.write(e.path.split('/')[0]!, e.path.split('/')[1]!, decoder.decode(e.data))));
  }

  verdict(stageId: string): boolean | undefined {
    return this.passed.get(stageId);
  }

  setVerdict(stageId: string, passed: boolean): Promise<void> {
    this.passed.set(stageId, passed);
    return this.store.putVerdict(stageId, passed);
  }
}
