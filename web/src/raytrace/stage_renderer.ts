// The ray-tracing track's renderer in WebGL 2 (native:
// framework/src/raytrace/stage_renderer.cpp): one full-screen canvas whose
// fragment shader traces the scene. The web always compiles the program
// specialised to its scene (the scene's static data as constants): the
// generic program keeps everything in uniform arrays, which can exceed a
// browser's uniform budget (WebGL 2 guarantees only 224 vectors); the
// specialised one needs only the spheres' centres (a uniform block,
// sphere_block.ts) and the spinning tori.
import { Camera } from '../app/camera.js';
import { type Catalog, type Sources, type StageJson, searchPath } from '../course/catalog.js';
import { Program } from '../gl/program.js';
import { cubeMap, dataTexture, textureArray } from '../gl/textures.js';
import { buildBvh, packBvhTextures } from '../scene/bvh.js';
import type { Scene } from '../scene/scene.js';
import { torusAxisAt, torusToLocal } from '../scene/scene.js';
import { bakedSceneDefines, bakedSceneGlsl } from '../scene/scene_baking.js';
import { findOpenTodos, type OpenTodo } from '../shader/open_todos.js';
import { asGlslEs300, assembleShader, type ShaderSource } from '../shader/shader_source.js';
import type { RenderSettings } from './render_settings.js';
import { SceneLimitError } from './scene_limit_error.js';
import { checkSpheresFitBlock, SphereBlock } from './sphere_block.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';

// Texture units, one per sampler type (WebGL refuses to draw when samplers
// of two types share a unit, and unused samplers default to unit 0).
const TEXTURE_UNIT = 0, SKY_UNIT = 1, BVH_NODE_UNIT = 2, BVH_ITEM_UNIT = 3;
// Measured natively (ShaderVariant::fastestFor): the BVH repays its walk from 32 spheres.
const SPHERES_FOR_BVH = 32;

export { SceneLimitError };

// The stage's limits (native: checkSceneFits).
function checkSceneFits(stage: StageJson, scene: Scene, shown: string): void {
  const l = stage.limits;
  const fits = (what: string, count: number) => {
    const limit = Number(l[what] ?? 0);
    if (count > 0 && limit === 0) throw new SceneLimitError(`${shown}: ${what}: stage ${stage.id} has no ${what}`);
    if (count > limit)
      throw new SceneLimitError(`${shown}: ${what}: ${count} ${what}, but stage ${stage.id} supports at most ${limit}`);
  };
  fits('spheres', scene.spheres.length);
  fits('materials', scene.materials.length);
  fits('lights', scene.lights.length);
  fits('planes', scene.planes.length);
  fits('discs', scene.discs.length);
  fits('triangles', scene.triangles.length);
  fits('tori', scene.tori.length);
  fits('textures', scene.textures.length);
  if (scene.skyBox && !l.sky_box) throw new SceneLimitError(`${shown}: sky_box: stage ${stage.id} has no sky box`);
}

// The specialised program keeps the spheres' centres in a uniform block
// (sphere_block.ts), three vectors per torus in plain uniforms, plus about
// 30 for the camera and the switches. A browser that offers too little
// would fail to link with a message naming no cause.
const OTHER_UNIFORM_VECTORS = 32;
function checkUniformBudget(gl: WebGL2RenderingContext, scene: Scene, shown: string): void {
  checkSpheresFitBlock(scene, Number(gl.getParameter(gl.MAX_UNIFORM_BLOCK_SIZE)), shown);
  const need = 3 * scene.tori.length + OTHER_UNIFORM_VECTORS;
  const have = Number(gl.getParameter(gl.MAX_FRAGMENT_UNIFORM_VECTORS));
  if (need > have)
    throw new SceneLimitError(`${shown}: tori: ${scene.tori.length} tori need about ${need} uniform vectors, ` +
      `but this browser offers ${have} (WebGL 2 guarantees 224): use a scene with fewer tori`);
}

export interface StageProgramSources {
  vertex: ShaderSource;
  fragment: ShaderSource;
  defines: string[];
}

// The program's sources exactly as natively (stage_programs.cpp), in GLSL ES.
// BVH: walk a BVH (stage 08); by default where it repays itself natively.
export async function assembleStagePrograms(
  catalog: Catalog, stage: StageJson, sources: Sources, scene: Scene, sceneShown: string,
  bvh = scene.spheres.length >= SPHERES_FOR_BVH,
): Promise<StageProgramSources> {
  const defines = [...bakedSceneDefines(scene), ...(stage.defines ?? [])];
  if (bvh) defines.push('RAYLAB_BVH');
  const search = searchPath(catalog, stage, sources, defines);
  const vertex = asGlslEs300(await assembleShader(stage.program.vertex, search, defines));
  const fragment = asGlslEs300(await assembleShader(stage.program.fragment, search, defines, bakedSceneGlsl(scene, sceneShown)));
  return { vertex, fragment, defines };
}

