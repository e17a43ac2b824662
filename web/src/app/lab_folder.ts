// A student's lab opened from disk: their whole labs/ folder (one
// sub-folder per stage; a handout's stage folder holds only its own files and
// reads the stages it builds on from the folders beside it, as natively) or
// one stage folder. Only shader files are read; nothing is uploaded anywhere.
//  - Where the browser offers the File System Access API (Chrome, Edge), the
//    folder stays open and is watched: saving a file reloads the stage, as
//    the native window does.
//  - Elsewhere (Firefox, Safari) <input type="file" webkitdirectory> reads a
//    snapshot; picking the folder again reloads it.
import type { Sources } from '../course/catalog.js';
import type { ZipEntry } from './submission_zip.js';

const SHADER = /\.(glsl|vert|frag|geom)$/;

function noShaders(root: string, stageId: string): Error {
  return new Error(`${root}/ has no shader files for stage ${stageId} (open your labs/ folder or labs/${stageId}/)`);
}

// Which folder holds STAGEID's files, given the picked folder ROOT and the
// names of the folders in it: ROOT/<stage> in a whole labs/ folder, else
// ROOT itself - unless ROOT is another stage's folder, or a labs/ folder
// without this stage, which would silently run the wrong code.
function stageFolder(root: string, subfolders: string[], stageId: string, stageIds: string[]): 'nested' | 'root' {
  if (subfolders.includes(stageId)) return 'nested';
  if (stageIds.includes(root) && root !== stageId)
    throw new Error(`you opened ${root}/, the folder of stage ${root}: for stage ${stageId} open your labs/ folder or ${stageId}/`);
  if (subfolders.some((f) => stageIds.includes(f)))
    throw new Error(`${root}/ has no ${stageId}/ folder (it has ${subfolders.filter((f) => stageIds.includes(f)).join(', ')})`);
  return 'root';
}

// STAGEID's files; in a labs/ folder also those of the stages it builds on
// (EARLIER, newest first) that its own folder lacks: a file of a later stage
// replaces an earlier one of the same name.
export async function labFromFiles(files: FileList | File[], stageId: string, stageIds: string[],
                                   earlier: string[] = []): Promise<Sources> {
  const list = Array.from(files);
  if (list.length === 0) throw new Error('the folder is empty');
  const root = (list[0]!.webkitRelativePath || list[0]!.name).split('/')[0]!;
  const byPath = new Map(list.map((f) => [f.webkitRelativePath || f.name, f]));
  const subfolders = [...new Set([...byPath.keys()].map((p) => p.split('/')).filter((p) => p.length > 2).map((p) => p[1]!))];
  const nested = stageFolder(root, subfolders, stageId, stageIds) === 'nested';
  const folders = nested ? [stageId, ...earlier.filter((id) => subfolders.includes(id))] : [''];
  const texts = new Map<string, string>();
  const owners = new Map<string, string>();
  for (const id of folders) {
    const prefix = id ? `${root}/${id}/` : `${root}/`;
    for (const [path, file] of byPath) {
      if (!path.startsWith(prefix)) continue;
      const name = path.slice(prefix.length);
      if (name.includes('/') || !SHADER.test(name) || texts.has(name)) continue;
      texts.set(name, await file.text());
      if (id && id !== stageId) owners.set(name, id);
    }
  }
  if (texts.size === 0) throw noShaders(root, stageId);
  return { kind: 'disk', shown: nested ? `${root}/${stageId}` : root, files: texts, owners };
}

