// The ray-tracing track's renderer in WebGL 2 (native:
// framework/src/raytrace/stage_renderer.cpp): one full-screen canvas whose
// fragment shader traces the scene. Everything the CPU prepares comes from
// the C++ core (core/core.ts: framework/src/wasm/web_ray_stage.h): the scene
// read and framed, checked against the stage's limits, the program as
// `raylab shader --es` prints it (with the demo's levers where the demo
// shows the solution), the BVH, the light buffer and the eye's cells. What
// stays here is WebGL: the textures, the uniforms, the draw. The page always
// draws the program specialised to its scene (its static data compiled in):
// the generic one keeps everything in uniform arrays, which can exceed a
// browser's uniform budget (WebGL 2 guarantees only 224 vectors).
import { Camera } from '../app/camera.js';
import { type Catalog, type Sources, type StageJson } from '../course/catalog.js';
import {
  type Core, coreFileUrl, CORE_ROOT, ensureProjectFiles, labForCore, type OpenTodo, projectFiles, type RayStageHandle,
  type RayStageInfo, writeProjectFile,
} from '../core/core.js';
import { Program } from '../gl/program.js';
import { cubeMap, dataTexture, textureArray } from '../gl/textures.js';
import type { RenderSettings } from './render_settings.js';
import { SceneLimitError } from './scene_limit_error.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';

// Texture units, one per sampler (WebGL refuses to draw when samplers of
// two types share a unit, and unused samplers default to unit 0).
const UNITS = {
  uTextures: 0, uSky: 1, uBvhNodes: 2, uBvhItems: 3, uLightCells: 4, uLightItems: 5, uEyeCells: 6, uMeshCorners: 7, uMeshMaterials: 8,
};
const SPHERE_BINDING_POINT = 0;

export { SceneLimitError };

// The specialised program keeps three vectors per torus in plain uniforms,
// plus about 30 for the camera and the switches. A browser that offers too
// little would fail to link with a message naming no cause.
const OTHER_UNIFORM_VECTORS = 32;
function checkUniformBudget(gl: WebGL2RenderingContext, info: RayStageInfo): void {
  const need = 3 * info.tori + OTHER_UNIFORM_VECTORS;
  const have = Number(gl.getParameter(gl.MAX_FRAGMENT_UNIFORM_VECTORS));
  if (need > have)
    throw new SceneLimitError(`${info.sceneFile}: tori: ${info.tori} tori need about ${need} uniform vectors, ` +
      `but this browser offers ${have} (WebGL 2 guarantees 224): use a scene with fewer tori`);
}

export interface RayStageRequest {
  stage: StageJson;
  sources: Sources;
  sceneName: string;       // under assets/scenes/
  sceneText?: string;      // that file's text, made up by a test
  bvh?: boolean;           // stage 08: with or without the BVH; default: the fastest choice
  demoLevers?: boolean;    // the demo's levers (the solution only), as `raylab demo`
  todoMarks?: boolean;     // a check's target: also mark the pixels that reach a TODO stub
  view?: string;           // a debug view (depth, normal, id): view_main.frag's program
  trace?: boolean;         // the build that records one pixel's path (app/pixel_trace.ts)
}

// The core's stage for REQUEST, after the files it reads are in its file
// system. Throws Error with native's message.
export async function openRayStage(gl: WebGL2RenderingContext, core: Core, catalog: Catalog, r: RayStageRequest): Promise<{ handle: RayStageHandle; info: RayStageInfo }> {
  await ensureProjectFiles(core, projectFiles(catalog));
  if (r.sceneText !== undefined) writeProjectFile(core, `assets/scenes/${r.sceneName}`, r.sceneText);
  const lab = labForCore(core, r.stage.id, r.sources);
  const handle = new core.RayStage(JSON.stringify({
    stage: r.stage.id, lab, scene: `${CORE_ROOT}/assets/scenes/${r.sceneName}`,
    demoLevers: r.demoLevers ?? false, bvh: r.bvh === undefined ? -1 : r.bvh ? 1 : 0,
    maxBlockBytes: Number(gl.getParameter(gl.MAX_UNIFORM_BLOCK_SIZE)),
    todoMarks: r.todoMarks ?? false,
    view: r.view ?? 'color',
    trace: r.trace ?? false,
  }));
  const error = handle.error();
  if (error) {
    handle.delete();
    throw new Error(error);
  }
  return { handle, info: JSON.parse(handle.info()) as RayStageInfo };
}

