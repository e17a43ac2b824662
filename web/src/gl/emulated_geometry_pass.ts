// A stage's vertex + geometry + fragment program in WebGL 2, which has no
// geometry shaders (native: framework/src/gl/emulated_geometry_pass.cpp, the
// same steps on desktop GL). The core rewrote the geometry shader into a
// vertex shader (framework/src/core/geometry_emulation.h, where the method
// is told); here:
//  1. capture: the stage's vertex shader runs once per corner of every input
//     primitive, its outputs kept by transform feedback (one record of
//     recordWords words per corner);
//  2. expand: the rewritten geometry shader runs `runs` times per input
//     primitive (a vertex per primitive, its records read as uvec4
//     attributes raylab_in0.., an instance per run), each run keeping
//     emissionsPerRun emissions by transform feedback;
//  3. the emissions are copied into an RGBA32UI 2D array texture (the
//     feedback buffer bound as the pixel unpack buffer);
//  4. draw: one vertex per (input primitive, output primitive slot, corner),
//     read from that texture, into the stage's fragment shader.
// run(true) draws nothing and counts the primitives made instead (transform
// feedback of the draw's output raylab_kept): the fin count.
import type { Core, CoreSource } from '../core/core.js';
import { Program } from './program.js';

// The core's EmulatedGeometry::json().
export interface EmulationLayout {
  input: string;
  corners: number;
  recordWords: number;
  attributes: number;
  captured: string[];
  emitted: string[];
  output: 'points' | 'lines' | 'triangles';
  maxVertices: number;
  slots: number;
  verticesPerSlot: number;
  emissionTexels: number;
  emissionsPerRun: number;
  runs: number;
  textureWidth: number;
  layerRows: number;
  textureUnit: number;
}

export interface EmulatedProgramSources {
  vertex: CoreSource;
  fragment: CoreSource;
  geometry: CoreSource;         // the geometry shader as a vertex shader: its emissions out
  geometryDraw: CoreSource;     // the primitives drawn from the emissions
  captureFragment: CoreSource;  // writes nothing: the capture's and expand's link
  emulation: EmulationLayout;
}

export class EmulatedGeometryPass {
  private cornerVao: WebGLVertexArrayObject;
  private recordVao: WebGLVertexArrayObject;
  private emptyVao: WebGLVertexArrayObject;
  private corners: WebGLBuffer;
  private records: WebGLBuffer;
  private emissions: WebGLBuffer;
  private kept: WebGLBuffer;
  private texture: WebGLTexture;
  private cornerCount = 0;
  private rows = 0;
  private layers = 0;

  private constructor(private gl: WebGL2RenderingContext, readonly capture: Program, readonly expand: Program,
    readonly draw: Program, readonly layout: EmulationLayout) {
    this.cornerVao = gl.createVertexArray()!;
    this.recordVao = gl.createVertexArray()!;
    this.emptyVao = gl.createVertexArray()!;
    this.corners = gl.createBuffer()!;
    this.records = gl.createBuffer()!;
    this.emissions = gl.createBuffer()!;
    this.kept = gl.createBuffer()!;
    this.texture = gl.createTexture()!;
    gl.useProgram(draw.id);
    gl.uniform1i(gl.getUniformLocation(draw.id, 'raylab_emissions'), layout.textureUnit);
    gl.useProgram(null);
  }

  // Throws ShaderError with the student's file and line.
  static async build(gl: WebGL2RenderingContext, core: Core, s: EmulatedProgramSources): Promise<EmulatedGeometryPass> {
    const built: Program[] = [];
    try {
      built.push(await Program.build(gl, core, s.vertex, s.captureFragment, s.emulation.captured));
      built.push(await Program.build(gl, core, s.geometry, s.captureFragment, s.emulation.emitted));
      built.push(await Program.build(gl, core, s.geometryDraw, s.fragment, ['raylab_kept']));
    } catch (e) {
      for (const p of built) p.dispose();
      throw e;
    }
    return new EmulatedGeometryPass(gl, built[0], built[1], built[2], s.emulation);
  }