// What a submission holds (submission_zip.ts): each stage folder of a
// labs/ folder, or one stage's folder (ROOT: a stage's name, else CURRENT),
// its own shader files under <stage>/. FILES: [path below the picked
// folder's parent, file].
async function submissionEntries(files: [string, File][], current: string, stageIds: string[]): Promise<ZipEntry[]> {
  if (files.length === 0) throw new Error('the folder is empty');
  const root = files[0]![0].split('/')[0]!;
  const nested = files.some(([p]) => p.split('/').length === 3 && stageIds.includes(p.split('/')[1]!));
  const entries: ZipEntry[] = [];
  for (const [path, file] of files) {
    const parts = path.split('/');
    if (!SHADER.test(path)) continue;
    if (nested && parts.length === 3 && stageIds.includes(parts[1]!)) entries.push({ path: `${parts[1]}/${parts[2]}`, data: new Uint8Array(await file.arrayBuffer()) });
    else if (!nested && parts.length === 2) entries.push({ path: `${stageIds.includes(root) ? root : current}/${parts[1]}`, data: new Uint8Array(await file.arrayBuffer()) });
  }
  if (entries.length === 0) throw new Error(`${root}/ has no shader files to submit`);
  return entries.sort((a, b) => (a.path < b.path ? -1 : 1));
}

export function submissionFromFiles(files: FileList | File[], current: string, stageIds: string[]): Promise<ZipEntry[]> {
  return submissionEntries(Array.from(files).map((f) => [f.webkitRelativePath || f.name, f]), current, stageIds);
}

// A folder picked through <input webkitdirectory> (browsers without folder
// watching): its shader files read at once, as a snapshot. The browser's
// File objects keep pointing at the files on disk, and a file saved since is
// unreadable in Chrome (a raw "could not be read" error) or reads the new
// text elsewhere: either way the page would check or zip something other
// than what it shows. changedOnDisk() tells before Check and Download.
export class PickedFolder {
  private constructor(private files: File[], private texts: Map<string, string>) {}

  static async read(files: FileList | File[]): Promise<PickedFolder> {
    const list = Array.from(files);
    if (list.length === 0) throw new Error('the folder is empty');
    const texts = new Map<string, string>();
    for (const f of list) {
      const path = f.webkitRelativePath || f.name;
      if (!SHADER.test(path)) continue;
      try {
        texts.set(path, await f.text());
      } catch {
        throw new Error(`${path} cannot be read (saved while the folder was being picked?): pick the folder again`);
      }
    }
    return new PickedFolder(list, texts);
  }

  // The snapshot as Files (labFromFiles and submissionFromFiles read them).
  private snapshot(): File[] {
    return [...this.texts].map(([path, text]) => {
      const f = new File([text], path.split('/').pop()!);
      Object.defineProperty(f, 'webkitRelativePath', { value: path });
      return f;
    });
  }

  lab(stageId: string, stageIds: string[], earlier: string[] = []): Promise<Sources> {
    return labFromFiles(this.snapshot(), stageId, stageIds, earlier);
  }

  submission(current: string, stageIds: string[]): Promise<ZipEntry[]> {
    return submissionFromFiles(this.snapshot(), current, stageIds);
  }

  // The shader files saved, removed or made unreadable since the folder was read.
  async changedOnDisk(): Promise<string[]> {
    const changed: string[] = [];
    for (const f of this.files) {
      const path = f.webkitRelativePath || f.name;
      if (!this.texts.has(path)) continue;
      try {
        if (await f.text() !== this.texts.get(path)) changed.push(path);
      } catch {
        changed.push(path);
      }
    }
    return changed;
  }
}

// The one line Check and Download stop with when a picked folder changed on disk.
export function changedOnDiskMessage(changed: string[]): string {
  const named = changed.slice(0, 3).join(', ') + (changed.length > 3 ? ` and ${changed.length - 3} more` : '');
  return `Your files changed on disk since the page read them (${named}): press Reload my files.`;
}

// The File System Access API's folder picker (not yet in TypeScript's DOM types).
type DirectoryPicker = (options?: { id?: string; mode?: 'read' }) => Promise<FileSystemDirectoryHandle>;
const picker = (window as unknown as { showDirectoryPicker?: DirectoryPicker }).showDirectoryPicker;
export const canWatchFolders = typeof picker === 'function';

// An open lab folder that can tell when its shader files change.
export class WatchedLab {
  private stamps = '';
  private readStage = '';  // the stage whose files the stamps describe

