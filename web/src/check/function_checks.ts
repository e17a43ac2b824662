// The function checks in WebGL 2 (native: framework/src/grading/
// function_harness.cpp): each harness program the core assembled draws one
// pixel per case into a one-row float target, reading the case's inputs from
// a float texture; the core scores what it wrote against its double
// references. Only the drawing is here.
import type { Core, CheckSessionHandle, FunctionCheckInfo } from '../core/core.js';
import { Program } from '../gl/program.js';
import { CheckTarget } from './check_target.js';

// A full-screen quad at attribute 0 (the canvas.vert's aCorner).
function quad(gl: WebGL2RenderingContext): { vao: WebGLVertexArrayObject; buffer: WebGLBuffer } {
  const vao = gl.createVertexArray()!;
  gl.bindVertexArray(vao);
  const buffer = gl.createBuffer()!;
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, -1, 1, 1, -1, 1, 1]), gl.STATIC_DRAW);
  gl.enableVertexAttribArray(0);
  gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
  gl.bindVertexArray(null);
  return { vao, buffer };
}

function caseTexture(gl: WebGL2RenderingContext, texels: Float32Array, cases: number): WebGLTexture {
  const t = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, cases, 4, 0, gl.RGBA, gl.FLOAT, texels);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  return t;
}

// WebGL refuses to draw a program whose uniform blocks have no buffer
// (native leaves them unread): a harness that includes a scene file
// declaring one (the spheres' blocks) gets zero-filled buffers, never read.
function bindEmptyUniformBlocks(gl: WebGL2RenderingContext, program: WebGLProgram): WebGLBuffer[] {
  const buffers: WebGLBuffer[] = [];
  const blocks = Number(gl.getProgramParameter(program, gl.ACTIVE_UNIFORM_BLOCKS));
  for (let i = 0; i < blocks; ++i) {
    const size = Number(gl.getActiveUniformBlockParameter(program, i, gl.UNIFORM_BLOCK_DATA_SIZE));
    const buffer = gl.createBuffer()!;
    gl.bindBuffer(gl.UNIFORM_BUFFER, buffer);
    gl.bufferData(gl.UNIFORM_BUFFER, size, gl.STATIC_DRAW);
    gl.uniformBlockBinding(program, i, i);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, i, buffer);
    buffers.push(buffer);
  }
  return buffers;
}

// Runs the stage's function checks for LAB (the core's path; '' for the
// solution) and records each outcome in SESSION.
export async function runFunctionChecks(gl: WebGL2RenderingContext, core: Core, session: CheckSessionHandle, stage: string, lab: string): Promise<void> {
  const checks = new core.FunctionChecks(JSON.stringify({ stage, lab }));
  try {
    const error = checks.error();
    if (error) throw new Error(error);
    const { vao, buffer } = quad(gl);
    try {
      for (const f of JSON.parse(checks.list()) as FunctionCheckInfo[]) {
        if (f.error || !f.vertex || !f.fragment) {
          session.addFunctionNotBuilt(f.name, f.error ?? 'no harness');
          continue;
        }
        let program: Program;
        try {
          program = await Program.build(gl, core, f.vertex, f.fragment);
        } catch (e) {
          session.addFunctionNotBuilt(f.name, (e as Error).message);
          continue;
        }
        const texture = caseTexture(gl, checks.texels(f.name), f.cases);
        const target = new CheckTarget(gl, f.cases, 1, false);
        const blocks = bindEmptyUniformBlocks(gl, program.id);
        try {
          target.bind();
          gl.useProgram(program.id);
          gl.activeTexture(gl.TEXTURE0);
          gl.bindTexture(gl.TEXTURE_2D, texture);
          gl.uniform1i(program.uniform('uCases'), 0);
          gl.bindVertexArray(vao);
          if (!f.perCase) {
            gl.drawArrays(gl.TRIANGLES, 0, 6);
          } else {  // each case with its own uniforms: one pixel at a time
            gl.enable(gl.SCISSOR_TEST);
            f.uniforms.forEach((uniforms, i) => {
              for (const [name, value] of uniforms) gl.uniform1i(program.uniform(name), value);
              gl.scissor(i, 0, 1, 1);
              gl.drawArrays(gl.TRIANGLES, 0, 6);
            });
            gl.disable(gl.SCISSOR_TEST);
          }
          gl.bindVertexArray(null);
          target.unbind();
          const scored = JSON.parse(session.addFunction(f.name, target.readFloats())) as { error?: string };
          if (scored.error) throw new Error(scored.error);
        } finally {
          target.dispose();
          for (const b of blocks) gl.deleteBuffer(b);
          gl.deleteTexture(texture);
          program.dispose();
        }
      }
    } finally {
      gl.deleteVertexArray(vao);
      gl.deleteBuffer(buffer);
    }
  } finally {
    checks.delete();
  }
}
