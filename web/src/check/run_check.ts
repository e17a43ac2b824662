// `raylab check` in the page (native: framework/src/cli/cmd_check.cpp): the
// stage's function checks, then each check view drawn at 160x120 into a
// float target and compared with the shipped reference picture. The core
// judges every result with native's tables, thresholds and hints
// and words the report as native does; the page only draws.
import { frameOfView, sceneOfView } from '../app/frame.js';
import { type Catalog, type CheckViewJson, type Sources, type StageJson } from '../course/catalog.js';
import { ensureProjectFiles, labForCore, loadCore, projectFiles } from '../core/core.js';
import { FurRenderer } from '../fur/fur_renderer.js';
import { loadStage, type LoadedStage } from '../tracks/track_registry.js';
import { CheckTarget } from './check_target.js';
import { runFunctionChecks } from './function_checks.js';
import { referencePicture } from './reference_pictures.js';

export const CHECK_WIDTH = 160, CHECK_HEIGHT = 120;

export interface ViewVerdict {
  name: string;
  passed: boolean;
  description: string;
  hint: string;
  mine: Uint8Array;      // RGBA, top-down, CHECK_WIDTH x CHECK_HEIGHT
  expected: Uint8Array;
  heatMap: Uint8Array;   // native's, black = equal
}

export interface CheckRun {
  report: string;        // as `raylab check` prints it
  passed: number;
  failed: number;
  failedChecks: string[];  // the names of the failing checks, for the tests
  views: ViewVerdict[];
}

// Where the code comes from, in the words of the report's first line
// (native: "lab labs/", "solution").
export function sourceLabel(sources: Sources): string {
  if (sources.kind === 'solution') return 'solution';
  if (sources.kind === 'lab') return 'lab labs/';
  return `lab ${sources.shown.replace(/\/[^/]*$/, '')}/`;
}

// "WebGL 2 (ANGLE (...llvmpipe...))": what drew the pictures.
export function backendName(gl: WebGL2RenderingContext): string {
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return `WebGL 2 (${gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)})`;
}

// A count check from the check views' cameras (native: runCountCheck): the
// number the student's shaders produced against the same number worked out
// on the CPU natively (the core's count tables). Null where the page has no
// such count.
async function countResults(name: string, stage: StageJson, rendererFor: (scene: string) => Promise<LoadedStage>) {
  if (name !== 'fin_count') return null;
  const results = [];
  for (const view of stage.check_views) {
    const loaded = await rendererFor(sceneOfView(stage, view));
    const r = loaded.renderer;
    const frame = frameOfView(loaded.camera, loaded.fovYDeg, view, stage);
    // As natively: fins drawn, with shells (not the fur shader).
    const fins = r instanceof FurRenderer && frame.settings.fins && frame.settings.furTechnique === 0
      ? r.countFins(frame.camera, frame.time, frame.settings, CHECK_WIDTH, CHECK_HEIGHT) : null;
    results.push(fins === null || !(r instanceof FurRenderer) ? { view: view.name, applies: false }
      : { view: view.name, applies: true, ...r.finCountVerdict(fins, view.name) });
  }
  return results;
}

// The lab as handed out's pictures of each stage's check views ("stage/view"),
// drawn by the first Check that needs them: the files they come from
// (labs/ of the page's course) stay the same while the page is open.
const handedOutPictures = new Map<string, Uint8Array>();

