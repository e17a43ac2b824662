// A stage's vertex + geometry + fragment program in WebGL 2, which has no
// geometry shaders (native: framework/src/gl/emulated_geometry_pass.cpp, the
// same steps on desktop GL). The core rewrote the geometry shader into a
// vertex shader (framework/src/core/geometry_emulation.h, where the method
// is told); here:
//  1. capture: the stage's vertex shader runs once per corner of every input
//     primitive, its outputs kept by transform feedback (one record of
//     recordWords words per corner);
//  2. draw: the rewritten geometry shader runs once per (input primitive,
//     output primitive slot, corner), one instance per input primitive, the
//     primitive's records read as uvec4 attributes raylab_in0.. .
// run(true) draws nothing and counts the primitives made instead (transform
// feedback of the output raylab_kept): the fin count.
import type { Core, CoreSource } from '../core/core.js';
import { Program } from './program.js';

// The core's EmulatedGeometry::json().
export interface EmulationLayout {
  input: string;
  corners: number;
  recordWords: number;
  attributes: number;
  captured: string[];
  output: 'points' | 'lines' | 'triangles';
  maxVertices: number;
  slots: number;
  verticesPerSlot: number;
}

export interface EmulatedProgramSources {
  vertex: CoreSource;
  fragment: CoreSource;
  geometry: CoreSource;         // the geometry shader as a vertex shader
  captureFragment: CoreSource;  // writes nothing: the capture's link
  emulation: EmulationLayout;
}

export class EmulatedGeometryPass {
  private cornerVao: WebGLVertexArrayObject;
  private recordVao: WebGLVertexArrayObject;
  private corners: WebGLBuffer;
  private records: WebGLBuffer;
  private kept: WebGLBuffer;
  private cornerCount = 0;

  private constructor(private gl: WebGL2RenderingContext, readonly capture: Program, readonly draw: Program,
    readonly layout: EmulationLayout) {
    this.cornerVao = gl.createVertexArray()!;
    this.recordVao = gl.createVertexArray()!;
    this.corners = gl.createBuffer()!;
    this.records = gl.createBuffer()!;
    this.kept = gl.createBuffer()!;
  }

  // Throws ShaderError with the student's file and line.
  static async build(gl: WebGL2RenderingContext, core: Core, s: EmulatedProgramSources): Promise<EmulatedGeometryPass> {
    const capture = await Program.build(gl, core, s.vertex, s.captureFragment, s.emulation.captured);
    let draw: Program;
    try {
      draw = await Program.build(gl, core, s.geometry, s.fragment, ['raylab_kept']);
    } catch (e) {
      capture.dispose();
      throw e;
    }
    return new EmulatedGeometryPass(gl, capture, draw, s.emulation);
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
    // One record per corner, read per primitive (16 bytes more: the last
    // attribute may read past the last record).
    gl.bindBuffer(gl.ARRAY_BUFFER, this.records);
    gl.bufferData(gl.ARRAY_BUFFER, this.cornerCount * 4 * l.recordWords + 16, gl.DYNAMIC_COPY);
    gl.bindVertexArray(this.recordVao);
    for (let a = 0; a < l.attributes; ++a) {
      const location = gl.getAttribLocation(this.draw.id, `raylab_in${a}`);
      if (location < 0) continue;  // not read
      gl.enableVertexAttribArray(location);
      gl.vertexAttribIPointer(location, 4, gl.UNSIGNED_INT, 4 * l.corners * l.recordWords, 16 * a);
      gl.vertexAttribDivisor(location, 1);
    }
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
  }

  // Both programs read the stage's uniforms: the caller sets them on each first.
  run(count = false): number {
    const gl = this.gl, l = this.layout;
    const primitives = this.cornerCount / l.corners;
    if (!primitives) return 0;
    // 1. The vertex shader per corner, its outputs kept.
    gl.useProgram(this.capture.id);
    gl.enable(gl.RASTERIZER_DISCARD);
    gl.bindVertexArray(this.cornerVao);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, this.records);
    gl.beginTransformFeedback(gl.POINTS);
    gl.drawArrays(gl.POINTS, 0, this.cornerCount);
    gl.endTransformFeedback();
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
    if (!count) gl.disable(gl.RASTERIZER_DISCARD);

    // 2. The geometry shader per output primitive's corner.
    const mode = l.output === 'points' ? gl.POINTS : l.output === 'lines' ? gl.LINES : gl.TRIANGLES;
    const vertices = l.slots * l.verticesPerSlot;
    gl.useProgram(this.draw.id);
    gl.bindVertexArray(this.recordVao);
    let made = 0;
    if (count) {
      const n = vertices * primitives;
      gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, this.kept);
      gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, 4 * n, gl.DYNAMIC_READ);
      gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, this.kept);
      gl.beginTransformFeedback(mode);
      gl.drawArraysInstanced(mode, 0, vertices, primitives);
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
      gl.drawArraysInstanced(mode, 0, vertices, primitives);
    }
    gl.bindVertexArray(null);
    return made;
  }

  dispose(): void {
    const gl = this.gl;
    this.capture.dispose();
    this.draw.dispose();
    gl.deleteVertexArray(this.cornerVao);
    gl.deleteVertexArray(this.recordVao);
    for (const b of [this.corners, this.records, this.kept]) gl.deleteBuffer(b);
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
