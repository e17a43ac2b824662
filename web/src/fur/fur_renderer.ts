// The fur track's renderer in WebGL 2 (native: framework/src/fur/fur_renderer.cpp):
// the skin and the shells with the stage's own program, then the fins or
// the fur shader's strands with the stage's own fin and strand programs.
// WebGL 2 has no geometry shaders: the core rewrote fin.geom and strand.geom
// into vertex shaders, run by gl/emulated_geometry_pass.ts. The scene, the
// mesh, its edge adjacency and the programs come from the C++ core
// (core/core.ts: framework/src/wasm/web_fur_stage.h); what stays here is WebGL.
import type { Camera } from '../app/camera.js';
import type { Catalog, Sources, StageJson } from '../course/catalog.js';
import {
  type Core, coreFileUrl, CORE_ROOT, ensureProjectFiles, type FurStageHandle, type FurStageInfo, labForCore,
  type OpenTodo, projectFiles, writeProjectFile,
} from '../core/core.js';
import { columnLength, lookAt, perspective, transformPoint } from '../gl/mat4.js';
import { EmulatedGeometryPass, MESH_CORNER_ATTRIBUTES, meshCorners } from '../gl/emulated_geometry_pass.js';
import { Program } from '../gl/program.js';
import { texture2D } from '../gl/textures.js';
import type { RenderSettings } from '../raytrace/render_settings.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';
import { FurMeshBuffers, type MeshArrays } from './fur_mesh_buffers.js';

const COLOR_UNIT = 0, PATTERN_UNIT = 1, FIN_UNIT = 2;
// As natively: from inside the bounding sphere the near plane is this share of the far one.
const NEAR_SHARE_OF_FAR = 1e-4;

export interface FurStageRequest {
  stage: StageJson;
  sources: Sources;
  sceneName: string;   // under assets/scenes/ ("fur/torus.json")
  sceneText?: string;  // that file's text, made up by a test
  todoMarks?: boolean; // a check's target: also mark the pixels that reach a TODO stub
}

// The core's fur stage for REQUEST. Throws Error with native's message.
export async function openFurStage(core: Core, catalog: Catalog, r: FurStageRequest): Promise<{ handle: FurStageHandle; info: FurStageInfo }> {
  await ensureProjectFiles(core, projectFiles(catalog));
  if (r.sceneText !== undefined) writeProjectFile(core, `assets/scenes/${r.sceneName}`, r.sceneText);
  const handle = new core.FurStage(JSON.stringify({
    stage: r.stage.id, lab: labForCore(core, r.stage.id, r.sources), scene: `${CORE_ROOT}/assets/scenes/${r.sceneName}`,
    todoMarks: r.todoMarks ?? false,
  }));
  const error = handle.error();
  if (error) {
    handle.delete();
    throw new Error(error);
  }
  const info = JSON.parse(handle.info()) as FurStageInfo;
  info.todoMarks = r.todoMarks ?? false;
  return { handle, info };
}

// The core's current mesh.
function meshArrays(handle: FurStageHandle): MeshArrays {
  return { positions: handle.positions(), normals: handle.normals(), uvs: handle.uvs(), indices: handle.indices() };
}

interface Frame {
  model: Float32Array; view: Float32Array; projection: Float32Array; eye: number[]; time: number; furLength: number;
}

export class FurRenderer implements TrackRenderer {
  private meshShown = 0;  // RenderSettings.furMesh of the mesh in buffers
  private textures: WebGLTexture[] = [];

  private constructor(
    private gl: WebGL2RenderingContext,
    readonly stage: StageJson,
    private core: FurStageHandle,
    readonly info: FurStageInfo,
    private buffers: FurMeshBuffers,
    private shells: Program,
    private fins: EmulatedGeometryPass | null,
    private strands: EmulatedGeometryPass | null,
  ) {
    this.todos = info.todos;
  }

  readonly todos: OpenTodo[];