// LABEL: where the code comes from, as the report's first line names it.
// SCORE: end the report with the grader's score (when a view fails, the lab
// as handed out is drawn from the check views for it, as natively).
export async function runCheck(gl: WebGL2RenderingContext, catalog: Catalog, stage: StageJson, sources: Sources,
  label: string, backend: string, score = true): Promise<CheckRun> {
  const core = await loadCore();
  await ensureProjectFiles(core, projectFiles(catalog));
  // One renderer per scene the views use, as natively; the first one built
  // lists the lab's open TODOs (a compile error stops the check there).
  const renderers = new Map<string, LoadedStage>();
  const rendererFor = async (scene: string) => {
    let r = renderers.get(scene);
    if (!r) {
      // With the BVH in every scene, as native's check (its generic program
      // walks the tree even in a scene of ten spheres, so a wrong walk fails there too).
      r = await loadStage(gl, catalog, stage, sources, scene, { bvh: true, todoMarks: true });
      renderers.set(scene, r);
    }
    return r;
  };
  try {
    const first = await rendererFor(sceneOfView(stage, stage.check_views[0]));
    const header = `raylab check: stage ${stage.id}, ${label} against the reference pictures ` +
      `(tests/reference/${stage.id}), ${CHECK_WIDTH}x${CHECK_HEIGHT}, ${backend}`;
    const session = new core.CheckSession(stage.id, header, JSON.stringify(first.renderer.todos));
    try {
      if (session.error()) throw new Error(session.error());
      if (!score) session.noScore();
      const failedChecks: string[] = [];
      const lab = labForCore(core, stage.id, sources);
      await runFunctionChecks(gl, core, session, stage.id, lab);
      const views: ViewVerdict[] = [];
      const target = new CheckTarget(gl, CHECK_WIDTH, CHECK_HEIGHT, true);
      // A frame of VIEW drawn by LOADED into the check target, read as natively.
      const draw = (loaded: LoadedStage, view: CheckViewJson) => {
        const frame = frameOfView(loaded.camera, loaded.fovYDeg, view, stage);
        target.bind();
        loaded.renderer.render(frame.camera, frame.time, frame.settings, CHECK_WIDTH, CHECK_HEIGHT);
        target.unbind();
        const read = core.viewImage(target.readFloats(), target.readMarks(), CHECK_WIDTH, CHECK_HEIGHT);
        if (read.error) throw new Error(read.error);
        return read;
      };
      try {
        for (const view of stage.check_views) {
          const read = draw(await rendererFor(sceneOfView(stage, view)), view);
          const expected = await referencePicture(stage.id, view.name);
          const verdict = JSON.parse(session.addView(view.name, read.rgba, expected.rgba, expected.width, expected.height,
            read.nonFinite, read.todoPixels)) as { passed: boolean; description: string; hint: string; error?: string };
          if (verdict.error) throw new Error(verdict.error);
          views.push({
            name: view.name, passed: verdict.passed, description: verdict.description, hint: verdict.hint,
            mine: read.rgba, expected: expected.rgba, heatMap: core.heatMap(read.rgba, expected.rgba, CHECK_WIDTH, CHECK_HEIGHT),
          });
        }
        // The score's rule on views the lab as handed out draws (native:
        // cmd_check.cpp): drawn only when a view fails, once a page session
        // (the lab as handed out does not change in it).
        if (score && views.some((v) => !v.passed)) {
          const handedOut = new Map<string, LoadedStage>();
          try {
            for (const view of stage.check_views) {
              const key = `${stage.id}/${view.name}`;
              let rgba = handedOutPictures.get(key);
              if (!rgba) {
                const scene = sceneOfView(stage, view);
                let r = handedOut.get(scene);
                if (!r) {
                  r = await loadStage(gl, catalog, stage, { kind: 'lab' }, scene, { bvh: true, todoMarks: true });
                  handedOut.set(scene, r);
                }
                rgba = draw(r, view).rgba;
                handedOutPictures.set(key, rgba);
              }
              const added = JSON.parse(session.addUntouched(view.name, rgba, CHECK_WIDTH, CHECK_HEIGHT)) as { error?: string };
              if (added.error) throw new Error(added.error);
            }
          } finally {
            for (const r of handedOut.values()) r.renderer.dispose();
          }
        }
      } finally {
        target.dispose();
      }
      for (const name of stage.count_checks ?? []) {
        const results = await countResults(name, stage, rendererFor);
        if (!results) {
          session.addCountNotRun(name, 'not available in the page');
          continue;
        }
        const added = JSON.parse(session.addCount(name, JSON.stringify(results))) as { error?: string };
        if (added.error) throw new Error(added.error);
      }
      const report = session.report();
      for (const m of report.matchAll(/^ {2}FAIL (\S+)/gm)) failedChecks.push(m[1]!);
      return { report, passed: session.passed(), failed: session.failed(), failedChecks, views };
    } finally {
      session.delete();
    }
  } finally {
    for (const r of renderers.values()) r.renderer.dispose();
  }
}
