// The C++ core in WebAssembly (framework/src/wasm, built by
// web/tools/build_core.sh into dist/core/raylab_core.js): the page reads
// scenes, assembles programs and builds the BVH, the light buffer and the
// eye cells with the very code the native `raylab` runs. The core reads
// files through Emscripten's in-memory file system: this module writes the
// project's files there (fetched from the server, under CORE_ROOT, so that
// native's messages name "assets/scenes/lite.json" and
// "solution/01-raycast/intersect_sphere.glsl" as natively) and a student's
// folder (under STUDENT_ROOT, the core's working folder, so that its files
// are named as the student's folder names them).
import { ROOT, type Catalog } from '../course/catalog.js';

export const CORE_ROOT = '/raylab';
export const STUDENT_ROOT = '/student';

// What the core gives for a ray-tracing stage (framework/src/wasm/bindings.cpp).
export interface CoreSource {
  text: string;
  origin: [string, number][];
}
export interface RayStageInfo {
  stage: string;
  sceneFile: string;
  vertex: CoreSource;
  fragment: CoreSource;
  todos: { file: string; line: number; title: string }[];
  levers: string[];
  spheres: number;
  tori: number;
  triangles: number;
  lights: number;
  textures: string[];
  skyBox: string[];
  camera: { position: [number, number, number]; yaw: number; pitch: number; fovY: number };
  lightBuffer: { size: number; everyCell: number; reach: number };
  eyeCellsSize: number;
}
export interface RayStageHandle {
  error(): string;
  info(): string;
  mapLog(log: string, which: 'vertex' | 'fragment'): string;
  sphereCentres(t: number): Float32Array;
  torusToLocal(t: number): Float32Array;
  bvhNodes(): Float32Array;
  bvhItems(): Int32Array;
  lightCells(): Int32Array;
  lightItems(): Int32Array;
  eyeCells(): Int32Array;
  placeEye(x: number, y: number, z: number): { eye: Float32Array; eyeCellsMoved: boolean };
  delete(): void;
}
interface CoreFs {
  mkdirTree(path: string): void;
  writeFile(path: string, data: string | Uint8Array): void;
  rmdir(path: string): void;
  readdir(path: string): string[];
  isDir(mode: number): boolean;
  stat(path: string): { mode: number };
  unlink(path: string): void;
  chdir(path: string): void;
}
export interface Core {
  FS: CoreFs;
  RayStage: new (request: string) => RayStageHandle;
}

declare function RayLabCore(options: object): Promise<Core>;

let loading: Promise<Core> | null = null;

// The core, loaded once (a classic script: the module is one file with the
// WebAssembly inside).
export function loadCore(): Promise<Core> {
  loading ??= new Promise<void>((resolve, reject) => {
    const script = document.createElement('script');
    script.src = new URL('dist/core/raylab_core.js', document.baseURI).href;
    script.onload = () => resolve();
    script.onerror = () => reject(new Error('dist/core/raylab_core.js does not load (run `npm run build` in web/)'));
    document.head.appendChild(script);
  }).then(() => RayLabCore({ preRun: [(m: { ENV: Record<string, string> }) => { m.ENV.RAYLAB_ROOT = CORE_ROOT; }] }))
    .then((core) => {
      core.FS.mkdirTree(STUDENT_ROOT);
      core.FS.chdir(STUDENT_ROOT);
      return core;
    });
  return loading;
}

const written = new Map<string, Promise<void>>();

function mkdirFor(core: Core, path: string): void {
  core.FS.mkdirTree(path.slice(0, path.lastIndexOf('/')));
}

// Writes each of PATHS (relative to the project root) into the core's file
// system once per page load, fetched from the server.
export async function ensureProjectFiles(core: Core, paths: string[]): Promise<void> {
  await Promise.all(paths.map((rel) => {
    let done = written.get(rel);
    if (!done) {
      done = fetch(`${ROOT}/${rel}`).then(async (r) => {
        if (!r.ok) throw new Error(`${rel}: HTTP ${r.status}`);
        const target = `${CORE_ROOT}/${rel}`;
        mkdirFor(core, target);
        core.FS.writeFile(target, new Uint8Array(await r.arrayBuffer()));
      });
      done.catch(() => written.delete(rel));
      written.set(rel, done);
    }
    return done;
  }));
}

// A file made up in the page (a test's scene): written over whatever was there.
export function writeProjectFile(core: Core, rel: string, text: string): void {
  const target = `${CORE_ROOT}/${rel}`;
  mkdirFor(core, target);
  core.FS.writeFile(target, text);
  written.set(rel, Promise.resolve());
}

function removeTree(core: Core, path: string): void {
  for (const name of core.FS.readdir(path)) {
    if (name === '.' || name === '..') continue;
    const p = `${path}/${name}`;
    if (core.FS.isDir(core.FS.stat(p).mode)) {
      removeTree(core, p);
      core.FS.rmdir(p);
    } else {
      core.FS.unlink(p);
    }
  }
}

// A student's lab, laid out like labs/ (LABROOT/<stage>/<file>), written
// afresh under the core's working folder; returns LABROOT, the folder the
// core is given (relative, so that messages name the student's own folders).
export function writeStudentLab(core: Core, labRoot: string, folders: Map<string, Map<string, string>>): string {
  removeTree(core, STUDENT_ROOT);
  for (const [stageId, files] of folders)
    for (const [name, text] of files) {
      const target = `${STUDENT_ROOT}/${labRoot}/${stageId}/${name}`;
      mkdirFor(core, target);
      core.FS.writeFile(target, text);
    }
  return labRoot;
}

// Every file the core may read for the ray-tracing stages: the stage.json
// files, every shader folder, the scenes and their pictures (a scene names its
// pictures; the reader checks that they exist).
export function rayTracingFiles(catalog: Catalog): string[] {
  const files: string[] = [];
  for (const s of catalog.stages) {
    files.push(`solution/${s.info.id}/stage.json`);
    files.push(...s.solutionFiles.map((n) => `solution/${s.info.id}/${n}`));
    files.push(...s.labFiles.map((n) => `labs/${s.info.id}/${n}`));
  }
  files.push(...catalog.framework.map((n) => `framework/shaders/${n}`));
  files.push(...catalog.web.map((n) => `web/shaders/${n}`));
  for (const [folder, names] of Object.entries(catalog.variants))
    files.push(...names.map((n) => `framework/shaders/variants/${folder}/${n}`));
  files.push(...catalog.scenes.filter((n) => !n.startsWith('fur/')).map((n) => `assets/scenes/${n}`));
  files.push(...catalog.assets.map((n) => `assets/${n}`));
  return files;
}

// A core path (/raylab/assets/scenes/../textures/earth.png) as a URL the page fetches.
export function coreFileUrl(path: string): string {
  return path.startsWith(`${CORE_ROOT}/`) ? `${ROOT}/${path.slice(CORE_ROOT.length + 1)}` : path;
}
