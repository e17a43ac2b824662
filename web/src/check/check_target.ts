// A check's render target (native: Framebuffer with PixelFormat::
// Rgba32FWithTodoMarks): the picture in 32-bit floats, so that NaN and Inf
// survive to be counted and the 8-bit conversion is native's (the core's
// viewImage), and, where asked, a second attachment in which the program
// marks the pixels that reached a TODO stub (RAYLAB_TODO_MARK). Also the
// one-row target of the function checks' harness.
export class CheckTarget {
  private fbo: WebGLFramebuffer;
  private color: WebGLTexture;
  private marks: WebGLTexture | null = null;
  private depth: WebGLRenderbuffer;

  constructor(private gl: WebGL2RenderingContext, readonly width: number, readonly height: number, withMarks: boolean) {
    if (!gl.getExtension('EXT_color_buffer_float'))
      throw new Error('this browser cannot draw into float pictures (no EXT_color_buffer_float): run raylab check natively');
    gl.getExtension('EXT_float_blend');  // the fur's blended shells on a float target
    const texture = (internal: number, format: number, type: number) => {
      const t = gl.createTexture()!;
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texImage2D(gl.TEXTURE_2D, 0, internal, width, height, 0, format, type, null);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      return t;
    };
    this.fbo = gl.createFramebuffer()!;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
    this.color = texture(gl.RGBA32F, gl.RGBA, gl.FLOAT);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.color, 0);
    if (withMarks) {
      this.marks = texture(gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, this.marks, 0);
    }
    this.depth = gl.createRenderbuffer()!;
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.depth);
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (status !== gl.FRAMEBUFFER_COMPLETE) {
      this.dispose();
      throw new Error(`this browser cannot draw into a check's float picture (framebuffer status 0x${status.toString(16)}): run raylab check natively`);
    }
  }

  // Draws go here until unbind(); the marks start at zero.
  bind(): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
    gl.drawBuffers(this.marks ? [gl.COLOR_ATTACHMENT0, gl.COLOR_ATTACHMENT1] : [gl.COLOR_ATTACHMENT0]);
    gl.viewport(0, 0, this.width, this.height);
    gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, 1]);
    if (this.marks) gl.clearBufferfv(gl.COLOR, 1, [0, 0, 0, 0]);
    gl.clearBufferfi(gl.DEPTH_STENCIL, 0, 1, 0);
  }

  unbind(): void {
    this.gl.bindFramebuffer(this.gl.FRAMEBUFFER, null);
  }

  // RGBA floats, rows bottom-up (as GL reads them).
  readFloats(): Float32Array {
    const gl = this.gl;
    const out = new Float32Array(this.width * this.height * 4);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.fbo);
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
    gl.readPixels(0, 0, this.width, this.height, gl.RGBA, gl.FLOAT, out);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    return out;
  }

  // One byte per pixel (the mark's red), rows bottom-up; empty without marks.
  readMarks(): Uint8Array {
    const gl = this.gl;
    if (!this.marks) return new Uint8Array(0);
    const rgba = new Uint8Array(this.width * this.height * 4);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.fbo);
    gl.readBuffer(gl.COLOR_ATTACHMENT1);
    gl.readPixels(0, 0, this.width, this.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    return rgba.filter((_, i) => i % 4 === 0);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteFramebuffer(this.fbo);
    gl.deleteTexture(this.color);
    if (this.marks) gl.deleteTexture(this.marks);
    gl.deleteRenderbuffer(this.depth);
  }
}