  static async create(gl: WebGL2RenderingContext, core: Core, catalog: Catalog, request: FurStageRequest): Promise<FurRenderer> {
    const { handle, info } = await openFurStage(core, catalog, request);
    const stage = request.stage;
    const has = (f: string) => stage.features.includes(f);
    // Built into locals: a failure (a student's compile error) deletes what
    // was built so far, so a watched folder's broken saves leak nothing.
    const built: { dispose(): void }[] = [];
    const program = async (name: 'shells') => {
      const p = info.programs[name]!;
      const program = await Program.build(gl, core, p.vertex, p.fragment);
      built.push(program);
      return program;
    };
    const emulated = async (name: 'fins' | 'strands') => {
      const p = info.programs[name];
      if (!p?.geometry || !p.geometryDraw || !p.captureFragment || !p.emulation) return null;
      const pass = await EmulatedGeometryPass.build(gl, core, {
        vertex: p.vertex, fragment: p.fragment, geometry: p.geometry, geometryDraw: p.geometryDraw,
        captureFragment: p.captureFragment, emulation: p.emulation,
      });
      built.push(pass);
      return pass;
    };
    let shells: Program, fins: EmulatedGeometryPass | null, strands: EmulatedGeometryPass | null;
    try {
      shells = await program('shells');
      fins = await emulated('fins');
      strands = await emulated('strands');
    } catch (e) {
      for (const p of built) p.dispose();
      handle.delete();
      throw e;
    }
    const mesh = meshArrays(handle);
    const buffers = new FurMeshBuffers(gl, mesh);
    // Each input primitive's corners for the emulated geometry shaders:
    // an edge with its neighbours (A B C D) for the fins, a triangle for the strands.
    fins?.setCorners(meshCorners(mesh, handle.adjacency()), MESH_CORNER_ATTRIBUTES);
    strands?.setCorners(meshCorners(mesh, mesh.indices), MESH_CORNER_ATTRIBUTES);
    const r = new FurRenderer(gl, stage, handle, info, buffers, shells, fins, strands);
    // All three pictures or none: those that loaded are deleted with the rest.
    const pictures = await Promise.allSettled(info.textures.map((u) => texture2D(gl, coreFileUrl(u))));
    r.textures = pictures.flatMap((p) => (p.status === 'fulfilled' ? [p.value] : []));
    const failed = pictures.find((p) => p.status === 'rejected');
    if (failed) {
      r.dispose();
      throw (failed as PromiseRejectedResult).reason;
    }
    return r;
  }

  private setUniforms(p: Program, f: Frame): void {
    const gl = this.gl, s = this.info;
    gl.useProgram(p.id);
    gl.uniformMatrix4fv(p.uniform('uModel'), false, f.model);
    gl.uniformMatrix4fv(p.uniform('uView'), false, f.view);
    gl.uniformMatrix4fv(p.uniform('uProjection'), false, f.projection);
    gl.uniform3fv(p.uniform('uEye'), f.eye);
    gl.uniform3fv(p.uniform('uLightDir'), s.lightDirection);
    gl.uniform3fv(p.uniform('uLightColor'), s.lightColor);
    gl.uniform3fv(p.uniform('uAmbient'), s.ambient);
    gl.uniform1f(p.uniform('uFurLength'), f.furLength);
    gl.uniform1f(p.uniform('uPatternScale'), s.fur.patternScale);
    gl.uniform1f(p.uniform('uShadowIntensity'), s.fur.shadowIntensity);
    gl.uniform3fv(p.uniform('uGravity'), [0, -s.fur.gravity, 0]);
    gl.uniform1f(p.uniform('uStrandDensity'), s.fur.strandDensity);
    gl.uniform1f(p.uniform('uTime'), f.time);
    gl.uniform1i(p.uniform('uColorMap'), COLOR_UNIT);
    gl.uniform1i(p.uniform('uPattern'), PATTERN_UNIT);
    gl.uniform1i(p.uniform('uFinMap'), FIN_UNIT);
  }

  // The frame (native: FurRenderer::frameFor): near and far planes hug the
  // mesh's bounding sphere with room for the fur.
  private frameFor(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number) {
    const s = this.info;
    const model = this.core.modelMatrix(timeSeconds);
    const eye = camera.pose.position;
    const f = camera.forward(), up = camera.up();
    const view = lookAt(eye, [eye[0] + f[0], eye[1] + f[1], eye[2] + f[2]], up);
    const furLength = s.fur.length * settings.furLength;
    const centre = transformPoint(model, s.bounds.centre);
    const scale = Math.max(columnLength(model, 0), columnLength(model, 1), columnLength(model, 2));
    const radius = s.bounds.radius * scale + furLength * (1 + s.fur.gravity) * 1.05;
    const distance = Math.hypot(eye[0] - centre[0], eye[1] - centre[1], eye[2] - centre[2]);
    const far = distance + radius;
    const near = Math.max(far * NEAR_SHARE_OF_FAR, distance - radius);
    const projection = perspective((camera.fovYDeg * Math.PI) / 180, width / height, near, far);
    return { model, view, projection, eye, time: timeSeconds, furLength };
  }

