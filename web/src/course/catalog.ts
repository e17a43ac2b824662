// The project as the page sees it (dist/catalog.json, written at build time
// by tools/write_catalog.mjs): stage.json files and which shader files exist
// where. Stage order and search paths follow the native rules
// (framework/src/course/stage_catalog.cpp, stage_sources.cpp).
import { memoryFolder, servedFolder, type SourceFolder } from '../shader/source_folder.js';

export interface CheckViewJson {
  name: string;
  why?: string;
  camera?: { position: [number, number, number]; yaw: number; pitch: number };
  time?: number;
  scene?: string;
  shadows?: boolean;
  max_depth?: number;
  glow?: boolean;
  normal_maps?: boolean;
  color_mode?: string;
  shells?: number;
  fins?: boolean;
  technique?: string;
}

export interface StageProgramJson {
  vertex: string;
  geometry?: string;
  fragment: string;
}

export interface StageJson {
  id: string;
  title: string;
  track: string;
  builds_on: string | null;
  scene: string;
  program: StageProgramJson;
  programs?: Record<string, StageProgramJson>;
  limits: Record<string, number | boolean>;
  features: string[];
  defines?: string[];
  check_views: CheckViewJson[];
}

export interface Catalog {
  stages: { info: StageJson; solutionFiles: string[]; labFiles: string[] }[];
  framework: string[];
  web: string[];
  variants: Record<string, string[]>;
  scenes: string[];
  assets: string[];  // under assets/: textures/*.png, meshes/*.obj
}

export async function loadCatalog(url = 'dist/catalog.json'): Promise<Catalog> {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: HTTP ${r.status} (run \`npm run build\` in web/)`);
  return r.json();
}

// The project root as the page's URL sees it (the page is /web/index.html).
export const ROOT = new URL('../', document.baseURI).pathname.replace(/\/$/, '');

export function stageById(catalog: Catalog, id: string): StageJson {
  const s = catalog.stages.find((x) => x.info.id === id || x.info.id.split('-')[0] === id);
  if (!s) throw new Error(`no stage "${id}" (stages: ${catalog.stages.map((x) => x.info.id).join(', ')})`);
  return s.info;
}

// The stage and those it builds on, newest first.
export function chain(catalog: Catalog, stage: StageJson): StageJson[] {
  const out: StageJson[] = [];
  for (let at: StageJson | null = stage; at; at = at.builds_on ? stageById(catalog, at.builds_on) : null)
    out.push(at);
  return out;
}

// MAX_SPHERES... from the limits (at least 1: GLSL has no empty arrays), then "defines".
export function stageDefines(stage: StageJson): string[] {
  const size = (name: string, key: string) => `${name} ${Math.max(1, Number(stage.limits[key] ?? 0))}`;
  return [
    size('MAX_SPHERES', 'spheres'), size('MAX_MATERIALS', 'materials'), size('MAX_LIGHTS', 'lights'),
    size('MAX_PLANES', 'planes'), size('MAX_DISCS', 'discs'), size('MAX_TRIANGLES', 'triangles'),
    size('MAX_TORI', 'tori'), ...(stage.defines ?? []),
  ];
}

// Where a program's files come from: a solution, a lab served from the
// project's labs/, or a lab folder the student opened from disk.
export type Sources =
  | { kind: 'solution' }
  | { kind: 'lab' }
  | { kind: 'disk'; shown: string; files: Map<string, string> };

// Which define switches which variant folder on (native: kVariants).
const VARIANTS: { define: string; whenDefined: boolean; folder: string }[] = [
  { define: 'RAYLAB_NAIVE_NUMERICS', whenDefined: true, folder: 'naive-numerics' },
  { define: 'TORUS_SOLVER_CLOSED_FORM', whenDefined: true, folder: 'torus-closed-form' },
  { define: 'RAYLAB_BVH', whenDefined: false, folder: 'linear-search' },
  { define: 'RAYLAB_WEIGHT_CUT', whenDefined: true, folder: 'weight-cut' },
  { define: 'RAYLAB_OLD_PATH', whenDefined: true, folder: 'old-path' },
  { define: 'RAYLAB_MESHES', whenDefined: true, folder: 'meshes' },
];

// The search path: the web's own replacements (the BVH over 2D textures)
// first, then the stage folders with their variant folders in front, then
// the framework (native: searchWithVariants, with web/shaders put first).
export function searchPath(catalog: Catalog, stage: StageJson, sources: Sources, defines: string[]): SourceFolder[] {
  const defined = (name: string) => defines.some((d) => d === name || d.startsWith(name + ' '));
  const on = VARIANTS.filter((v) => defined(v.define) === v.whenDefined).map((v) => v.folder);
  const variantFolders = (id: string) =>
    on.filter((f) => catalog.variants[`${f}/${id}`]).map((f) =>
      servedFolder(`framework/shaders/variants/${f}/${id}`, `${ROOT}/framework/shaders/variants/${f}/${id}`, catalog.variants[`${f}/${id}`]));
  const ids = chain(catalog, stage).map((s) => s.id);
  const search: SourceFolder[] = [servedFolder('web/shaders', `${ROOT}/web/shaders`, catalog.web)];
  if (sources.kind === 'solution') {
    for (const id of ids) {
      search.push(...variantFolders(id));
      const entry = catalog.stages.find((s) => s.info.id === id)!;
      search.push(servedFolder(`solution/${id}`, `${ROOT}/solution/${id}`, entry.solutionFiles));
    }
  } else {
    for (const id of ids) search.push(...variantFolders(id));
    if (sources.kind === 'lab') {
      const entry = catalog.stages.find((s) => s.info.id === stage.id)!;
      search.push(servedFolder(`labs/${stage.id}`, `${ROOT}/labs/${stage.id}`, entry.labFiles));
    } else {
      search.push(memoryFolder(sources.shown, sources.files));
    }
  }
  search.push(servedFolder('framework/shaders', `${ROOT}/framework/shaders`, catalog.framework));
  return search;
}
