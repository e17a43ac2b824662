// The mesh on the GPU for the fur track (native: fur/mesh_buffers.cpp):
// vertices (position, normal, uv at locations 0, 1, 2) and triangles for the
// skin and shells; for the web's instanced fins one instance per edge
// (locations 3..10: A, B, C, D, the normals and uvs at B and C); for the
// instanced strands one triangle per STRANDS instances (locations 3..11:
// three corners, three normals, three uvs, advancing every STRANDS instances).
import { edgeInstances } from './fin_instances.js';

// A mesh as the core gives it (native: fur/mesh/mesh.h).
export interface MeshArrays {
  positions: Float32Array;  // x, y, z per vertex
  normals: Float32Array;    // x, y, z per vertex, unit length
  uvs: Float32Array;        // u, v per vertex
  indices: Uint32Array;     // three per triangle
}

export class FurMeshBuffers {
  private triangles: WebGLVertexArrayObject;
  private finVao: WebGLVertexArrayObject | null = null;
  private strandVao: WebGLVertexArrayObject | null = null;
  private buffers: WebGLBuffer[] = [];
  private indexCount: number;
  private edgeCount = 0;
  private triangleCount: number;

  constructor(
    private gl: WebGL2RenderingContext,
    mesh: MeshArrays,
    adjacency: Uint32Array | null,  // the core's: 4 per edge (A B C D); null without fins
    // The fur shader's strands: per triangle, and vertices per strand (segments + 1).
    private strands: { perTriangle: number; vertices: number } | null,
  ) {
    const n = mesh.positions.length / 3;
    const vertices = new Float32Array(8 * n);
    for (let i = 0; i < n; ++i) {
      vertices.set(mesh.positions.subarray(3 * i, 3 * i + 3), 8 * i);
      vertices.set(mesh.normals.subarray(3 * i, 3 * i + 3), 8 * i + 3);
      vertices.set(mesh.uvs.subarray(2 * i, 2 * i + 2), 8 * i + 6);
    }
    this.triangles = gl.createVertexArray()!;
    gl.bindVertexArray(this.triangles);
    this.arrayBuffer(vertices);
    this.attributes([[0, 3], [1, 3], [2, 2]], 0);
    const indices = mesh.indices;
    this.buffers.push(gl.createBuffer()!);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.buffers[this.buffers.length - 1]);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    this.indexCount = indices.length;
    this.triangleCount = indices.length / 3;

    if (adjacency && adjacency.length) {
      this.edgeCount = adjacency.length / 4;
      this.finVao = gl.createVertexArray()!;
      gl.bindVertexArray(this.finVao);
      this.arrayBuffer(edgeInstances(mesh, adjacency));
      this.attributes([[3, 3], [4, 3], [5, 3], [6, 3], [7, 3], [8, 3], [9, 2], [10, 2]], 1);
    }
    if (strands) {
      const data = new Float32Array(24 * this.triangleCount);
      for (let t = 0; t < this.triangleCount; ++t) {
        for (let k = 0; k < 3; ++k) {
          const v = indices[3 * t + k]!;
          data.set(mesh.positions.subarray(3 * v, 3 * v + 3), 24 * t + 3 * k);
          data.set(mesh.normals.subarray(3 * v, 3 * v + 3), 24 * t + 9 + 3 * k);
          data.set(mesh.uvs.subarray(2 * v, 2 * v + 2), 24 * t + 18 + 2 * k);
        }
      }
      this.strandVao = gl.createVertexArray()!;
      gl.bindVertexArray(this.strandVao);
      this.arrayBuffer(data);
      this.attributes([[3, 3], [4, 3], [5, 3], [6, 3], [7, 3], [8, 3], [9, 2], [10, 2], [11, 2]], strands.perTriangle);
    }
    gl.bindVertexArray(null);
  }

  private arrayBuffer(data: Float32Array): void {
    const gl = this.gl, b = gl.createBuffer()!;
    this.buffers.push(b);
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
  }

  // Interleaved float attributes [location, size]; DIVISOR 0 per vertex, else per DIVISOR instances.
  private attributes(list: [number, number][], divisor: number): void {
    const gl = this.gl;
    const stride = 4 * list.reduce((s, [, size]) => s + size, 0);
    let offset = 0;
    for (const [loc, size] of list) {
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, size, gl.FLOAT, false, stride, offset);
      gl.vertexAttribDivisor(loc, divisor);
      offset += 4 * size;
    }
  }

  drawTriangles(): void {
    const gl = this.gl;
    gl.bindVertexArray(this.triangles);
    gl.drawElements(gl.TRIANGLES, this.indexCount, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
  }

  drawFins(): void {
    if (!this.finVao) return;
    const gl = this.gl;
    gl.bindVertexArray(this.finVao);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, this.edgeCount);
    gl.bindVertexArray(null);
  }

  drawStrands(): void {
    if (!this.strandVao || !this.strands) return;
    const gl = this.gl;
    gl.bindVertexArray(this.strandVao);
    gl.drawArraysInstanced(gl.LINE_STRIP, 0, this.strands.vertices, this.triangleCount * this.strands.perTriangle);
    gl.bindVertexArray(null);
  }

  dispose(): void {
    const gl = this.gl;
    for (const v of [this.triangles, this.finVao, this.strandVao]) if (v) gl.deleteVertexArray(v);
    for (const b of this.buffers) gl.deleteBuffer(b);
  }
}
