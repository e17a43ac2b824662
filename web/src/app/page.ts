// The page: pick a stage, where its code comes from (the solution, labs/ as
// handed out, or the student's own folder from disk) and a scene; fly
// around with the native window's keys; read the frame time and the switches
// in the overlay; save a screenshot.
import { Camera, flyThroughPose } from './camera.js';
import { frameOfView } from './frame.js';
import { labFromFiles } from './lab_folder.js';
import { type Catalog, type Sources, type StageJson, stageById } from '../course/catalog.js';
import { applyFurKey, applySettingsKey, COLOR_MODES, defaultSettings, FUR_TECHNIQUES, type RenderSettings } from '../raytrace/render_settings.js';
import { loadStage } from '../tracks/track_registry.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;
const MOVE_UNITS_PER_SECOND = 2.5;  // as natively (app/viewer_app.cpp)
const LOOK_DEGREES_PER_PIXEL = 0.2;
const FRAME_WINDOW = 30;  // frames in the overlay's median

export class Page {
  private renderer: TrackRenderer | null = null;
  private camera = new Camera({ position: [0, 0, 0], yawDeg: 0, pitchDeg: 0 }, 36.87);
  private settings: RenderSettings = defaultSettings();
  private time = 0;
  private paused = false;
  private vsync = true;
  private last = 0;
  private intervals: number[] = [];
  private held = new Set<string>();
  private note = '';
  private disk: Sources | null = null;
  private loading = 0;
  private demo = false;
  private track = 'raytrace';
  private sceneShells = 0;

  constructor(readonly gl: WebGL2RenderingContext, readonly canvas: HTMLCanvasElement, readonly catalog: Catalog) {}

  start(): void {
    const stageSel = $<HTMLSelectElement>('stage');
    for (const { info } of this.catalog.stages) {
      const o = new Option(`${info.id}: ${info.title}`, info.id);
      stageSel.add(o);
    }
    stageSel.value = this.catalog.stages.filter((s) => s.info.features.includes('demo') && s.info.track === 'raytrace').pop()?.info.id ?? '';
    stageSel.onchange = () => { this.demo = false; this.fillScenes(); void this.load(); };
    $<HTMLSelectElement>('source').onchange = (e) => {
      if ((e.target as HTMLSelectElement).value === 'disk') $<HTMLInputElement>('folder').click();
      else void this.load();
    };
    $<HTMLInputElement>('folder').onchange = async (e) => {
      const files = (e.target as HTMLInputElement).files;
      try {
        this.disk = await labFromFiles(files ?? [], this.stage().id);
        void this.load();
      } catch (err) {
        this.showError(String((err as Error).message));
      }
    };
    $<HTMLSelectElement>('scene').onchange = () => void this.load();
    $<HTMLSelectElement>('size').onchange = () => this.resize();
    $('demo-lite').onclick = () => this.startDemo('lite.json');
    $('demo-pro').onclick = () => this.startDemo('pro.json');
    $('demo-fur').onclick = () => this.startDemo('fur/sphere.json', 'fur');
    $('shot').onclick = () => this.screenshot();
    this.bindInput();
    this.fillScenes();
    this.resize();
    void this.load();
    this.schedule();
  }

  private stage(): StageJson {
    return stageById(this.catalog, $<HTMLSelectElement>('stage').value);
  }

  private fillScenes(): void {
    const sel = $<HTMLSelectElement>('scene');
    const own = this.stage().scene;
    sel.innerHTML = '';
    const ofTrack = (name: string) => name.startsWith('fur/') === (this.stage().track === 'fur');
    for (const name of [own, ...this.catalog.scenes.filter((s) => s !== own && ofTrack(s))]) sel.add(new Option(name === own ? `${name} (the stage's)` : name, name));
  }

  private resize(): void {
    const [w, h] = $<HTMLSelectElement>('size').value.split('x').map(Number);
    this.canvas.width = w;
    this.canvas.height = h;
  }

  private startDemo(scene: string, track = 'raytrace'): void {
    const full = this.catalog.stages.filter((s) => s.info.track === track && s.info.features.includes('demo')).pop();
    if (!full) return;
    $<HTMLSelectElement>('stage').value = full.info.id;
    $<HTMLSelectElement>('source').value = 'solution';
    this.fillScenes();
    $<HTMLSelectElement>('scene').value = scene;
    this.demo = track === 'raytrace';  // the fly-through; fur scenes spin by themselves
    void this.load();
  }

  private sources(): Sources {
    const kind = $<HTMLSelectElement>('source').value;
    if (kind === 'disk' && this.disk) return this.disk;
    return { kind: kind === 'lab' ? 'lab' : 'solution' };
  }

