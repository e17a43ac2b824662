// Where a student's work lives when they edit in the page: the browser's
// IndexedDB (every engine the page supports has it, Safari included, and it
// outlives closing the tab, a reload or a crash). Two object stores: the
// files, keyed "<stage>/<file>" (a labs/ folder's layout), and each stage's
// last Check verdict. One database per course bundle, named after the page's
// URL folder: a course that republishes its bundle at the same address each
// week keeps its students' work, and two courses on one host keep theirs
// apart.
const FILES = 'files';
const VERDICTS = 'verdicts';

// The page's folder, e.g. "https://host/course/raylab/web/".
export function bundleAddress(): string {
  return `${location.origin}${location.pathname.replace(/[^/]*$/, '')}`;
}

function request<T>(r: IDBRequest<T>): Promise<T> {
  return new Promise((resolve, reject) => {
    r.onsuccess = () => resolve(r.result);
    r.onerror = () => reject(r.error ?? new Error('IndexedDB request failed'));
  });
}

export class WorkStore {
  private constructor(private db: IDBDatabase) {}

  static open(name = `raylab-work ${bundleAddress()}`): Promise<WorkStore> {
    return new Promise((resolve, reject) => {
      if (typeof indexedDB === 'undefined') return reject(new Error('this browser keeps no data for pages (no IndexedDB)'));
      const r = indexedDB.open(name, 1);
      r.onupgradeneeded = () => {
        r.result.createObjectStore(FILES);
        r.result.createObjectStore(VERDICTS);
      };
      r.onsuccess = () => resolve(new WorkStore(r.result));
      r.onerror = () => reject(new Error(`the browser refused to keep the page's work (IndexedDB: ${r.error?.message ?? 'no reason given'}); ` +
        'Code: labs/ (as handed out) shows the labs, but keeps no edit'));
      r.onblocked = () => reject(new Error('another tab of this page holds its storage open: close it and reload'));
    });
  }

  // Every entry of STORE as key -> value.
  private async all<T>(store: string): Promise<Map<string, T>> {
    const tx = this.db.transaction(store, 'readonly').objectStore(store);
    const [keys, values] = await Promise.all([request(tx.getAllKeys()), request(tx.getAll())]);
    return new Map(keys.map((k, i) => [String(k), values[i] as T]));
  }

  // ENTRIES (key, value) in one transaction: done when it committed.
  private put(store: string, entries: [string, unknown][]): Promise<void> {
    const tx = this.db.transaction(store, 'readwrite');
    for (const [key, value] of entries) tx.objectStore(store).put(value, key);
    return new Promise((resolve, reject) => {
      tx.oncomplete = () => resolve();
      tx.onerror = tx.onabort = () => reject(tx.error ?? new Error('IndexedDB: the write was aborted'));
    });
  }

  files(): Promise<Map<string, string>> { return this.all<string>(FILES); }
  putFiles(files: [string, string][]): Promise<void> { return this.put(FILES, files); }
  verdicts(): Promise<Map<string, boolean>> { return this.all<boolean>(VERDICTS); }
  putVerdict(stageId: string, passed: boolean): Promise<void> { return this.put(VERDICTS, [[stageId, passed]]); }
}
