// The ray tracer's debug views in the page (native: `raylab render --view
// depth|normal|id`, raytrace/debug_views.h): the stage's own shader files
// built from framework/shaders/view_main.frag (the core assembles it), drawn
// into a float picture, turned into a picture for people by the core
// (core/view_pictures.h, native's mapping) and put on the canvas.
import type { Camera } from './camera.js';
import type { StageJson } from '../course/catalog.js';
import { CheckTarget } from '../check/check_target.js';
import type { RenderSettings } from '../raytrace/render_settings.js';
import { StageRenderer } from '../raytrace/stage_renderer.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';

// The views a ray-tracing stage's own shaders can draw; bounces and stack
// count the reference tracer's rays, which only native has.
export const DEBUG_VIEWS = ['color', 'depth', 'normal', 'id'] as const;

// Whether STAGE has the debug views (the ray tracer's).
export const hasDebugViews = (stage: StageJson) => stage.track === 'raytrace';

export class DebugViewPainter {
  private target: CheckTarget | null = null;
  private picture: WebGLTexture | null = null;
  private pictureFbo: WebGLFramebuffer | null = null;

  constructor(private gl: WebGL2RenderingContext) {}

  // Draws RENDERER's debug view into the canvas's framebuffer (WIDTH x
  // HEIGHT) and says what was mapped how ("depth 2.31..41.7 mapped to ...").
  draw(renderer: TrackRenderer, camera: Camera, time: number, settings: RenderSettings, width: number, height: number): string {
    if (!(renderer instanceof StageRenderer)) throw new Error('debug views are the ray tracer\'s');
    const gl = this.gl;
    if (!this.target || this.target.width !== width || this.target.height !== height) {
      this.dispose();
      this.target = new CheckTarget(gl, width, height, false);
      this.picture = gl.createTexture()!;
      gl.bindTexture(gl.TEXTURE_2D, this.picture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, width, height);
      this.pictureFbo = gl.createFramebuffer()!;
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.pictureFbo);
      gl.framebufferTexture2D(gl.READ_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.picture, 0);
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    }
    this.target.bind();
    renderer.render(camera, time, settings, width, height);
    this.target.unbind();
    const { rgba, mapping } = renderer.viewPicture(this.target.readFloats(), width, height);
    // The picture's rows are top-down: uploaded as they are and blitted
    // upside down onto the canvas.
    gl.bindTexture(gl.TEXTURE_2D, this.picture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.pictureFbo);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    gl.blitFramebuffer(0, 0, width, height, 0, height, width, 0, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    return mapping;
  }

  dispose(): void {
    const gl = this.gl;
    this.target?.dispose();
    if (this.picture) gl.deleteTexture(this.picture);
    if (this.pictureFbo) gl.deleteFramebuffer(this.pictureFbo);
    this.target = null;
    this.picture = null;
    this.pictureFbo = null;
  }
}

// The View menu: colour or a debug view, on the stages that have them.
export class DebugViewMenu {
  readonly painter: DebugViewPainter;

  constructor(gl: WebGL2RenderingContext, private select: HTMLSelectElement, private label: HTMLElement, changed: () => void) {
    this.painter = new DebugViewPainter(gl);
    select.onchange = changed;
  }

  // The debug view to build STAGE with (undefined: its colour picture);
  // the menu shows only where the stage has debug views.
  chosen(stage: StageJson): string | undefined {
    this.label.hidden = !hasDebugViews(stage);
    return hasDebugViews(stage) && this.select.value !== 'color' ? this.select.value : undefined;
  }
}
