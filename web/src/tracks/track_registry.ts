// Which renderer draws which track, and how its scenes are read (native:
// framework/src/tracks/track_registry.cpp). Everything that draws a stage -
// the page, the tests, the benchmark - comes through here.
import type { CameraPose } from '../app/camera.js';
import { type Catalog, type Sources, type StageJson } from '../course/catalog.js';
import { FurRenderer } from '../fur/fur_renderer.js';
import { loadCore } from '../core/core.js';
import { StageRenderer } from '../raytrace/stage_renderer.js';
import type { TrackRenderer } from './track_renderer.js';

export interface LoadedStage {
  renderer: TrackRenderer;
  camera: CameraPose;  // the scene's
  fovYDeg: number;
  summary: string;     // one line about the scene, for the page
  sceneShells: number; // the fur scene's shell count (what shells 0 means); 0 elsewhere
}

export interface LoadOptions {
  // The ray tracer's BVH switch (stage 08); undefined: as natively.
  bvh?: boolean;
  // The scene file's text, not fetched (the browser tests' made-up scenes,
  // window.raylab.renderView); it is still shown as assets/scenes/SCENENAME.
  sceneText?: string;
  // The ray tracer's program with the demo's levers (the solution only), as
  // `raylab demo` and the native window showing the solution draw it.
  demoLevers?: boolean;
  // For a check's target (check/check_target.ts): the programs also mark
  // the pixels that reach a TODO stub, in a second colour attachment.
  todoMarks?: boolean;
  // A ray tracer's debug view (depth, normal, id: app/debug_view.ts).
  view?: string;
  // The ray tracer's build that records one pixel's path (app/pixel_trace.ts).
  trace?: boolean;
}

// SCENENAME: a file under assets/scenes/ ("lite.json", "fur/torus.json").
export async function loadStage(
  gl: WebGL2RenderingContext, catalog: Catalog, stage: StageJson, sources: Sources, sceneName: string, o: LoadOptions = {},
): Promise<LoadedStage> {
  const { bvh, sceneText, demoLevers = false, todoMarks = false, view, trace } = o;
  if (stage.track === 'raytrace') {
    const core = await loadCore();
    const renderer = await StageRenderer.create(gl, core, catalog, {
      stage, sources, sceneName, sceneText, bvh, demoLevers: demoLevers && sources.kind === 'solution', todoMarks, view, trace,
    });
    const c = renderer.info.camera;
    return {
      renderer, camera: { position: c.position, yawDeg: c.yaw, pitchDeg: c.pitch }, fovYDeg: c.fovY,
      summary: `${renderer.info.spheres} spheres, ${renderer.info.triangles} triangles, ` +
        `${renderer.info.tori} tori, ${renderer.info.lights} lights` +
        (renderer.info.levers.length ? `; program with ${renderer.info.levers.join(', ')}` : ''),
      sceneShells: 0,
    };
  }
  if (stage.track === 'fur') {
    const core = await loadCore();
    const renderer = await FurRenderer.create(gl, core, catalog, { stage, sources, sceneName, sceneText, todoMarks });
    const i = renderer.info, c = i.camera;
    return {
      renderer, camera: { position: c.position, yawDeg: c.yaw, pitchDeg: c.pitch }, fovYDeg: c.fovY,
      // (The shell count is the overlay's: it follows [ and ].)
      summary: `${i.mesh.triangles} triangles, ${i.mesh.vertices} vertices`,
      sceneShells: i.fur.shells,
    };
  }
  throw new Error(`stage ${stage.id}: the web build has no renderer for track "${stage.track}"`);
}
