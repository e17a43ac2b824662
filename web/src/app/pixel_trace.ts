// One pixel's path in the page, from the student's own shader (native's
// `raylab trace` prints the reference tracer's): the core's trace build
// (framework/src/core/trace_recording.h) records each ray findClosest()
// traces. Each record is one draw of the whole program for that pixel: the
// picture's viewport is placed so that the pixel lands on the record's
// column of a one-row float target with four attachments; column 0 holds
// the pixel's colour and how many rays there were. The core words the
// report as `raylab trace` does.
import type { Camera } from './camera.js';
import type { Catalog, Sources, StageJson } from '../course/catalog.js';
import type { RenderSettings } from '../raytrace/render_settings.js';
import { StageRenderer } from '../raytrace/stage_renderer.js';
import { loadStage } from '../tracks/track_registry.js';

// The most rays a report lists (a path of depth 8 with shadow rays stays far below).
const MAX_RECORDS = 1024;
const ATTACHMENTS = 4;

// A one-row float target of WIDTH columns, four RGBA32F attachments.
function recordTarget(gl: WebGL2RenderingContext, width: number) {
  if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('this browser cannot draw into float pictures (no EXT_color_buffer_float)');
  const fbo = gl.createFramebuffer()!;
  const textures: WebGLTexture[] = [];
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  for (let a = 0; a < ATTACHMENTS; ++a) {
    const t = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, 1);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + a, gl.TEXTURE_2D, t, 0);
    textures.push(t);
  }
  gl.drawBuffers(textures.map((_, a) => gl.COLOR_ATTACHMENT0 + a));
  const read = (columns: number) => textures.map((_, a) => {
    const out = new Float32Array(4 * columns);
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + a);
    gl.readPixels(0, 0, columns, 1, gl.RGBA, gl.FLOAT, out);
    return out;
  });
  const dispose = () => {
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fbo);
    for (const t of textures) gl.deleteTexture(t);
  };
  return { read, dispose };
}

export interface PixelTraceRequest {
  stage: StageJson;
  sources: Sources;
  sceneName: string;
  camera: Camera;
  time: number;
  settings: RenderSettings;
  width: number;   // the picture's size
  height: number;
  x: number;       // the pixel, 0,0 top left
  y: number;
}

// The path of R's pixel, in the words of `raylab trace`. Throws Error
// (a stage without the ray tracer, a compile error with its file and line).
export async function tracePixel(gl: WebGL2RenderingContext, catalog: Catalog, r: PixelTraceRequest): Promise<string> {
  if (r.stage.track !== 'raytrace') throw new Error('a pixel\'s path is the ray tracer\'s (a fur stage draws no rays)');
  const loaded = await loadStage(gl, catalog, r.stage, r.sources, r.sceneName, { trace: true });
  const renderer = loaded.renderer;
  let target: ReturnType<typeof recordTarget> | null = null;
  try {
    if (!(renderer instanceof StageRenderer)) throw new Error('a pixel\'s path is the ray tracer\'s');
    // The pixel's row counted from the bottom, as GL counts.
    const row = r.height - 1 - r.y;
    const draw = (record: number) => renderer.render(r.camera, r.time, r.settings, r.width, r.height,
      { x: record - r.x, y: -row, record });
    target = recordTarget(gl, MAX_RECORDS + 1);
    // One column per draw: the picture's other pixels fall on the other columns.
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(0, 0, 1, 1);
    draw(0);
    const summary = target.read(1)[0]!;
    const calls = Math.min(MAX_RECORDS, Math.round(summary[3]!));
    for (let k = 1; k <= calls; ++k) {
      gl.scissor(k, 0, 1, 1);
      draw(k);
    }
    gl.disable(gl.SCISSOR_TEST);
    const columns = target.read(calls + 1);
    // 16 floats per call: the four attachments' RGBA of its column.
    const records = new Float32Array(16 * calls);
    for (let k = 0; k < calls; ++k)
      for (let a = 0; a < ATTACHMENTS; ++a) records.set(columns[a]!.subarray(4 * (k + 1), 4 * (k + 2)), 16 * k + 4 * a);
    return renderer.traceReport(summary, records, r.x, r.y, r.width, r.height);
  } finally {
    gl.disable(gl.SCISSOR_TEST);
    target?.dispose();
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    renderer.dispose();
  }
}

// The page's "Trace a pixel" button: the next click on the picture traces
// that pixel; the report goes to the messages.
export class PixelTraceButton {
  private armed = false;

  constructor(private gl: WebGL2RenderingContext, private catalog: Catalog, private canvas: HTMLCanvasElement,
    button: HTMLButtonElement, shownStage: () => StageJson | null,
    state: () => Promise<Omit<PixelTraceRequest, 'x' | 'y'> | null>, show: (text: string, isError: boolean) => void) {
    button.onclick = () => {
      const stage = shownStage();
      if (!stage || stage.track !== 'raytrace') return show('Trace a pixel: pick a ray-tracing stage first (a fur stage draws no rays).', true);
      this.armed = true;
      canvas.style.cursor = 'crosshair';
      show('Trace a pixel: click the pixel whose path you want.', false);
    };
    // Before the page's own handlers: a traced click does not look around.
    canvas.addEventListener('pointerdown', (e) => {
      if (!this.armed) return;
      e.stopImmediatePropagation();
      this.armed = false;
      canvas.style.cursor = '';
      const box = canvas.getBoundingClientRect();
      const x = Math.min(canvas.width - 1, Math.floor(((e.clientX - box.left) / box.width) * canvas.width));
      const y = Math.min(canvas.height - 1, Math.floor(((e.clientY - box.top) / box.height) * canvas.height));
      show(`tracing pixel ${x},${y}…`, false);
      state().then((s) => {
        if (!s) throw new Error('nothing is drawn to trace');
        return tracePixel(this.gl, this.catalog, { ...s, x, y });
      }).then((report) => show(report, false), (err: Error) => show(err.message, true));
    }, true);
  }
}
