// Code: my lab folder… - the student's lab folder from disk, as the page
// holds it: watched where the browser can (Chrome, Edge: File System Access,
// a saved file reloads the stage), else a snapshot picked through the folder
// input (Firefox, Safari: "Reload my files" picks it again, and a file saved
// on disk since stops Check and Download with one line). The folders
// themselves are read by lab_folder.ts; this file is what the page does
// with them.
import { canWatchFolders, changedOnDiskMessage, PickedFolder, WatchedLab } from './lab_folder.js';
import type { Sources } from '../course/catalog.js';
import type { ZipEntry } from './submission_zip.js';

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

export interface DiskFolderEvents {
  opened(again: boolean): void;  // a folder is open (AGAIN: the same one read anew)
  cancelled(): void;             // the picker was closed without a folder
  failed(message: string): void;
}

export class DiskFolder {
  private watched: WatchedLab | null = null;  // a folder the page watches (Chrome, Edge)
  private picked: PickedFolder | null = null;  // a snapshot of a folder (other browsers)

  // STAGEIDS: every stage's folder name, to tell a labs/ folder from a stage's.
  constructor(private stageIds: string[], private on: DiskFolderEvents) {
    $<HTMLInputElement>('folder').onchange = (e) => {
      const files = (e.target as HTMLInputElement).files;
      if (!files || files.length === 0) return;
      // The same folder again ("Reload my files"): a reload, as after a save.
      const again = this.picked !== null;
      PickedFolder.read(files).then((picked) => {
        this.picked = picked;
        this.watched = null;
        this.on.opened(again);
      }, (err: Error) => this.on.failed(err.message));
    };
    $<HTMLInputElement>('folder').addEventListener('cancel', () => this.on.cancelled());
    // Browsers without folder watching: read the folder again after an edit.
    // (Emptied first: picking the same folder again must count as a change.)
    $('reload').onclick = () => {
      $<HTMLInputElement>('folder').value = '';
      $<HTMLInputElement>('folder').click();
    };
  }

  // Asks the student for their folder: the picker where folders can be watched, else the folder input.
  pick(): void {
    if (!canWatchFolders) return $<HTMLInputElement>('folder').click();
    WatchedLab.pick(this.stageIds).then((lab) => this.watch(lab), (err: Error) => {
      // Cancelled or refused: back to what was shown.
      if (err.name !== 'AbortError') this.on.failed(err.message);
      this.on.cancelled();
    });
  }

  // Watches LAB as if picked (also the tests: a folder in the browser's private file system).
  watch(lab: WatchedLab): void {
    this.watched = lab;
    this.picked = null;
    this.on.opened(false);
  }

  // True while the open folder is watched (saving reloads): no Reload button then.
  get watching(): boolean {
    return this.watched !== null;
  }

  // STAGEID's files (and those of the EARLIER stages a labs/ folder holds).
  async sources(stageId: string, earlier: string[]): Promise<Sources> {
    if (this.watched) return this.watched.read(stageId, earlier);
    if (this.picked) return (await this.fresh()).lab(stageId, this.stageIds, earlier);
    throw new Error('pick your lab folder (Code: my lab folder…)');
  }

  // The open folder as a submission's entries (null: none open).
  async submission(current: string): Promise<ZipEntry[] | null> {
    return this.watched ? this.watched.submission(current)
      : this.picked ? (await this.fresh()).submission(current, this.stageIds) : null;
  }

  // True when a watched folder's files of STAGEID changed since they were
  // read. A folder that went away or whose permission was withdrawn is no
  // longer watched (LOST says so); anything else (a file caught mid-save)
  // counts as no change, to be tried again.
  async changed(stageId: string, earlier: string[], lost: () => void): Promise<boolean> {
    if (!this.watched) return false;
    try {
      return await this.watched.changed(stageId, earlier);
    } catch (e) {
      const name = (e as Error).name;
      if (name === 'NotFoundError' || name === 'NotAllowedError' || name === 'SecurityError') {
        this.watched = null;
        lost();
      }
      return false;
    }
  }

  // The picked folder, unless a file of it changed on disk since it was read:
  // then Check and Download stop with one line (never a stale verdict or zip).
  private async fresh(): Promise<PickedFolder> {
    const changed = await this.picked!.changedOnDisk();
    if (changed.length) throw new Error(changedOnDiskMessage(changed));
    return this.picked!;
  }
}
