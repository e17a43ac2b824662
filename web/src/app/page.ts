// The page: pick a stage, where its code comes from (the student's work kept
// in the page and edited there - editor/ -, the solution, labs/ as handed
// out, or the student's own folder from disk) and a scene; fly
// around with the native window's keys; read the frame time and the switches
// in the overlay; save a screenshot.
import { CheckPanel } from './check_panel.js';
import { Camera, type CameraPose, flyThroughPose } from './camera.js';
import { frameOfView } from './frame.js';
import { DebugViewMenu } from './debug_view.js';
import { DiskFolder } from './disk_folder.js';
import { PixelTraceButton } from './pixel_trace.js';
import type { WatchedLab } from './lab_folder.js';
import { downloadZip } from './submission_zip.js';
import { WorkPanel } from '../editor/work_panel.js';
import { type Catalog, type Sources, type StageJson, chain, stageById } from '../course/catalog.js';
import { defaultSettings, type RenderSettings } from '../raytrace/render_settings.js';
import { applySettingsKey, settingsRows } from './settings_keys.js';
import { loadStage } from '../tracks/track_registry.js';
import type { TrackRenderer } from '../tracks/track_renderer.js';

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;
const MOVE_UNITS_PER_SECOND = 3;  // as natively (app/viewer_app.cpp)
const SLOW_FACTOR = 0.2;  // while Shift is held
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
  private held = new Set<string>();
  private note = '';
  private loading = 0;
  private demo = false;
  private sceneShells = 0;
  private shown: StageJson | null = null;  // the stage being drawn (the select can be ahead of it while loading)
  private sourceShown = 'solution';  // the Code choice being drawn (a cancelled picker goes back to it)
  private busy = false;  // a load is under way
  // While a new stage, scene or code is built: what (for the overlay). The
  // old renderer stops drawing (its frames would hold up the build on the
  // same GPU or CPU), its last picture stays, dimmed, labelled with what it is.
  private building: string | null = null;
  private shownLabel = '';  // what the picture on screen is: "08-full (solution) on pro.json"
  // Called with the time of the first frame a finished load draws (tests, the switching benchmark).
  private firstFrameWaiters: ((at: number) => void)[] = [];
  private overlayHidden = false;  // key H

  private checks: CheckPanel;
  private work: WorkPanel;
  private disk: DiskFolder;  // Code: my lab folder…
  private views: DebugViewMenu;  // View: colour, depth, normal, id
  private shownView: string | undefined;  // the debug view drawn (undefined: colour)
  private viewMapping = '';  // what the debug view's picture maps how
  // Said above the first stage's messages where there is no solution (a
  // students' page): where to start.
  private startHere = '';

  constructor(readonly gl: WebGL2RenderingContext, readonly canvas: HTMLCanvasElement, readonly catalog: Catalog) {
    this.checks = new CheckPanel(gl, catalog, $('messages'), $('check-views'), $('check'));
    this.views = new DebugViewMenu(gl, $('view-mode'), $('view-mode-label'), () => void this.load());
    new PixelTraceButton(gl, catalog, canvas, $('trace'), () => this.shown, async () => this.shown && {
      stage: this.shown, sources: await this.sources(), sceneName: $<HTMLSelectElement>('scene').value || this.shown.scene,
      camera: this.camera, time: this.time, settings: this.settings, width: canvas.width, height: canvas.height,
    }, (text, isError) => (isError ? this.showError(text, true) : this.showMessage(text)));
    this.work = new WorkPanel(catalog, () => void this.load(true), (m) => this.showError(m, true));
    this.disk = new DiskFolder(this.stageIds(), {
      opened: (again) => {
        again &&= this.sourceShown === 'disk';
        $<HTMLSelectElement>('source').value = this.sourceShown = 'disk';
        void this.load(again);
      },
      cancelled: () => { $<HTMLSelectElement>('source').value = this.sourceShown; },
      failed: (message) => this.showError(message, true),
    });
  }

  start(): void {
    const stageSel = $<HTMLSelectElement>('stage');
    for (const { info } of this.catalog.stages) {
      // Short: the id and the topic before the title's first colon (the full title is in the side panel).
      const o = new Option(`${info.id}: ${info.title.split(':')[0]}`, info.id);
      o.title = info.title;
      stageSel.add(o);
    }
    // The demo's stage where the solutions are; a students' page (or a
    // bundle of early stages) opens on its first.
    stageSel.value = (this.catalog.solutions ? this.catalog.stages.filter((s) => s.info.features.includes('demo') && s.info.track === 'raytrace').pop()?.info.id : undefined) ??
      this.catalog.stages[0]?.info.id ?? '';
    stageSel.onchange = () => { this.demo = false; this.fillScenes(); void this.load(); };
    if (!this.catalog.solutions) {
      // Labs only: no solution to draw, and the demos draw the solution;
      // the student's work, kept in the page, comes first.
      $<HTMLSelectElement>('source').querySelector('option[value="solution"]')?.remove();
      $<HTMLSelectElement>('source').value = 'work';
      for (const id of ['demo-lite', 'demo-pro', 'demo-fur']) $(id).hidden = true;
      this.startHere = 'Start here: pick your stage, edit its files in the editor (each unfinished TODO is marked), ' +
        'then press Check. Your work is kept in this browser; Download for submission makes the zip to upload.';
    }
    // What the browser kept from before a reload, but a folder (it must be picked again).
    if ($<HTMLSelectElement>('source').value === 'disk') $<HTMLSelectElement>('source').value = this.catalog.solutions ? 'solution' : 'work';
    this.sourceShown = $<HTMLSelectElement>('source').value;
    $<HTMLSelectElement>('source').onchange = (e) => {
      if ((e.target as HTMLSelectElement).value !== 'disk') {
        this.sourceShown = (e.target as HTMLSelectElement).value;
        return void this.load();
      }
      this.disk.pick();
    };
    // A watched folder: a saved file reloads the stage (as the native window does).
    setInterval(() => void this.reloadIfChanged(), 1000);
    $<HTMLSelectElement>('scene').onchange = () => void this.load();
    $<HTMLSelectElement>('size').onchange = () => this.resize();
    $('demo-lite').onclick = () => this.startDemo('lite.json');
    $('demo-pro').onclick = () => this.startDemo('pro.json');
    $('demo-fur').onclick = () => this.startDemo('fur/sphere.json', 'fur');
    $('shot').onclick = () => this.screenshot();
    $('check').onclick = () => void this.check();
    $('submit').onclick = () => void this.downloadSubmission();
    $('import').onclick = () => void this.importFolder();
    this.bindInput();
    // The picture's height limit follows the header's (page.css): its buttons wrap on narrow windows.
    const header = document.querySelector('header')!;
    new ResizeObserver(() => document.documentElement.style.setProperty('--header-height', `${header.offsetHeight}px`)).observe(header);
    this.fillScenes();
    this.resize();
    void this.load();
    this.schedule();
  }

  // The stages STAGE builds on, newest first: a handout's stage folder reads their files.
  private earlierStages(stage: StageJson): string[] {
    return chain(this.catalog, stage).slice(1).map((s) => s.id);
  }

  private stageIds(): string[] {
    return this.catalog.stages.map((s) => s.info.id);
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
    this.sourceShown = 'solution';
    this.fillScenes();
    $<HTMLSelectElement>('scene').value = scene;
    this.demo = track === 'raytrace';  // the fly-through; fur scenes spin by themselves
    void this.load();
  }

  private async sources(): Promise<Sources> {
    const kind = $<HTMLSelectElement>('source').value;
    if (kind === 'work') return this.work.sources(this.stage().id, this.earlierStages(this.stage()));
    if (kind !== 'disk') return { kind: kind === 'lab' ? 'lab' : 'solution' };
    return this.disk.sources(this.stage().id, this.earlierStages(this.stage()));
  }

  private checking = false;
  private async reloadIfChanged(): Promise<void> {
    if (!this.disk.watching || this.checking || this.busy || $<HTMLSelectElement>('source').value !== 'disk') return;
    this.checking = true;
    try {
      const stage = this.shown ?? this.stage();
      const lost = () => this.showError('Your lab folder can no longer be read: pick it again (Code: my lab folder…).', true);
      if (await this.disk.changed(stage.id, this.earlierStages(stage), lost)) await this.load(true);
    } finally {
      this.checking = false;
    }
  }

  // Builds the renderer for the current choices; a failure shows the
  // message (file:line for compile errors). RELOAD (a saved file): the
  // camera and clock stay, and on a failure the last version that compiled
  // keeps running, as in the native window.
  async load(reload = false): Promise<void> {
    const stage = this.stage();
    $('title').textContent = `${stage.id}: ${stage.title}`;
    $<HTMLAnchorElement>('guide-link').href = `guide.html?stage=${encodeURIComponent(stage.id)}`;
    const sceneName = $<HTMLSelectElement>('scene').value || stage.scene;
    const codeKind = $<HTMLSelectElement>('source').value;
    const view = this.views.chosen(stage);
    const label = `${stage.id} (${{ work: 'my work', disk: 'your files', lab: 'labs/' }[codeKind] ?? 'solution'}) on ${sceneName}` +
      (view ? `, ${view} view` : '');
    this.work.show(codeKind === 'work');
    $('import').hidden = codeKind !== 'disk';  // a folder from disk can be kept in the page
    // Another stage, scene or code: the last check's pictures were of something else.
    if (!reload) $('check-views').replaceChildren();
    // What is on screen already is not built again (a demo button for the
    // scene shown, the same choice twice): it starts afresh instead.
    if (!reload && !this.busy && this.renderer && !['disk', 'work'].includes(codeKind) && label === this.shownLabel) {
      this.restart(stage);
      return;
    }
    const ticket = ++this.loading;
    this.busy = true;
    this.building = reload ? `${label}, after your save` : label;
    this.canvas.classList.add('building');
    this.updateOverlay();
    if (!reload) this.showMessage(`building ${label}…`);
    try {
      const sources = await this.sources();
      // The solution gets the demo's levers, as in the native window.
      const loaded = await loadStage(this.gl, this.catalog, stage, sources, sceneName, { demoLevers: true, view });
      if (ticket !== this.loading) return loaded.renderer.dispose();
      this.busy = false;
      this.building = null;
      this.canvas.classList.remove('building');
      this.shownLabel = label;
      this.shownView = view;
      this.renderer?.dispose();
      this.renderer = loaded.renderer;
      this.sceneShells = loaded.sceneShells;
      this.shown = stage;
      this.startPose = { pose: loaded.camera, fovYDeg: loaded.fovYDeg };
      if (!reload) this.restart(stage);
      $('reload').hidden = !(codeKind === 'disk' && !this.disk.watching);
      this.work.loaded(loaded.renderer.todos, '');
      // One entry per TODO, a blank line between them: titles run over lines.
      const todos = loaded.renderer.todos.map((t) => `• ${t.file}:${t.line}\n  ${t.title}`);
      const from = codeKind === 'work' ? `Your files: ${sources.kind === 'disk' ? sources.shown : ''}/, kept in this browser: ` +
        'the picture follows your edits (Ctrl+S: at once).'
        : sources.kind === 'disk'
        ? `Your files: ${sources.shown}/${this.disk.watching ? ' (watched: save a file to reload)' : ' (Reload my files after editing)'}` +
          (reload ? `\nRead again at ${new Date().toLocaleTimeString()}.` : '')
        : '';
      this.showMessage([
        ...(this.startHere ? [this.startHere] : []),
        todos.length ? `Unfinished (magenta stripes where this code runs):\n${todos.join('\n\n')}` : `Ready: ${loaded.summary}.`,
        ...(from ? [from] : []),
      ].join('\n\n'));
      this.startHere = '';  // the first screen's only
    } catch (e) {
      if (ticket !== this.loading) return;
      this.busy = false;
      this.building = null;
      this.canvas.classList.remove('building');
      const message = (e as Error).message;
      this.work.loaded([], message);
      if (reload && this.renderer) {
        this.showError(`${message}\n\n(still showing the last version that compiled)`, true);
        return;
      }
      this.renderer?.dispose();
      this.renderer = null;
      this.shown = null;
      $('overlay').textContent = '';
      this.showError(message);
    }
  }

  showMessage(text: string): void {
    const m = $('messages');
    m.className = '';
    m.textContent = text;
  }

  showError(text: string, keepPicture = false): void {
    const m = $('messages');
    m.className = 'error';
    m.textContent = text;
    if (keepPicture) return;
    this.gl.clearColor(0, 0, 0, 1);
    this.gl.clear(this.gl.COLOR_BUFFER_BIT);
  }

  private bindInput(): void {
    const c = this.canvas;
    c.addEventListener('keydown', (e) => {
      if (e.repeat && e.key.length === 1 && !/[wasd]/i.test(e.key)) return e.preventDefault();  // a held key toggles once
      const changed = this.shown ? applySettingsKey(this.shown, this.settings, e.key, this.sceneShells) : null;
      if (changed) this.note = changed;
      else if (e.key === 'p' || e.key === 'P') { this.paused = !this.paused; this.note = this.paused ? 'paused' : 'running'; }
      else if (e.key === 'v' || e.key === 'V') { this.vsync = !this.vsync; this.note = `vsync ${this.vsync ? 'on' : 'off'}`; }
      else if (e.key === 'F12') this.screenshot();
      else if (e.key === 'c' || e.key === 'C') void this.check();
      else if (e.key === 'h' || e.key === 'H') {
        this.overlayHidden = !this.overlayHidden;
        $('overlay').hidden = this.overlayHidden;
      }
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
    this.last = now;
    if (!this.paused) this.time += dt;
    const step = MOVE_UNITS_PER_SECOND * dt * (this.held.has('shift') ? SLOW_FACTOR : 1);
    const k = this.held;
    this.camera.move(((k.has('w') ? 1 : 0) - (k.has('s') ? 1 : 0)) * step, ((k.has('d') ? 1 : 0) - (k.has('a') ? 1 : 0)) * step);
    try {
      this.drawFrame(now);
    } catch (e) {
      // A frame that throws (a lost context, a driver error) must not stop the loop silently.
      this.renderer?.dispose();
      this.renderer = null;
      this.shown = null;
      this.showError(`Drawing failed: ${(e as Error).message}`);
    }
    this.schedule();
  }

  private startPose: { pose: CameraPose; fovYDeg: number } | null = null;

  // A new stage or scene starts as the native window does: its own camera,
  // the clock at 0, every switch at its default.
  private restart(stage: StageJson): void {
    if (!this.startPose) return;
    const start = frameOfView(this.startPose.pose, this.startPose.fovYDeg, undefined, stage);
    this.camera = start.camera;
    this.settings = start.settings;
    this.time = 0;
    this.paused = false;
    this.note = '';
  }

  // Resolves with the time (performance.now()) at which the next finished
  // load's first frame was drawn.
  firstFrame(): Promise<number> {
    return new Promise((resolve) => this.firstFrameWaiters.push(resolve));
  }

  // The student's lab folder as the zip the graders take (submission_zip.ts).
  private async downloadSubmission(): Promise<void> {
    try {
      const entries = $<HTMLSelectElement>('source').value === 'work' ? await this.work.submission() : await this.disk.submission(this.stage().id);
      if (!entries) throw new Error('the submission is made from your files: choose Code: my work (in this page), or my lab folder…');
      this.showMessage(downloadZip(entries));
    } catch (e) {
      this.showError((e as Error).message, true);
    }
  }

  // Watches LAB as if picked (the tests: a folder in the browser's private file system).
  watchForTest(lab: WatchedLab): void {
    this.disk.watch(lab);
  }

  // The lab folder opened from disk (Code: my lab folder…) kept in the page
  // as the student's work, which the page then shows.
  private async importFolder(): Promise<void> {
    try {
      const entries = await this.disk.submission(this.stage().id);
      if (!entries) throw new Error('pick your lab folder first (Code: my lab folder…)');
      if (!await this.work.import(entries, 'your folder')) return;
      $<HTMLSelectElement>('source').value = this.sourceShown = 'work';
      await this.load();
    } catch (e) {
      this.showError((e as Error).message, true);
    }
  }

  // `raylab check` for what is on screen (one at a time); the picture pauses
  // meanwhile. On the student's work in the page, the verdict is kept.
  private async check(): Promise<void> {
    if (this.busy || this.checks.running) return;
    const stage = this.stage(), work = $<HTMLSelectElement>('source').value === 'work';
    const passed = await this.checks.run(stage, () => this.sources());
    if (work && passed !== null) await this.work.checked(stage.id, passed).catch((e: Error) => this.showError(e.message, true));
  }

  private drawFrame(now: number): void {
    if (this.building || this.checks.running) return this.updateOverlay();
    if (this.renderer) {
      const camera = this.demo ? new Camera(flyThroughPose(this.camera.pose, this.time * 10), this.camera.fovYDeg) : this.camera;
      if (this.shownView) this.viewMapping = this.views.painter.draw(this.renderer, camera, this.time, this.settings, this.canvas.width, this.canvas.height);
      else this.renderer.render(camera, this.time, this.settings, this.canvas.width, this.canvas.height);
      // The frame time: waited for by reading one pixel back (the browser's
      // glFinish), so that it is the drawing's time, not how fast frames are
      // queued - and so that without vsync the queue cannot grow without end.
      this.gl.readPixels(0, 0, 1, 1, this.gl.RGBA, this.gl.UNSIGNED_BYTE, this.pixel);
      this.frameTimes = [...this.frameTimes, performance.now() - now].slice(-FRAME_WINDOW);
      this.updateOverlay();
      const done = performance.now();
      for (const w of this.firstFrameWaiters.splice(0)) w(done);
    }
  }

  private pixel = new Uint8Array(4);
  private frameTimes: number[] = [];

  private updateOverlay(): void {
    const sorted = [...this.frameTimes].sort((a, b) => a - b);
    const median = sorted.length ? sorted[sorted.length >> 1]! : 0;
    if (this.building) {
      // The overlay names what is on screen, and what is coming.
      $('overlay').textContent = [`building ${this.building}…`, ...(this.shown ? [`showing ${this.shownLabel}`] : [])].join('\n');
      return;
    }
    if (!this.shown) return;
    const rows = settingsRows(this.shown, this.settings, this.sceneShells);
    $('overlay').textContent = [
      `${this.shownLabel}  ${this.canvas.width}x${this.canvas.height}`,
      `frame ${median.toFixed(1)} ms${this.vsync ? ' (vsync on)' : ''}`,
      ...rows,
      ...(this.shownView ? [this.viewMapping] : []),
      `time ${this.time.toFixed(1)} s${this.paused ? ' (paused)' : ''}`,
      ...(this.note ? [this.note] : []),
    ].join('\n');
  }

  screenshot(): void {
    this.canvas.toBlob((blob) => {
      if (!blob) return;
      const a = document.createElement('a');
      a.href = URL.createObjectURL(blob);
      a.download = `raylab-${(this.shown ?? this.stage()).id}.png`;
      a.click();
      setTimeout(() => URL.revokeObjectURL(a.href), 1000);
    }, 'image/png');
  }
}