export class StageRenderer implements TrackRenderer {
  readonly todos: OpenTodo[];
  private textures = new Map<string, WebGLTexture>();
  private sphereBuffer: WebGLBuffer;
  private shownTime = Number.NaN;
  private vao: WebGLVertexArrayObject;
  private buffer: WebGLBuffer;

  private constructor(
    private gl: WebGL2RenderingContext,
    readonly stage: StageJson,
    private core: RayStageHandle,
    readonly info: RayStageInfo,
    readonly program: Program,
  ) {
    this.todos = info.todos;
    this.buffer = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1]), gl.STATIC_DRAW);
    this.vao = gl.createVertexArray()!;
    gl.bindVertexArray(this.vao);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
    this.sphereBuffer = gl.createBuffer()!;
    const index = gl.getUniformBlockIndex(program.id, 'SphereGeometry');
    if (index !== gl.INVALID_INDEX) gl.uniformBlockBinding(program.id, index, SPHERE_BINDING_POINT);
  }

  // Throws ShaderError (file:line) or Error (native's message: the scene,
  // the stage's limits, a missing file).
  // The trace build's report of pixel (X, Y) from its SUMMARY and RECORDS.
  traceReport(summary: Float32Array, records: Float32Array, x: number, y: number, width: number, height: number): string {
    const r = this.core.traceReport(summary, records, x, y, width, height);
    if (r.error || r.report === undefined) throw new Error(r.error ?? 'traceReport: no report');
    return r.report;
  }

  // A debug view's picture of FLOATS (RGBA, rows bottom-up), top-down
  // bytes, and what was mapped how; throws Error.
  viewPicture(floats: Float32Array, width: number, height: number): { rgba: Uint8Array; mapping: string } {
    const r = this.core.viewPicture(floats, width, height);
    if (r.error || !r.rgba) throw new Error(r.error ?? 'viewPicture: no picture');
    return { rgba: r.rgba, mapping: r.mapping ?? '' };
  }

  static async create(gl: WebGL2RenderingContext, core: Core, catalog: Catalog, request: RayStageRequest): Promise<StageRenderer> {
    if (request.stage.track !== 'raytrace') throw new Error(`stage ${request.stage.id} is not a ray-tracing stage`);
    const { handle, info } = await openRayStage(gl, core, catalog, request);
    let program: Program;
    try {
      checkUniformBudget(gl, info);
      program = await Program.build(gl, core, info.vertex, info.fragment);
    } catch (e) {
      handle.delete();
      throw e;
    }
    const r = new StageRenderer(gl, request.stage, handle, info, program);
    try {
      if (info.textures.length) r.textures.set('uTextures', await textureArray(gl, info.textures.map(coreFileUrl)));
      if (info.skyBox.length) r.textures.set('uSky', await cubeMap(gl, info.skyBox.map(coreFileUrl)));
      // The buffers the core built for this program (none where it reads none).
      const nodes = handle.bvhNodes();
      if (nodes.length) r.textures.set('uBvhNodes', dataTexture(gl, nodes, 4));
      if (nodes.length) r.textures.set('uBvhItems', dataTexture(gl, handle.bvhItems(), 1));
      const corners = handle.meshCorners();
      if (corners.length) {
        r.textures.set('uMeshCorners', dataTexture(gl, corners, 4));
        r.textures.set('uMeshMaterials', dataTexture(gl, handle.meshMaterials(), 1));
      }
      const cells = handle.lightCells();
      if (cells.length) {
        r.textures.set('uLightCells', dataTexture(gl, cells, 4));
        r.textures.set('uLightItems', dataTexture(gl, handle.lightItems(), 1));
      }
    } catch (e) {
      r.dispose();
      throw e;
    }
    return r;
  }

  // COLUMN (the trace build, app/pixel_trace.ts): the picture's viewport
  // placed at (column.x, column.y) of the target, and the record to keep.
  render(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number,
    column?: { x: number; y: number; record: number }): void {
    const gl = this.gl, p = this.program;
    gl.viewport(column?.x ?? 0, column?.y ?? 0, width, height);
    if (!column) {
      gl.clearColor(0, 0, 0, 1);  // as natively: a discarded fragment leaves black
      gl.clear(gl.COLOR_BUFFER_BIT);
    }
    gl.useProgram(p.id);
    if (column) gl.uniform1i(p.uniform('uTraceRecord'), column.record);
    // The eye moves with the scene into the shaders' frame; directions stay.
    const [x, y, z] = camera.pose.position;
    const placed = this.core.placeEye(x, y, z);
    if (placed.eyeCellsMoved) this.uploadEyeCells();
    gl.uniform3fv(p.uniform('uEye'), placed.eye);
    gl.uniform3fv(p.uniform('uForward'), camera.forward());
    gl.uniform3fv(p.uniform('uRight'), camera.right());
    gl.uniform3fv(p.uniform('uUp'), camera.up());
    gl.uniform1f(p.uniform('uFocal'), camera.focalLength());
    gl.uniform1f(p.uniform('uAspect'), width / height);
    gl.uniform1f(p.uniform('uTime'), timeSeconds);
    gl.uniform1i(p.uniform('uShadows'), settings.shadows ? 1 : 0);
    gl.uniform1i(p.uniform('uMaxDepth'), settings.maxDepth);
    gl.uniform1i(p.uniform('uGlow'), settings.glow ? 1 : 0);
    gl.uniform1i(p.uniform('uNormalMaps'), settings.normalMaps ? 1 : 0);
    gl.uniform1i(p.uniform('uColorMode'), settings.colorMode);
    const lb = this.info.lightBuffer;
    gl.uniform1i(p.uniform('uLightBufferSize'), lb.size);
    gl.uniform1i(p.uniform('uLightBufferEveryCell'), lb.everyCell);
    gl.uniform1f(p.uniform('uLightBufferReach'), lb.reach);
    gl.uniform1i(p.uniform('uEyeCellsSize'), this.info.eyeCellsSize);
    gl.uniform3fv(p.uniform('uEyeCellsCentre'), placed.eye);
    for (const [sampler, unit] of Object.entries(UNITS)) {
      const target = sampler === 'uTextures' ? gl.TEXTURE_2D_ARRAY : sampler === 'uSky' ? gl.TEXTURE_CUBE_MAP : gl.TEXTURE_2D;
      gl.uniform1i(p.uniform(sampler), unit);
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(target, this.textures.get(sampler) ?? null);
    }
    // Only sphere positions and torus axes change from frame to frame.
    if (timeSeconds !== this.shownTime) {
      this.shownTime = timeSeconds;
      gl.bindBuffer(gl.UNIFORM_BUFFER, this.sphereBuffer);
      gl.bufferData(gl.UNIFORM_BUFFER, this.core.sphereCentres(timeSeconds), gl.DYNAMIC_DRAW);
      gl.bindBuffer(gl.UNIFORM_BUFFER, null);
      if (this.info.tori) gl.uniformMatrix3fv(p.uniform('uTorusToLocal[0]'), false, this.core.torusToLocal(timeSeconds));
    }
    gl.bindBufferBase(gl.UNIFORM_BUFFER, SPHERE_BINDING_POINT, this.sphereBuffer);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 6);
    gl.bindVertexArray(null);
  }

  // The eye's cells moved with the eye: their lists follow the tree's items.
  private uploadEyeCells(): void {
    const gl = this.gl;
    for (const name of ['uBvhItems', 'uEyeCells']) {
      const t = this.textures.get(name);
      if (t) gl.deleteTexture(t);
    }
    this.textures.set('uBvhItems', dataTexture(gl, this.core.bvhItems(), 1));
    this.textures.set('uEyeCells', dataTexture(gl, this.core.eyeCells(), 2));
  }

  dispose(): void {
    const gl = this.gl;
    this.program.dispose();
    for (const t of this.textures.values()) gl.deleteTexture(t);
    gl.deleteBuffer(this.sphereBuffer);
    gl.deleteVertexArray(this.vao);
    gl.deleteBuffer(this.buffer);
    this.core.delete();
  }
}
