// The fur track's renderer in WebGL 2 (native: framework/src/fur/fur_renderer.cpp):
// the skin and the shells with the stage's own program, then the fins or
// the fur shader's strands. WebGL 2 has no geometry shaders, so fins and
// strands come from instanced draws whose vertex shaders
// (web/shaders/fin_instanced.vert, strand_instanced.vert) do what fin.geom
// and strand.geom do natively, calling the student's silhouette.glsl and
// strand_point.glsl; the fragment shaders are the stage's own.
import type { Camera } from '../app/camera.js';
import { type Catalog, type Sources, type StageJson, searchPath, stageDefines } from '../course/catalog.js';
import { columnLength, lookAt, perspective, transformPoint } from '../gl/mat4.js';
import { Program } from '../gl/program.js';
import { texture2D } from '../gl/textures.js';
import type { RenderSettings } from '../raytrace/render_settings.js';
import { findOpenTodos, type OpenTodo } from '../shader/open_todos.js';
import { asGlslEs300, assembleShader, type ShaderSource } from '../shader/shader_source.js';
import type { SourceFolder } from '../shader/source_folder.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';
import { buildEdgeAdjacency } from './mesh/adjacency.js';
import { type FurScene, modelMatrix } from './mesh/fur_scene.js';
import type { Mesh } from './mesh/mesh.js';
import { FurMeshBuffers } from './fur_mesh_buffers.js';

const COLOR_UNIT = 0, PATTERN_UNIT = 1, FIN_UNIT = 2;
// As natively: from inside the bounding sphere the near plane is this share of the far one.
const NEAR_SHARE_OF_FAR = 1e-4;
// The strands per triangle natively (strand_budget.cpp) with the geometry
// budget every OpenGL 3.3 driver offers (1024 components): the same fur.
const STRAND_VERTEX_COMPONENTS = 17, STRANDS_WANTED = 32, MIN_TOTAL_COMPONENTS = 1024, MIN_OUTPUT_VERTICES = 256;

function strandsPerTriangle(segments: number): number {
  const perStrand = segments + 1;
  return Math.min(STRANDS_WANTED, Math.floor(MIN_OUTPUT_VERTICES / perStrand),
    Math.floor(MIN_TOTAL_COMPONENTS / (perStrand * STRAND_VERTEX_COMPONENTS)));
}

function strandDefines(segments: number): string[] {
  const strands = strandsPerTriangle(segments);
  return [`STRAND_SEGMENTS ${segments}`, `STRANDS_PER_TRIANGLE ${strands}`, `STRAND_MAX_VERTICES ${strands * (segments + 1)}`];
}

export class FurRenderer implements TrackRenderer {
  readonly notes: string[] = [];
  private textures: WebGLTexture[] = [];

  private constructor(
    private gl: WebGL2RenderingContext,
    readonly stage: StageJson,
    readonly scene: FurScene,
    private buffers: FurMeshBuffers,
    private shells: Program,
    private fins: Program | null,
    private strands: Program | null,
    readonly todos: OpenTodo[],
    private bounds: { centre: [number, number, number]; radius: number },
  ) {}

