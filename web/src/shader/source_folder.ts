// A folder of shader files the assembler searches: served over HTTP (the
// solution, the framework, a lab in the project) or read from the student's
// disk. Listing the names up front means the assembler never asks a server
// for a file that is not there (a 404 is a console error in a browser).

export interface SourceFolder {
  shown: string;                  // display path, e.g. "labs/03-shadows"
  has(name: string): boolean;
  read(name: string): Promise<string>;
}

// Files at BASEURL/<name> for the names listed in the catalog.
export function servedFolder(shown: string, baseUrl: string, names: string[]): SourceFolder {
  const known = new Set(names);
  const cache = new Map<string, Promise<string>>();
  return {
    shown,
    has: (name) => known.has(name),
    read(name) {
      let text = cache.get(name);
      if (!text) {
        text = fetch(`${baseUrl}/${name}`).then((r) => {
          if (!r.ok) throw new Error(`${shown}/${name}: HTTP ${r.status}`);
          return r.text();
        });
        cache.set(name, text);
      }
      return text;
    },
  };
}

// Files already in memory (a folder opened from disk, or given by a test).
export function memoryFolder(shown: string, files: Map<string, string>): SourceFolder {
  return {
    shown,
    has: (name) => files.has(name),
    read: async (name) => files.get(name) as string,
  };
}
