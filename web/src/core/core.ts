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
import { ROOT, type Catalog, type Sources } from '../course/catalog.js';
import type { EmulationLayout } from '../gl/emulated_geometry_pass.js';

export const CORE_ROOT = '/raylab';
export const STUDENT_ROOT = '/student';

// An assembled shader: its text and where each line came from (file, line).
export interface CoreSource {
  text: string;
  origin: [string, number][];
}
// A TODO block of a lab that still holds its stub (native: OpenTodo).
export interface OpenTodo {
  file: string;
  line: number;
  title: string;
}
// What the core gives for a ray-tracing stage (framework/src/wasm/bindings.cpp).
export interface RayStageInfo {
  stage: string;
  sceneFile: string;
  vertex: CoreSource;
  fragment: CoreSource;
  todos: OpenTodo[];
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
  sphereCentres(t: number): Float32Array;
  torusToLocal(t: number): Float32Array;
  bvhNodes(): Float32Array;
  bvhItems(): Int32Array;
  lightCells(): Int32Array;
  lightItems(): Int32Array;
  eyeCells(): Int32Array;
  meshCorners(): Float32Array;
  meshMaterials(): Int32Array;
  placeEye(x: number, y: number, z: number): { eye: Float32Array; eyeCellsMoved: boolean };
  // A debug view's picture of the floats its program drew (rows bottom-up).
  viewPicture(floats: Float32Array, width: number, height: number): { rgba?: Uint8Array; mapping?: string; error?: string };
  // The trace build: a pixel's path in raylab trace's words.
  traceReport(summary: Float32Array, records: Float32Array, x: number, y: number, width: number, height: number): { report?: string; error?: string };
  delete(): void;
}
// What the core gives for a fur stage.
export interface FurStageInfo {
  stage: string;
  sceneFile: string;
  // fins and strands: with their geometry shader's emulation (gl/emulated_geometry_pass.ts).
  programs: Record<'shells' | 'fins' | 'strands', {
    vertex: CoreSource; fragment: CoreSource;
    geometry?: CoreSource; geometryDraw?: CoreSource; captureFragment?: CoreSource; emulation?: EmulationLayout;
  } | undefined>;
  todos: OpenTodo[];
  background: [number, number, number];
  camera: RayStageInfo['camera'];
  lightDirection: [number, number, number];
  lightColor: [number, number, number];
  ambient: [number, number, number];
  fur: {
    length: number; shells: number; patternScale: number; shadowIntensity: number;
    gravity: number; strandDensity: number; strandSegments: number;
  };
  textures: [string, string, string];  // colour map, pattern, fin map
  bounds: { centre: [number, number, number]; radius: number };
  strands: { perTriangle: number; vertices: number } | null;
  mesh: { name: string; vertices: number; triangles: number };
  shapes: string[];  // key M's meshes (native: shapeNames())
  todoMarks?: boolean;  // the programs mark TODO pixels (a check's target)
}
export interface FurStageHandle {
  error(): string;
  info(): string;
  positions(): Float32Array;
  normals(): Float32Array;
  uvs(): Float32Array;
  indices(): Uint32Array;
  adjacency(): Uint32Array;
  modelMatrix(t: number): Float32Array;
  finCount(emitted: number, view: string): string;  // {passed, detail} or {error}
  showMesh(furMesh: number): void;  // key M: 0 the scene's mesh, i shapes[i - 1]
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
// The checks (framework/src/wasm/check_bindings.cpp).
export interface FunctionCheckInfo {
  name: string;
  cases: number;
  perCase: boolean;                      // some case sets uniforms: one pixel at a time
  uniforms: [string, number][][];        // per case
  vertex?: CoreSource;
  fragment?: CoreSource;
  error?: string;                        // the harness could not be assembled
}
export interface FunctionChecksHandle {
  error(): string;
  list(): string;                        // FunctionCheckInfo[] as JSON
  texels(name: string): Float32Array;    // uCases: RGBA floats, cases wide, 4 rows
  delete(): void;
}
export interface CheckSessionHandle {
  error(): string;
  addFunction(name: string, results: Float32Array): string;
  addFunctionNotBuilt(name: string, message: string): string;
  addView(view: string, mine: Uint8Array, expected: Uint8Array, width: number, height: number, nonFinite: number, todoPixels: number): string;
  addCount(name: string, resultsJson: string): string;
  addCountNotRun(name: string, why: string): void;
  addUntouched(viewName: string, rgba: Uint8Array, width: number, height: number): string;
  noScore(): void;
  passed(): number;
  failed(): number;
  report(): string;
  delete(): void;
}
export interface Core {
  FS: CoreFs;
  RayStage: new (request: string) => RayStageHandle;
  FurStage: new (request: string) => FurStageHandle;
  FunctionChecks: new (request: string) => FunctionChecksHandle;
  CheckSession: new (stage: string, header: string, todosJson: string) => CheckSessionHandle;
  // A check target's read-back as natively converted (rows bottom-up in, top-down out).
  viewImage(floats: Float32Array, marks: Uint8Array, width: number, height: number):
    { rgba: Uint8Array; nonFinite: number; todoPixels: number; error?: string };
  heatMap(mine: Uint8Array, expected: Uint8Array, width: number, height: number): Uint8Array;
  // A driver's log with its line references turned into file:line (native's mapCompilerLog).
  mapCompilerLog(log: string, sourceJson: string): string;
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

// Every file the core may read: the stage.json files, every shader folder,
// the scenes, their pictures and meshes (a scene names them; the readers
// check that they exist).
export function projectFiles(catalog: Catalog): string[] {
  const files: string[] = [];
  for (const s of [...catalog.stages, ...(catalog.earlier ?? [])]) {
    files.push(`solution/${s.info.id}/stage.json`);
    files.push(...s.solutionFiles.map((n) => `solution/${s.info.id}/${n}`));
    files.push(...s.labFiles.map((n) => `labs/${s.info.id}/${n}`));
  }
  files.push(...catalog.framework.map((n) => `framework/shaders/${n}`));
  files.push(...catalog.web.map((n) => `web/shaders/${n}`));
  // The function checks' expected values (the core has no reference code).
  files.push('web/function_tables.json');
  for (const [folder, names] of Object.entries(catalog.variants))
    files.push(...names.map((n) => `framework/shaders/variants/${folder}/${n}`));
  files.push(...catalog.scenes.map((n) => `assets/scenes/${n}`));
  files.push(...catalog.assets.map((n) => `assets/${n}`));
  return files;
}

// The lab a request names, as the core takes it: '' for the solution, the
// project's labs/, or a student's folder written under the core's working
// folder (a labs/-like folder shown as ROOT/<stage>, or one stage's folder,
// then laid out as <stage>/ under .).
export function labForCore(core: Core, stageId: string, sources: Sources): string {
  if (sources.kind === 'lab') return `${CORE_ROOT}/labs`;
  if (sources.kind !== 'disk') return '';
  const suffix = `/${stageId}`;
  const root = sources.shown.endsWith(suffix) ? sources.shown.slice(0, -suffix.length) : '.';
  const folders = new Map<string, Map<string, string>>([[stageId, new Map()]]);
  for (const [name, text] of sources.files) {
    const owner = sources.owners?.get(name) ?? stageId;
    if (!folders.has(owner)) folders.set(owner, new Map());
    folders.get(owner)!.set(name, text);
  }
  return writeStudentLab(core, root, folders);
}

// A core path (/raylab/assets/scenes/../textures/earth.png) as a URL the page fetches.
export function coreFileUrl(path: string): string {
  return path.startsWith(`${CORE_ROOT}/`) ? `${ROOT}/${path.slice(CORE_ROOT.length + 1)}` : path;
}
