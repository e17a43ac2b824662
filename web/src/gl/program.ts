// A linked WebGL 2 program from two assembled shaders; compile and link
// errors come back with the student's file:line (mapCompilerLog).
import { mapCompilerLog, ShaderError, type ShaderSource } from '../shader/shader_source.js';

function compile(gl: WebGL2RenderingContext, type: number, source: ShaderSource, what: string): WebGLShader {
  const shader = gl.createShader(type)!;
  gl.shaderSource(shader, source.text);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    const log = mapCompilerLog(gl.getShaderInfoLog(shader) ?? '', source);
    gl.deleteShader(shader);
    throw new ShaderError(`${what} shader does not compile:\n${log}`);
  }
  return shader;
}

export class Program {
  readonly id: WebGLProgram;
  private locations = new Map<string, WebGLUniformLocation | null>();

  constructor(private gl: WebGL2RenderingContext, vertex: ShaderSource, fragment: ShaderSource) {
    const vs = compile(gl, gl.VERTEX_SHADER, vertex, 'vertex');
    let fs: WebGLShader;
    try {
      fs = compile(gl, gl.FRAGMENT_SHADER, fragment, 'fragment');
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
      throw new ShaderError(`the program does not link:\n${mapCompilerLog(log, fragment)}`);
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