  // The input primitives' corners one after the other: FLOATS per corner
  // interleaved as ATTRIBUTES says ([location, size]), for the vertex shader.
  setCorners(floats: Float32Array, attributes: [number, number][]): void {
    const gl = this.gl, l = this.layout;
    const perCorner = attributes.reduce((n, [, size]) => n + size, 0);
    this.cornerCount = floats.length / perCorner;
    gl.bindVertexArray(this.cornerVao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.corners);
    gl.bufferData(gl.ARRAY_BUFFER, floats, gl.STATIC_DRAW);
    let offset = 0;
    for (const [location, size] of attributes) {
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, gl.FLOAT, false, 4 * perCorner, offset);
      offset += 4 * size;
    }
    // One record per corner, read per primitive, the expand's vertex (16
    // bytes more: the last attribute may read past the last record).
    gl.bindBuffer(gl.ARRAY_BUFFER, this.records);
    gl.bufferData(gl.ARRAY_BUFFER, this.cornerCount * 4 * l.recordWords + 16, gl.DYNAMIC_COPY);
    gl.bindVertexArray(this.recordVao);
    for (let a = 0; a < l.attributes; ++a) {
      const location = gl.getAttribLocation(this.expand.id, `raylab_in${a}`);
      if (location < 0) continue;  // not read
      gl.enableVertexAttribArray(location);
      gl.vertexAttribIPointer(location, 4, gl.UNSIGNED_INT, 4 * l.corners * l.recordWords, 16 * a);
    }
    gl.bindVertexArray(null);
    // The emissions (the core's emissionTextureSize): written by transform
    // feedback, copied into the texture the draw reads.
    const primitives = this.cornerCount / l.corners;
    gl.useProgram(this.draw.id);
    gl.uniform1i(gl.getUniformLocation(this.draw.id, 'raylab_primitives'), primitives);
    gl.useProgram(null);
    const texels = Math.max(1, primitives * l.runs * l.emissionsPerRun * l.emissionTexels);
    const rows = Math.ceil(texels / l.textureWidth);
    this.layers = Math.ceil(rows / l.layerRows);
    this.rows = Math.min(rows, l.layerRows);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.emissions);
    gl.bufferData(gl.ARRAY_BUFFER, 16 * l.textureWidth * this.rows * this.layers, gl.DYNAMIC_COPY);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    gl.activeTexture(gl.TEXTURE0 + l.textureUnit);
    gl.bindTexture(gl.TEXTURE_2D_ARRAY, this.texture);
    gl.texImage3D(gl.TEXTURE_2D_ARRAY, 0, gl.RGBA32UI, l.textureWidth, this.rows, this.layers, 0,
      gl.RGBA_INTEGER, gl.UNSIGNED_INT, null);
    gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.activeTexture(gl.TEXTURE0);
  }

  // The three programs read the stage's uniforms: the caller sets them on each
  // first. Leaves the emissions' texture bound to its unit.
  run(count = false): number {
    const gl = this.gl, l = this.layout;
    const primitives = this.cornerCount / l.corners;
    if (!primitives) return 0;
    gl.enable(gl.RASTERIZER_DISCARD);
    // 1. The vertex shader per corner, its outputs kept.
    gl.useProgram(this.capture.id);
    gl.bindVertexArray(this.cornerVao);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, this.records);
    gl.beginTransformFeedback(gl.POINTS);
    gl.drawArrays(gl.POINTS, 0, this.cornerCount);
    gl.endTransformFeedback();

    // 2. The geometry shader's body: a vertex per input primitive, an
    // instance per run, its emissions kept.
    gl.useProgram(this.expand.id);
    gl.bindVertexArray(this.recordVao);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, this.emissions);
    gl.beginTransformFeedback(gl.POINTS);
    gl.drawArraysInstanced(gl.POINTS, 0, primitives, l.runs);
    gl.endTransformFeedback();
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
    if (!count) gl.disable(gl.RASTERIZER_DISCARD);

    // 3. The emissions into the texture the draw reads.
    gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, this.emissions);
    gl.activeTexture(gl.TEXTURE0 + l.textureUnit);
    gl.bindTexture(gl.TEXTURE_2D_ARRAY, this.texture);
    gl.texSubImage3D(gl.TEXTURE_2D_ARRAY, 0, 0, 0, 0, l.textureWidth, this.rows, this.layers,
      gl.RGBA_INTEGER, gl.UNSIGNED_INT, 0);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, null);

    // 4. The primitives, one vertex per (input primitive, slot, corner).
    const mode = l.output === 'points' ? gl.POINTS : l.output === 'lines' ? gl.LINES : gl.TRIANGLES;
    const n = l.slots * l.verticesPerSlot * primitives;
    gl.useProgram(this.draw.id);
    gl.bindVertexArray(this.emptyVao);
    let made = 0;
    if (count) {
      gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, this.kept);
      gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, 4 * n, gl.DYNAMIC_READ);
      gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, this.kept);
      gl.beginTransformFeedback(mode);
      gl.drawArrays(mode, 0, n);
      gl.endTransformFeedback();
      gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
      gl.disable(gl.RASTERIZER_DISCARD);
      const kept = new Int32Array(n);
      gl.bindBuffer(gl.COPY_READ_BUFFER, this.kept);
      gl.getBufferSubData(gl.COPY_READ_BUFFER, 0, kept);
      gl.bindBuffer(gl.COPY_READ_BUFFER, null);
      for (const k of kept) made += k;
      made /= l.verticesPerSlot;
    } else {
      gl.drawArrays(mode, 0, n);
    }
    gl.bindVertexArray(null);
    return made;
  }

  dispose(): void {
    const gl = this.gl;
    this.capture.dispose();
    this.expand.dispose();
    this.draw.dispose();
    for (const v of [this.cornerVao, this.recordVao, this.emptyVao]) gl.deleteVertexArray(v);
    for (const b of [this.corners, this.records, this.emissions, this.kept]) gl.deleteBuffer(b);
    gl.deleteTexture(this.texture);
  }
}

// Each input primitive's corners one after the other, from a mesh's vertex
// arrays and INDICES (3 per triangle, or 4 per edge with its neighbours):
// position, normal, uv (8 floats, locations 0, 1, 2).
export function meshCorners(mesh: { positions: Float32Array; normals: Float32Array; uvs: Float32Array }, indices: Uint32Array): Float32Array {
  const out = new Float32Array(8 * indices.length);
  indices.forEach((v, i) => {
    out.set(mesh.positions.subarray(3 * v, 3 * v + 3), 8 * i);
    out.set(mesh.normals.subarray(3 * v, 3 * v + 3), 8 * i + 3);
    out.set(mesh.uvs.subarray(2 * v, 2 * v + 2), 8 * i + 6);
  });
  return out;
}
export const MESH_CORNER_ATTRIBUTES: [number, number][] = [[0, 3], [1, 3], [2, 2]];