  static async create(
    gl: WebGL2RenderingContext, catalog: Catalog, stage: StageJson, sources: Sources, scene: FurScene, mesh: Mesh,
  ): Promise<FurRenderer> {
    const has = (f: string) => stage.features.includes(f);
    if (!has('mesh')) throw new Error(`solution/${stage.id}/stage.json: features: a fur stage needs the "mesh" feature`);
    const defines = [...stageDefines(stage), ...(has('fur_shader') ? strandDefines(scene.fur.strandSegments) : [])];
    const search = searchPath(catalog, stage, sources, defines);
    const sourcesRead: ShaderSource[] = [];
    const assemble = async (entry: string, folder?: SourceFolder[]) => {
      const s = asGlslEs300(await assembleShader(entry, folder ?? search, defines));
      sourcesRead.push(s);
      return s;
    };
    const programOf = async (vertex: string, fragment: string) => new Program(gl, await assemble(vertex), await assemble(fragment));
    const named = (name: string, feature: string) => {
      const p = stage.programs?.[name];
      if (!p) throw new Error(`solution/${stage.id}/stage.json: programs.${name}: the feature "${feature}" needs this program`);
      return p;
    };
    // Built into locals: a failure (a student's compile error) deletes what
    // was built so far, so a watched folder's broken saves leak nothing.
    const programs: Program[] = [];
    const built = async (vertex: string, fragment: string) => {
      const p = await programOf(vertex, fragment);
      programs.push(p);
      return p;
    };
    const notes: string[] = [];
    let shells: Program, fins: Program | null = null, strands: Program | null = null;
    try {
      shells = await built(stage.program.vertex, stage.program.fragment);
      if (has('fins')) {
        const p = named('fins', 'fins');
        fins = await built('fin_instanced.vert', p.fragment);
        await assemble(p.vertex);  // for its TODOs only
        if (p.geometry) await assemble(p.geometry);
        notes.push(`WebGL 2 has no geometry shaders, so the fins are instanced quads (web/shaders/fin_instanced.vert) that use your silhouette.glsl but the web's own finished copies of ${p.vertex} and ${p.geometry}: what you write in those two shows only natively (raylab run/check --stage ${stage.id.split('-')[0]})`);
      }
      if (has('fur_shader')) {
        const p = named('strands', 'fur_shader');
        strands = await built('strand_instanced.vert', p.fragment);
        if (p.geometry) await assemble(p.geometry);
        notes.push(`the fur shader's strands (key T) are instanced line strips (web/shaders/strand_instanced.vert) that use your strand_point.glsl in place of ${p.vertex} and ${p.geometry}, which run natively only`);
      }
    } catch (e) {
      for (const p of programs) p.dispose();
      throw e;
    }
    // Open TODOs of every file read, each once.
    const seen = new Set<string>();
    const todos: OpenTodo[] = [];
    for (const s of sourcesRead)
      for (const t of await findOpenTodos(s))
        if (!seen.has(`${t.file}:${t.line}`)) {
          seen.add(`${t.file}:${t.line}`);
          todos.push(t);
        }
    const buffers = new FurMeshBuffers(gl, mesh, has('fins') ? buildEdgeAdjacency(mesh) : null,
      has('fur_shader') ? { perTriangle: strandsPerTriangle(scene.fur.strandSegments), vertices: scene.fur.strandSegments + 1 } : null);
    // The mesh's bounding sphere (native: FurRenderer::setMesh).
    const p = mesh.positions;
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let v = 0; v < p.length; v += 3)
      for (let i = 0; i < 3; ++i) {
        lo[i] = Math.min(lo[i]!, p[v + i]!);
        hi[i] = Math.max(hi[i]!, p[v + i]!);
      }
    const centre: [number, number, number] = [0.5 * (lo[0]! + hi[0]!), 0.5 * (lo[1]! + hi[1]!), 0.5 * (lo[2]! + hi[2]!)];
    let radius = 0;
    for (let v = 0; v < p.length; v += 3) radius = Math.max(radius, Math.hypot(p[v]! - centre[0], p[v + 1]! - centre[1], p[v + 2]! - centre[2]));
    const r = new FurRenderer(gl, stage, scene, buffers, shells, fins, strands, todos, { centre, radius });
    r.notes.push(...notes);
    // All three pictures or none: those that loaded are deleted with the rest.
    const pictures = await Promise.allSettled([scene.fur.colorMap, scene.fur.pattern, scene.fur.finMap].map((u) => texture2D(gl, u)));
    r.textures = pictures.flatMap((p) => (p.status === 'fulfilled' ? [p.value] : []));
    const failed = pictures.find((p) => p.status === 'rejected');
    if (failed) {
      r.dispose();
      throw (failed as PromiseRejectedResult).reason;
    }
    return r;
  }

  private setUniforms(p: Program, f: { model: Float32Array; view: Float32Array; projection: Float32Array; eye: number[]; time: number; furLength: number }): void {
    const gl = this.gl, s = this.scene;
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

  render(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number): void {
    const gl = this.gl, s = this.scene;
    // The frame (native: FurRenderer::frameFor): near and far planes hug the
    // mesh's bounding sphere with room for the fur.
    const model = modelMatrix(s, timeSeconds);
    const eye = camera.pose.position;
    const f = camera.forward(), up = camera.up();
    const view = lookAt(eye, [eye[0] + f[0], eye[1] + f[1], eye[2] + f[2]], up);
    const furLength = s.fur.length * settings.furLength;
    const centre = transformPoint(model, this.bounds.centre);
    const scale = Math.max(columnLength(model, 0), columnLength(model, 1), columnLength(model, 2));
    const radius = this.bounds.radius * scale + furLength * (1 + s.fur.gravity) * 1.05;
    const distance = Math.hypot(eye[0] - centre[0], eye[1] - centre[1], eye[2] - centre[2]);
    const far = distance + radius;
    const near = Math.max(far * NEAR_SHARE_OF_FAR, distance - radius);
    const projection = perspective((camera.fovYDeg * Math.PI) / 180, width / height, near, far);
    const frame = { model, view, projection, eye, time: timeSeconds, furLength };

    gl.viewport(0, 0, width, height);
    gl.clearColor(s.background[0], s.background[1], s.background[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
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
      this.setUniforms(this.strands, frame);
      this.buffers.drawStrands();
    } else if (has('fins') && settings.fins && this.fins) {
      this.setUniforms(this.fins, frame);
      gl.disable(gl.CULL_FACE);  // fins are seen from either side
      gl.depthMask(false);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      this.buffers.drawFins();
      gl.disable(gl.BLEND);
      gl.depthMask(true);
    }
    gl.colorMask(true, true, true, true);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
  }

  dispose(): void {
    const gl = this.gl;
    for (const p of [this.shells, this.fins, this.strands]) p?.dispose();
    for (const t of this.textures) gl.deleteTexture(t);
    this.buffers.dispose();
  }
}