export class StageRenderer implements TrackRenderer {
  readonly notes: string[] = [];
  private textures: WebGLTexture | null = null;
  private sky: WebGLTexture | null = null;
  private bvhNodes: WebGLTexture | null = null;
  private bvhItems: WebGLTexture | null = null;
  private spheres: SphereBlock | null = null;
  private vao: WebGLVertexArrayObject;
  private buffer: WebGLBuffer;

  private constructor(
    private gl: WebGL2RenderingContext,
    readonly stage: StageJson,
    readonly scene: Scene,
    readonly program: Program,
    readonly todos: OpenTodo[],
  ) {
    this.buffer = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1]), gl.STATIC_DRAW);
    this.vao = gl.createVertexArray()!;
    gl.bindVertexArray(this.vao);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
  }

  // Throws ShaderError (file:line), SceneError or SceneLimitError (one line).
  static async create(
    gl: WebGL2RenderingContext, catalog: Catalog, stage: StageJson, sources: Sources, scene: Scene, sceneShown: string,
    bvh?: boolean,
  ): Promise<StageRenderer> {
    if (stage.track !== 'raytrace') throw new Error(`stage ${stage.id} is not a ray-tracing stage`);
    checkSceneFits(stage, scene, sceneShown);
    checkUniformBudget(gl, scene, sceneShown);
    const p = await assembleStagePrograms(catalog, stage, sources, scene, sceneShown, bvh);
    const program = new Program(gl, p.vertex, p.fragment);
    let r: StageRenderer;
    try {
      r = new StageRenderer(gl, stage, scene, program, await findOpenTodos(p.fragment));
    } catch (e) {
      program.dispose();
      throw e;
    }
    try {
      SphereBlock.attach(gl, program.id);
      r.spheres = new SphereBlock(gl, scene);
      if (scene.textures.length) r.textures = await textureArray(gl, scene.textures);
      if (scene.skyBox) r.sky = await cubeMap(gl, scene.skyBox);
      // The tree only for a program that walks it (as natively).
      if (program.uniform('uBvhNodes') !== null) {
        const packed = packBvhTextures(buildBvh(scene));
        r.bvhNodes = dataTexture(gl, packed.nodes);
        r.bvhItems = dataTexture(gl, packed.items);
      }
    } catch (e) {
      r.dispose();
      throw e;
    }
    return r;
  }

  render(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number): void {
    const gl = this.gl, p = this.program;
    gl.viewport(0, 0, width, height);
    gl.clearColor(0, 0, 0, 1);  // as natively: a discarded fragment leaves black
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.useProgram(p.id);
    gl.uniform3fv(p.uniform('uEye'), camera.pose.position);
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
    const bind = (unit: number, target: number, t: WebGLTexture | null, sampler: string) => {
      gl.uniform1i(p.uniform(sampler), unit);
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(target, t);
    };
    bind(TEXTURE_UNIT, gl.TEXTURE_2D_ARRAY, this.textures, 'uTextures');
    bind(SKY_UNIT, gl.TEXTURE_CUBE_MAP, this.sky, 'uSky');
    bind(BVH_NODE_UNIT, gl.TEXTURE_2D, this.bvhNodes, 'uBvhNodes');
    bind(BVH_ITEM_UNIT, gl.TEXTURE_2D, this.bvhItems, 'uBvhItems');
    // Only sphere positions and torus axes change from frame to frame.
    this.spheres!.bindAt(timeSeconds);
    if (this.scene.tori.length) {
      const m = new Float32Array(9 * this.scene.tori.length);
      this.scene.tori.forEach((t, i) => m.set(torusToLocal(torusAxisAt(t, timeSeconds)), 9 * i));
      gl.uniformMatrix3fv(p.uniform('uTorusToLocal[0]'), false, m);
    }
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 6);
    gl.bindVertexArray(null);
  }

  dispose(): void {
    const gl = this.gl;
    this.program.dispose();
    this.spheres?.dispose();
    for (const t of [this.textures, this.sky, this.bvhNodes, this.bvhItems]) if (t) gl.deleteTexture(t);
    gl.deleteVertexArray(this.vao);
    gl.deleteBuffer(this.buffer);
  }
}