  // Key M (native: FurRenderer::render): the procedural mesh FURMESH, or the scene's (0).
  private showMesh(furMesh: number): void {
    this.core.showMesh(furMesh);
    const info = JSON.parse(this.core.info()) as FurStageInfo;
    this.info.bounds = info.bounds;
    this.info.mesh = info.mesh;
    this.buffers.dispose();
    const mesh = meshArrays(this.core);
    this.buffers = new FurMeshBuffers(this.gl, mesh);
    this.fins?.setCorners(meshCorners(mesh, this.core.adjacency()), MESH_CORNER_ATTRIBUTES);
    this.strands?.setCorners(meshCorners(mesh, mesh.indices), MESH_CORNER_ATTRIBUTES);
    this.meshShown = furMesh;
  }

  render(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number): void {
    if ((settings.furMesh ?? 0) !== this.meshShown) this.showMesh(settings.furMesh ?? 0);
    const gl = this.gl, s = this.info;
    const frame = this.frameFor(camera, timeSeconds, settings, width, height);
    gl.viewport(0, 0, width, height);
    gl.clearColor(s.background[0], s.background[1], s.background[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    // A check's target: its TODO marks start at zero, not at the background.
    if (this.info.todoMarks) gl.clearBufferfv(gl.COLOR, 1, [0, 0, 0, 0]);
    gl.colorMask(true, true, true, false);  // the picture's alpha stays 1
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LEQUAL);
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.BACK);
    this.textures.forEach((t, i) => {
      gl.activeTexture(gl.TEXTURE0 + i);
      gl.bindTexture(gl.TEXTURE_2D, t);
    });
    const has = (x: string) => this.stage.features.includes(x);
    const furShader = has('fur_shader') && settings.furTechnique === 1;
    const shells = !has('shells') || furShader ? 1 : settings.shells > 0 ? settings.shells : s.fur.shells;

    // The skin (draw 0) is opaque and writes depth; the shells after it are
    // blended over it, tested against depth but not writing it (lab guide f2).
    this.setUniforms(this.shells, frame);
    gl.uniform1i(this.shells.uniform('uShellCount'), shells);
    for (let i = 0; i < shells; ++i) {
      if (i === 1) {
        gl.depthMask(false);
        gl.enable(gl.BLEND);
        gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      }
      gl.uniform1i(this.shells.uniform('uShellIndex'), i);
      this.buffers.drawTriangles();
    }
    gl.depthMask(true);
    gl.disable(gl.BLEND);

    if (furShader && this.strands) {
      this.setPassUniforms(this.strands, frame);
      this.strands.run();
    } else if (has('fins') && settings.fins && this.fins) {
      this.setPassUniforms(this.fins, frame);
      gl.disable(gl.CULL_FACE);  // fins are seen from either side
      gl.depthMask(false);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      this.fins.run();
      gl.disable(gl.BLEND);
      gl.depthMask(true);
    }
    gl.colorMask(true, true, true, true);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
  }

  private setPassUniforms(pass: EmulatedGeometryPass, frame: Frame): void {
    this.setUniforms(pass.capture, frame);
    this.setUniforms(pass.expand, frame);
    this.setUniforms(pass.draw, frame);
  }

  // The fins the stage's fin.geom makes in a frame (native:
  // FurRenderer::countFins), drawn nowhere; null without fins.
  countFins(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number): number | null {
    if (!this.fins) return null;
    this.setPassUniforms(this.fins, this.frameFor(camera, timeSeconds, settings, width, height));
    return this.fins.run(true) / 2;  // each fin a strip of two triangles
  }

  // The fin count check's verdict on FINS in the stage's check view VIEW
  // (the core's, as native's, against the count tables: the core holds no
  // silhouette test). Throws when the tables have no count for VIEW.
  finCountVerdict(fins: number, view: string): { passed: boolean; detail: string } {
    const r = JSON.parse(this.core.finCount(fins, view)) as { passed: boolean; detail: string; error?: string };
    if (r.error !== undefined) throw new Error(r.error);
    return { passed: r.passed, detail: r.detail };
  }

  dispose(): void {
    const gl = this.gl;
    for (const p of [this.shells, this.fins, this.strands]) p?.dispose();
    for (const t of this.textures) gl.deleteTexture(t);
    this.buffers.dispose();
    this.core.delete();
  }
}
