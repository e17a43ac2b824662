// window.raylab: what the browser tests and the frame-time benchmark call
// (web/tests/browser/). Each call builds the stage's renderer afresh, draws
// into the page's canvas and reports what a student would see: the picture,
// the compile error with file:line, the open TODOs.
import { Camera, flyThroughPose } from './camera.js';
import { frameOfView, sceneOfView } from './frame.js';
import { WatchedLab } from './lab_folder.js';
import type { Page } from './page.js';
import { ROOT, type Catalog, type Sources, stageById } from '../course/catalog.js';
import { loadCore } from '../core/core.js';
import { FUR_TECHNIQUES } from '../raytrace/render_settings.js';
import { openRayStage } from '../raytrace/stage_renderer.js';
import { loadStage } from '../tracks/track_registry.js';
import { backendName, runCheck, sourceLabel } from '../check/run_check.js';
import type { OpenTodo } from '../core/core.js';
import { DebugViewPainter } from './debug_view.js';
import { tracePixel } from './pixel_trace.js';

export interface ViewRequest {
  stage: string;
  view?: string;               // a check view of the stage; none: the scene's camera
  scene?: string;              // a file under assets/scenes/ instead of the view's
  sceneText?: string;          // that file's text, made up by the test (no images in it)
  source?: 'solution' | 'lab';
  labFiles?: Record<string, string>;  // a lab "opened from disk": name -> text
  width: number;
  height: number;
  bvh?: boolean;               // stage 08: walk the BVH; default: where it repays itself
  demoLevers?: boolean;        // the solution with the demo's levers (raylab demo's program)
  debugView?: string;          // depth, normal, id: the ray tracer's debug view (app/debug_view.ts)
}

export interface ViewResult {
  ok: boolean;
  png?: string;  // data URL
  error?: string;
  todos: OpenTodo[];
  notes: string[];  // a debug view's mapping
}

async function makeRenderer(gl: WebGL2RenderingContext, catalog: Catalog, req: ViewRequest) {
  const stage = stageById(catalog, req.stage);
  const view = req.view ? stage.check_views.find((v) => v.name === req.view) : undefined;
  if (req.view && !view) throw new Error(`stage ${stage.id} has no check view "${req.view}"`);
  const sceneName = req.scene ?? sceneOfView(stage, view);
  const sources: Sources = req.labFiles
    ? { kind: 'disk', shown: `my-lab/${stage.id}`, files: new Map(Object.entries(req.labFiles)) }
    : { kind: req.source ?? 'solution' };
  const loaded = await loadStage(gl, catalog, stage, sources, sceneName, { bvh: req.bvh, sceneText: req.sceneText, demoLevers: req.demoLevers, view: req.debugView });
  return { renderer: loaded.renderer, frame: frameOfView(loaded.camera, loaded.fovYDeg, view, stage) };
}