  // STAGEIDS: every stage's folder name, to tell a labs/ folder from a stage's.
  constructor(private root: FileSystemDirectoryHandle, private stageIds: string[]) {}

  static async pick(stageIds: string[]): Promise<WatchedLab> {
    return new WatchedLab(await picker!({ id: 'raylab-lab', mode: 'read' }), stageIds);
  }

  // The stage's folder: ROOT/<stage> when there is one, else ROOT itself.
  private async folder(stageId: string): Promise<{ dir: FileSystemDirectoryHandle; shown: string }> {
    const subfolders: string[] = [];
    for await (const [name, handle] of (this.root as unknown as AsyncIterable<[string, FileSystemHandle]>))
      if (handle.kind === 'directory') subfolders.push(name);
    if (stageFolder(this.root.name, subfolders, stageId, this.stageIds) === 'nested')
      return { dir: await this.root.getDirectoryHandle(stageId), shown: `${this.root.name}/${stageId}` };
    return { dir: this.root, shown: this.root.name };
  }

  // The stage's shader files; in a labs/ folder also the earlier stages'
  // (EARLIER, newest first) its own folder lacks.
  private async shaderFiles(stageId: string, earlier: string[] = []):
    Promise<{ shown: string; files: [string, File][]; owners: Map<string, string> }> {
    const { dir, shown } = await this.folder(stageId);
    const dirs: [string, FileSystemDirectoryHandle][] = [[stageId, dir]];
    if (dir !== this.root)
      for (const id of earlier) {
        try {
          dirs.push([id, await this.root.getDirectoryHandle(id)]);
        } catch {
          // not there: the stage's own folder may hold the file
        }
      }
    const files: [string, File][] = [];
    const owners = new Map<string, string>();
    for (const [id, d] of dirs)
      for await (const [name, handle] of (d as unknown as AsyncIterable<[string, FileSystemHandle]>))
        if (handle.kind === 'file' && SHADER.test(name) && !files.some(([n]) => n === name)) {
          files.push([name, await (handle as FileSystemFileHandle).getFile()]);
          if (id !== stageId) owners.set(name, id);
        }
    files.sort(([a], [b]) => (a < b ? -1 : 1));
    return { shown, files, owners };
  }

  // The folder's files for a submission (submissionEntries).
  async submission(current: string): Promise<ZipEntry[]> {
    const files: [string, File][] = [];
    const walk = async (dir: FileSystemDirectoryHandle, prefix: string, depth: number) => {
      for await (const [name, handle] of (dir as unknown as AsyncIterable<[string, FileSystemHandle]>)) {
        if (handle.kind === 'file') files.push([`${prefix}/${name}`, await (handle as FileSystemFileHandle).getFile()]);
        else if (depth === 0) await walk(handle as FileSystemDirectoryHandle, `${prefix}/${name}`, 1);
      }
    };
    await walk(this.root, this.root.name, 0);
    return submissionEntries(files, current, this.stageIds);
  }

  async read(stageId: string, earlier: string[] = []): Promise<Sources> {
    const { shown, files, owners } = await this.shaderFiles(stageId, earlier);
    if (files.length === 0) throw noShaders(this.root.name, stageId);
    this.stamps = files.map(([n, f]) => `${n}:${f.lastModified}:${f.size}`).join('|');
    this.readStage = stageId;
    const texts = new Map<string, string>();
    for (const [name, file] of files) texts.set(name, await file.text());
    return { kind: 'disk', shown, files: texts, owners };
  }

  // True when a shader file of STAGEID was added, removed or saved since
  // read() read that stage (false while another stage's files were read last).
  async changed(stageId: string, earlier: string[] = []): Promise<boolean> {
    if (stageId !== this.readStage) return false;
    const { files } = await this.shaderFiles(stageId, earlier);
    return files.map(([n, f]) => `${n}:${f.lastModified}:${f.size}`).join('|') !== this.stamps;
  }
}
