// The project as the page sees it (dist/catalog.json, written at build time
// by tools/write_catalog.mjs): stage.json files and which files exist where,
// for the menus and for the files the core reads (core/core.ts). Search
// paths and stage rules are the core's own (native C++).

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
  technique?: string;  // the fur technique its pictures show by default
  program: StageProgramJson;
  programs?: Record<string, StageProgramJson>;
  limits: Record<string, number | boolean>;
  features: string[];
  defines?: string[];
  check_views: CheckViewJson[];
  count_checks?: string[];     // fin_count: a number the GPU produced against the CPU's
}

// A stage as the catalog lists it: its stage.json and the shader files its
// solution and lab folders hold.
export interface CatalogStage {
  info: StageJson;
  solutionFiles: string[];
  labFiles: string[];
}

export interface Catalog {
  // False where the server keeps the solutions back (tools/serve.mjs without
  // --with-solutions): the page offers the labs only.
  solutions: boolean;
  // A students' bundle (`raylab web-bundle`): no test API, the work kept in the browser.
  bundle?: boolean;
  stages: CatalogStage[];
  // A bundle's stages that those it releases build on and it does not
  // release: read for builds_on and their folders, not offered in the menu.
  earlier?: CatalogStage[];
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

// The stage and those it builds on, newest first (a bundle's earlier stages included).
export function chain(catalog: Catalog, stage: StageJson): StageJson[] {
  const known = [...catalog.stages, ...(catalog.earlier ?? [])];
  const byId = (id: string) => {
    const s = known.find((x) => x.info.id === id);
    if (!s) throw new Error(`stage ${stage.id} builds on "${id}", which this page does not have`);
    return s.info;
  };
  const out: StageJson[] = [];
  for (let at: StageJson | null = stage; at; at = at.builds_on ? byId(at.builds_on) : null)
    out.push(at);
  return out;
}

// Where a program's files come from: a solution, a lab served from the
// project's labs/, or a lab folder the student opened from disk.
export type Sources =
  | { kind: 'solution' }
  | { kind: 'lab' }
  | { kind: 'disk'; shown: string; files: Map<string, string>; owners?: Map<string, string> };
// (OWNERS: the earlier stage whose folder a file of FILES was read from, for
// those not in the stage's own folder: the core reads it from there, and its
// messages name it there, as natively.)