export function installTestApi(gl: WebGL2RenderingContext, canvas: HTMLCanvasElement, catalog: Catalog, page: Page): void {
  const api = {
    catalog,
    async renderView(req: ViewRequest): Promise<ViewResult> {
      canvas.width = req.width;
      canvas.height = req.height;
      try {
        const { renderer, frame } = await makeRenderer(gl, catalog, req);
        try {
          if (req.debugView && req.debugView !== 'color') {
            const painter = new DebugViewPainter(gl);
            try {
              const mapping = painter.draw(renderer, frame.camera, frame.time, frame.settings, req.width, req.height);
              return { ok: true, png: canvas.toDataURL('image/png'), todos: renderer.todos, notes: [mapping] };
            } finally {
              painter.dispose();
            }
          }
          renderer.render(frame.camera, frame.time, frame.settings, req.width, req.height);
          return { ok: true, png: canvas.toDataURL('image/png'), todos: renderer.todos, notes: [] };
        } finally {
          renderer.dispose();
        }
      } catch (e) {
        const error = (e as Error).message;
        page.showError(error);  // what the page shows a student
        return { ok: false, error, todos: [], notes: [] };
      }
    },
    // One pixel's path from the stage's own shader (app/pixel_trace.ts),
    // from the scene's camera: the report, or {error}.
    async tracePixel(req: { stage: string; source?: 'solution' | 'lab'; labFiles?: Record<string, string>; width: number; height: number; x: number; y: number }) {
      try {
        const stage = stageById(catalog, req.stage);
        const sources: Sources = req.labFiles
          ? { kind: 'disk', shown: `my-lab/${stage.id}`, files: new Map(Object.entries(req.labFiles)) }
          : { kind: req.source ?? 'solution' };
        const { renderer, frame } = await makeRenderer(gl, catalog, { stage: req.stage, source: req.source, labFiles: req.labFiles, width: req.width, height: req.height });
        renderer.dispose();
        const report = await tracePixel(gl, catalog, {
          stage, sources, sceneName: stage.scene, camera: frame.camera, time: frame.time, settings: frame.settings,
          width: req.width, height: req.height, x: req.x, y: req.y,
        });
        return { ok: true, report };
      } catch (e) {
        return { ok: false, error: (e as Error).message };
      }
    },
    // A lab folder watched as the page watches one, in the browser's private
    // file system (no folder picker needed): FILES written to labs/<stage>/,
    // read, then EDIT (name -> text) saved. Says what the watcher saw.
    async watchFolder(req: { stage: string; files: Record<string, string>; edit: Record<string, string> }) {
      const root = await navigator.storage.getDirectory();
      await root.removeEntry('labs', { recursive: true }).catch(() => undefined);
      const labs = await root.getDirectoryHandle('labs', { create: true });
      const dir = await labs.getDirectoryHandle(req.stage, { create: true });
      const write = async (name: string, text: string) => {
        const w = await (await dir.getFileHandle(name, { create: true })).createWritable();
        await w.write(text);
        await w.close();
      };
      for (const [name, text] of Object.entries(req.files)) await write(name, text);
      const ids = catalog.stages.map((x) => x.info.id);
      const lab = new WatchedLab(labs, ids);
      const first = await lab.read(req.stage);
      const changedBefore = await lab.changed(req.stage);
      await new Promise((r) => setTimeout(r, 20));  // a later modification time
      for (const [name, text] of Object.entries(req.edit)) await write(name, text);
      const changedAfter = await lab.changed(req.stage);
      const second = await lab.read(req.stage);
      const other = ids.find((id) => id !== req.stage)!;
      const wrongStage = await lab.read(other).then(() => '', (e: Error) => e.message);
      const text = (src: typeof first, name: string) => (src.kind === 'disk' ? src.files.get(name) ?? '' : '');
      const edited = Object.keys(req.edit)[0]!;
      return {
        shown: first.kind === 'disk' ? first.shown : '',
        changedBefore, changedAfter,
        editSeen: text(second, edited) === req.edit[edited] && text(first, edited) !== req.edit[edited],
        wrongStage,
      };
    },
    // FILES (path below labs/ -> text) written to labs/ in the browser's
    // private file system, which the page then watches as if picked.
    async openFolder(req: { files: Record<string, string> }) {
      const root = await navigator.storage.getDirectory();
      await root.removeEntry('labs', { recursive: true }).catch(() => undefined);
      const labs = await root.getDirectoryHandle('labs', { create: true });
      for (const [path, text] of Object.entries(req.files)) {
        const parts = path.split('/');
        let dir = labs;
        for (const p of parts.slice(0, -1)) dir = await dir.getDirectoryHandle(p, { create: true });
        const w = await (await dir.getFileHandle(parts[parts.length - 1]!, { create: true })).createWritable();
        await w.write(text);
        await w.close();
      }
      page.watchForTest(new WatchedLab(labs, catalog.stages.map((x) => x.info.id)));
    },
    // `raylab check` in the page for a stage's solution, its lab as handed
    // out, or lab files "opened from disk" (LABFILES: name -> text). SCORE
    // false: no score line (nor the handed-out lab's pictures it needs), for
    // tests that compare verdicts only.
    async check(req: { stage: string; source?: 'solution' | 'lab'; labFiles?: Record<string, string>; score?: boolean }) {
      const stage = stageById(catalog, req.stage);
      const sources: Sources = req.labFiles
        ? { kind: 'disk', shown: `my-lab/${stage.id}`, files: new Map(Object.entries(req.labFiles)) }
        : { kind: req.source ?? 'solution' };
      try {
        const run = await runCheck(gl, catalog, stage, sources, sourceLabel(sources), backendName(gl), req.score ?? true);
        return { ok: true, report: run.report, passed: run.passed, failed: run.failed, failedChecks: run.failedChecks };
      } catch (e) {
        return { ok: false, error: (e as Error).message };
      }
    },
    // The fragment program as `raylab shader --es --origins [--demo]` prints it.
    async assemble(req: { stage: string; scene: string; demoLevers?: boolean }): Promise<string> {
      const stage = stageById(catalog, req.stage);
      const { handle, info } = await openRayStage(gl, await loadCore(), catalog, {
        stage, sources: { kind: 'solution' }, sceneName: req.scene, demoLevers: req.demoLevers,
      });
      handle.delete();
      const lines = info.fragment.text.split('\n');
      return info.fragment.origin.map(([file, line], i) => `${file}:${line}\t${lines[i]}`).join('\n') + '\n';
    },
    // Drives the page's own controls as a student does (the page started
    // without ?test): a stage from the menu, or a demo button; says how long
    // it took from the choice to the new stage's first frame, and what the
    // page shows then.
    async switchTo(req: { stage?: string; demo?: 'lite' | 'pro' | 'fur'; timeoutMs?: number }) {
      const t0 = performance.now();
      if (req.demo) {
        document.getElementById(`demo-${req.demo}`)!.click();
      } else {
        const sel = document.getElementById('stage') as HTMLSelectElement;
        sel.value = stageById(catalog, req.stage!).id;
        sel.dispatchEvent(new Event('change'));
      }
      // The old stage stops drawing at once (the page is building now): the
      // next frame drawn is the new stage's.
      const overlayWhileBuilding = document.getElementById('overlay')!.textContent ?? '';
      const dimmed = canvas.classList.contains('building');
      const at = await Promise.race([
        page.firstFrame(),
        new Promise<number>((r) => setTimeout(() => r(Number.NaN), req.timeoutMs ?? 120_000)),
      ]);
      return {
        ms: at - t0,
        overlayWhileBuilding, dimmed,
        overlay: document.getElementById('overlay')!.textContent ?? '',
        message: document.getElementById('messages')!.textContent ?? '',
      };
    },
    // Median wall time of FRAMES frames of the demo's fly-through, each waited for by reading one pixel
    // back (the browser's equivalent of glFinish), after one warm-up frame: the frames native's
    // `raylab demo --frames FRAMES` times.
    async timeFrames(req: ViewRequest & { frames: number; technique?: string }): Promise<{ medianMs: number; ms: number[] }> {
      canvas.width = req.width;
      canvas.height = req.height;
      const { renderer, frame } = await makeRenderer(gl, catalog, req);
      if (req.technique) frame.settings.furTechnique = Math.max(0, FUR_TECHNIQUES.indexOf(req.technique));
      const pixel = new Uint8Array(4);
      const ms: number[] = [];
      try {
        // The native demo's frames (cmd_demo.cpp): the fly-through, 0.1 s
        // apart, frames 0 .. FRAMES - 1 after a warm-up draw of frame 0.
        for (let k = -1; k < req.frames; ++k) {
          const i = Math.max(k, 0);
          const t0 = performance.now();
          const camera = new Camera(flyThroughPose(frame.camera.pose, i), frame.camera.fovYDeg);
          renderer.render(camera, frame.time + 0.1 * i, frame.settings, req.width, req.height);
          gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
          if (k >= 0) ms.push(performance.now() - t0);
        }
      } finally {
        renderer.dispose();
      }
      const sorted = [...ms].sort((a, b) => a - b);
      return { medianMs: sorted[sorted.length >> 1], ms };
    },
  };
  (window as unknown as { raylab: typeof api }).raylab = api;
}
