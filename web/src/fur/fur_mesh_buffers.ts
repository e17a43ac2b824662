// The mesh on the GPU for the fur track (native: fur/mesh_buffers.cpp):
// vertices (position, normal, uv at locations 0, 1, 2) and triangles for the
// skin and shells. Fins and strands read the mesh through their emulated
// geometry shaders' own corner buffers (gl/emulated_geometry_pass.ts).

// A mesh as the core gives it (native: fur/mesh/mesh.h).
export interface MeshArrays {
  positions: Float32Array;  // x, y, z per vertex
  normals: Float32Array;    // x, y, z per vertex, unit length
  uvs: Float32Array;        // u, v per vertex
  indices: Uint32Array;     // three per triangle
}

export class FurMeshBuffers {
  private triangles: WebGLVertexArrayObject;
  private buffers: WebGLBuffer[] = [];
  private indexCount: number;

  constructor(private gl: WebGL2RenderingContext, mesh: MeshArrays) {
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
    this.attributes([[0, 3], [1, 3], [2, 2]]);
    const indices = mesh.indices;
    this.buffers.push(gl.createBuffer()!);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.buffers[this.buffers.length - 1]);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    this.indexCount = indices.length;
    gl.bindVertexArray(null);
  }

  private arrayBuffer(data: Float32Array): void {
    const gl = this.gl, b = gl.createBuffer()!;
    this.buffers.push(b);
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
  }

  // Interleaved float attributes [location, size], per vertex.
  private attributes(list: [number, number][]): void {
    const gl = this.gl;
    const stride = 4 * list.reduce((s, [, size]) => s + size, 0);
    let offset = 0;
    for (const [loc, size] of list) {
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, size, gl.FLOAT, false, stride, offset);
      offset += 4 * size;
    }
  }

  drawTriangles(): void {
    const gl = this.gl;
    gl.bindVertexArray(this.triangles);
    gl.drawElements(gl.TRIANGLES, this.indexCount, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteVertexArray(this.triangles);
    for (const b of this.buffers) gl.deleteBuffer(b);
  }
}
