// A linked WebGL 2 program from two shaders the core assembled; compile and
// link errors come back with the student's file:line (the core's
// mapCompilerLog, native's own). Built without blocking the page where the
// browser offers KHR_parallel_shader_compile: the driver compiles and links
// in the background while the page keeps answering (a switch of stage shows
// what is being built instead of freezing).
import type { Core, CoreSource } from '../core/core.js';

export class ShaderError extends Error {}

// (A browser's log may end in a NUL character; the mapped log in a newline.)
function mapCompilerLog(core: Core, log: string, source: CoreSource): string {
  return core.mapCompilerLog(log.replace(/\0/g, ''), JSON.stringify(source)).replace(/\n$/, '');
}

// How often a background build is asked whether it is done.
const POLL_MS = 4;

export class Program {
  private locations = new Map<string, WebGLUniformLocation | null>();

  private constructor(private gl: WebGL2RenderingContext, readonly id: WebGLProgram) {}

  // Throws ShaderError naming the file and line of the first problem.
  // FEEDBACK: outputs transform feedback captures, interleaved in this order.
  static async build(gl: WebGL2RenderingContext, core: Core, vertex: CoreSource, fragment: CoreSource,
    feedback: string[] = []): Promise<Program> {
    const shader = (type: number, source: CoreSource) => {
      const s = gl.createShader(type)!;
      gl.shaderSource(s, source.text);
      gl.compileShader(s);
      return s;
    };
    const vs = shader(gl.VERTEX_SHADER, vertex), fs = shader(gl.FRAGMENT_SHADER, fragment);
    const p = gl.createProgram()!;
    gl.attachShader(p, vs);
    gl.attachShader(p, fs);
    gl.bindAttribLocation(p, 0, 'aCorner');
    if (feedback.length) gl.transformFeedbackVaryings(p, feedback, gl.INTERLEAVED_ATTRIBS);
    gl.linkProgram(p);
    const parallel = gl.getExtension('KHR_parallel_shader_compile');
    if (parallel)
      while (!gl.getProgramParameter(p, parallel.COMPLETION_STATUS_KHR)) await new Promise((r) => setTimeout(r, POLL_MS));
    try {
      for (const [s, source, what] of [[vs, vertex, 'vertex'], [fs, fragment, 'fragment']] as const)
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS))
          throw new ShaderError(`${what} shader does not compile:\n${mapCompilerLog(core, gl.getShaderInfoLog(s) ?? '', source)}`);
      if (!gl.getProgramParameter(p, gl.LINK_STATUS))
        throw new ShaderError(`the program does not link:\n${mapCompilerLog(core, gl.getProgramInfoLog(p) ?? '', feedback.length ? vertex : fragment)}`);
    } catch (e) {
      gl.deleteProgram(p);
      throw e;
    } finally {
      gl.deleteShader(vs);
      gl.deleteShader(fs);
    }
    return new Program(gl, p);
  }

  // null when the program does not use NAME (the compiler removed it).
  uniform(name: string): WebGLUniformLocation | null {
    if (!this.locations.has(name)) this.locations.set(name, this.gl.getUniformLocation(this.id, name));
    return this.locations.get(name)!;
  }

  dispose(): void {
    this.gl.deleteProgram(this.id);
  }
}