  // Builds the renderer for the current choices; a failure leaves the
  // message (file:line for compile errors) and a black picture.
  async load(): Promise<void> {
    const ticket = ++this.loading;
    const stage = this.stage();
    this.renderer?.dispose();
    this.renderer = null;
    this.track = stage.track;
    $('title').textContent = `${stage.id}: ${stage.title}`;
    const sceneName = $<HTMLSelectElement>('scene').value || stage.scene;
    this.showMessage('compiling…');
    try {
      const loaded = await loadStage(this.gl, this.catalog, stage, this.sources(), sceneName);
      if (ticket !== this.loading) return loaded.renderer.dispose();
      this.renderer = loaded.renderer;
      this.sceneShells = Number(/(\d+) shells/.exec(loaded.summary)?.[1] ?? 0);
      this.camera = frameOfView(loaded.camera, loaded.fovYDeg).camera;
      this.time = 0;
      const todos = loaded.renderer.todos.map((t) => `${t.file}:${t.line}: ${t.title}`);
      const notes = loaded.renderer.notes.map((n) => `Web build: ${n}.`);
      this.showMessage([
        todos.length ? `Unfinished (the magenta stripes):\n${todos.join('\n')}` : `Ready: ${loaded.summary}.`,
        ...notes,
      ].join('\n\n'));
    } catch (e) {
      if (ticket === this.loading) this.showError((e as Error).message);
    }
  }

  showMessage(text: string): void {
    const m = $('messages');
    m.className = '';
    m.textContent = text;
  }

  showError(text: string): void {
    const m = $('messages');
    m.className = 'error';
    m.textContent = text;
    this.gl.clearColor(0, 0, 0, 1);
    this.gl.clear(this.gl.COLOR_BUFFER_BIT);
  }

  private bindInput(): void {
    const c = this.canvas;
    c.addEventListener('keydown', (e) => {
      const changed = this.track === 'fur'
        ? applyFurKey(this.settings, e.key, this.sceneShells)
        : applySettingsKey(this.settings, e.key);
      if (changed) this.note = changed;
      else if (e.key === 'p' || e.key === 'P') { this.paused = !this.paused; this.note = this.paused ? 'paused' : 'running'; }
      else if (e.key === 'v' || e.key === 'V') { this.vsync = !this.vsync; this.note = `vsync ${this.vsync ? 'on' : 'off'}`; }
      else if (e.key === 'F12') this.screenshot();
      else if (e.key === 'Escape') c.blur();
      else { this.held.add(e.key.toLowerCase()); return; }
      e.preventDefault();
    });
    c.addEventListener('keyup', (e) => this.held.delete(e.key.toLowerCase()));
    c.addEventListener('blur', () => this.held.clear());
    c.addEventListener('pointerdown', (e) => { c.focus(); c.setPointerCapture(e.pointerId); });
    c.addEventListener('pointermove', (e) => {
      if (!c.hasPointerCapture(e.pointerId)) return;
      this.camera.turn(e.movementX * LOOK_DEGREES_PER_PIXEL, -e.movementY * LOOK_DEGREES_PER_PIXEL);
    });
  }

  private schedule(): void {
    if (this.vsync) requestAnimationFrame(() => this.frame());
    else setTimeout(() => this.frame(), 0);
  }

  private frame(): void {
    const now = performance.now();
    const dt = this.last ? (now - this.last) / 1000 : 0;
    if (this.last) this.intervals = [...this.intervals, now - this.last].slice(-FRAME_WINDOW);
    this.last = now;
    if (!this.paused) this.time += dt;
    const step = MOVE_UNITS_PER_SECOND * dt;
    const k = this.held;
    this.camera.move(((k.has('w') ? 1 : 0) - (k.has('s') ? 1 : 0)) * step, ((k.has('d') ? 1 : 0) - (k.has('a') ? 1 : 0)) * step);
    if (this.renderer) {
      const camera = this.demo ? new Camera(flyThroughPose(this.camera.pose, this.time * 10), this.camera.fovYDeg) : this.camera;
      this.renderer.render(camera, this.time, this.settings, this.canvas.width, this.canvas.height);
      this.updateOverlay();
    }
    this.schedule();
  }

  private updateOverlay(): void {
    const sorted = [...this.intervals].sort((a, b) => a - b);
    const median = sorted.length ? sorted[sorted.length >> 1] : 0;
    const s = this.settings, on = (b: boolean) => (b ? 'on' : 'off');
    $('overlay').textContent =
      `${this.stage().id}  ${this.canvas.width}x${this.canvas.height}\n` +
      `frame ${median.toFixed(1)} ms (${median ? (1000 / median).toFixed(1) : '-'} fps)${this.vsync ? ', vsync' : ''}\n` +
      (this.track === 'fur'
        ? `shells ${s.shells || this.sceneShells}  fins ${on(s.fins)}  length x${s.furLength.toPrecision(3)}\n` +
          `technique ${FUR_TECHNIQUES[s.furTechnique]}\n`
        : `shadows ${on(s.shadows)}  depth ${s.maxDepth}  glow ${on(s.glow)}\n` +
          `normal maps ${on(s.normalMaps)}  colour ${COLOR_MODES[s.colorMode]}\n`) +
      `time ${this.time.toFixed(1)} s${this.paused ? ' (paused)' : ''}${this.note ? `\n${this.note}` : ''}`;
  }

  screenshot(): void {
    this.canvas.toBlob((blob) => {
      if (!blob) return;
      const a = document.createElement('a');
      a.href = URL.createObjectURL(blob);
      a.download = `raylab-${this.stage().id}.png`;
      a.click();
      setTimeout(() => URL.revokeObjectURL(a.href), 1000);
    }, 'image/png');
  }
}
