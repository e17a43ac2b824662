// The spheres' centres on the GPU (native: framework/src/raytrace/sphere_blocks.cpp):
// a uniform buffer behind the shaders' block SphereGeometry (uSpheres,
// framework/shaders/scene_spheres.glsl). A block, not a plain uniform array:
// plain uniforms share MAX_FRAGMENT_UNIFORM_VECTORS (WebGL 2 guarantees 224)
// with everything else, a block holds MAX_UNIFORM_BLOCK_SIZE bytes (WebGL 2
// guarantees 16 KB: 1024 spheres; desktop browsers offer 64 KB) on its own.
// The web compiles the specialised program only, where the spheres' colours
// and materials are constants: this one block is all it needs.
import type { Scene } from '../scene/scene.js';
import { offsetAt } from '../scene/scene.js';
import { SceneLimitError } from './scene_limit_error.js';

// Bytes one sphere takes (std140: a vec4 per array element).
export const SPHERE_BLOCK_STRIDE = 16;
const BINDING_POINT = 0;

// Refuses, in one line naming the limit, a scene with more spheres than the
// browser's uniform blocks hold.
export function checkSpheresFitBlock(scene: Scene, maxBlockBytes: number, shown: string): void {
  const most = Math.floor(maxBlockBytes / SPHERE_BLOCK_STRIDE);
  if (scene.spheres.length > most)
    throw new SceneLimitError(`${shown}: spheres: ${scene.spheres.length} spheres, but this browser's uniform blocks hold ` +
      `at most ${most} (MAX_UNIFORM_BLOCK_SIZE ${maxBlockBytes} bytes, ${SPHERE_BLOCK_STRIDE} per sphere)`);
}

export class SphereBlock {
  private buffer: WebGLBuffer;
  private centres: Float32Array;
  private firstMoving: number;
  private endMoving = 0;  // [firstMoving, endMoving) holds every moving sphere
  private shownTime = 0;

  // The buffer holds the block's whole declared array (MAX_SPHERES, at
  // least one entry): WebGL refuses to draw with a smaller one.
  constructor(private gl: WebGL2RenderingContext, private scene: Scene) {
    const n = Math.max(1, scene.spheres.length);
    this.centres = new Float32Array(4 * n);
    this.firstMoving = scene.spheres.length;
    scene.spheres.forEach((s, i) => {
      this.place(i, 0);
      if (s.motion.amplitude !== 0) {
        this.firstMoving = Math.min(this.firstMoving, i);
        this.endMoving = i + 1;
      }
    });
    this.buffer = gl.createBuffer()!;
    gl.bindBuffer(gl.UNIFORM_BUFFER, this.buffer);
    gl.bufferData(gl.UNIFORM_BUFFER, this.centres, this.endMoving > 0 ? gl.DYNAMIC_DRAW : gl.STATIC_DRAW);
    gl.bindBuffer(gl.UNIFORM_BUFFER, null);
  }

  // Ties PROGRAM's block to the binding point (once per program).
  static attach(gl: WebGL2RenderingContext, program: WebGLProgram): void {
    const index = gl.getUniformBlockIndex(program, 'SphereGeometry');
    if (index !== gl.INVALID_INDEX) gl.uniformBlockBinding(program, index, BINDING_POINT);
  }

  // Moves the spheres with a motion to time T (only their range is
  // uploaded; nothing when none moves) and binds the buffer.
  bindAt(timeSeconds: number): void {
    const gl = this.gl;
    if (this.endMoving > 0 && timeSeconds !== this.shownTime) {
      this.shownTime = timeSeconds;
      for (let i = this.firstMoving; i < this.endMoving; ++i) this.place(i, timeSeconds);
      gl.bindBuffer(gl.UNIFORM_BUFFER, this.buffer);
      gl.bufferSubData(gl.UNIFORM_BUFFER, this.firstMoving * SPHERE_BLOCK_STRIDE, this.centres,
        4 * this.firstMoving, 4 * (this.endMoving - this.firstMoving));
      gl.bindBuffer(gl.UNIFORM_BUFFER, null);
    }
    gl.bindBufferBase(gl.UNIFORM_BUFFER, BINDING_POINT, this.buffer);
  }

  dispose(): void {
    this.gl.deleteBuffer(this.buffer);
  }

  private place(i: number, timeSeconds: number): void {
    const s = this.scene.spheres[i]!;
    const o = offsetAt(s.motion, timeSeconds);
    this.centres.set([s.center[0] + o[0], s.center[1] + o[1], s.center[2] + o[2], s.radius], 4 * i);
  }
}
