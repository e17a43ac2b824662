// A linked WebGL 2 program from two shaders the core assembled; compile and
// link errors come back with the student's file:line (the core's
// mapCompilerLog, native's own).
import type { Core, CoreSource } from '../core/core.js';

export class ShaderError extends Error {}

// (A browser's log may end in a NUL character; the mapped log in a newline.)
function mapCompilerLog(core: Core, log: string, source: CoreSource): string {
  return core.mapCompilerLog(log.replace(/\0/g, ''), JSON.stringify(source)).replace(/\n$/, '');
}

function compile(gl: WebGL2RenderingContext, core: Core, type: number, source: CoreSource, what: string): WebGLShader {
  const shader = gl.createShader(type)!;
  gl.shaderSource(shader, source.text);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    const log = mapCompilerLog(core, gl.getShaderInfoLog(shader) ?? '', source);
    gl.deleteShader(shader);
    throw new ShaderError(`${what} shader does not compile:\n${log}`);
  }
  return shader;
}

export class Program {
  readonly id: WebGLProgram;
  private locations = new Map<string, WebGLUniformLocation | null>();

  constructor(private gl: WebGL2RenderingContext, core: Core, vertex: CoreSource, fragment: CoreSource) {
    const vs = compile(gl, core, gl.VERTEX_SHADER, vertex, 'vertex');
    let fs: WebGLShader;
    try {
      fs = compile(gl, core, gl.FRAGMENT_SHADER, fragment, 'fragment');
    } catch (e) {
      gl.deleteShader(vs);
      throw e;
    }
    const p = gl.createProgram()!;
    gl.attachShader(p, vs);
    gl.attachShader(p, fs);
    gl.bindAttribLocation(p, 0, 'aCorner');
    gl.linkProgram(p);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) {
      const log = gl.getProgramInfoLog(p) ?? '';
      gl.deleteProgram(p);
      throw new ShaderError(`the program does not link:\n${mapCompilerLog(core, log, fragment)}`);
    }
    this.id = p;
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
