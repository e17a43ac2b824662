// The page's Check button (and key C): `raylab check` for the stage and code
// on screen (check/run_check.ts), its report in the messages panel in
// native's words, and each failing view as three small pictures: the
// student's, the difference (native's heat map) and the reference.
import type { Catalog, Sources, StageJson } from '../course/catalog.js';
import { backendName, CHECK_HEIGHT, CHECK_WIDTH, runCheck, sourceLabel, type ViewVerdict } from '../check/run_check.js';

function picture(rgba: Uint8Array, caption: string): HTMLElement {
  const figure = document.createElement('figure');
  const canvas = document.createElement('canvas');
  canvas.width = CHECK_WIDTH;
  canvas.height = CHECK_HEIGHT;
  canvas.getContext('2d')!.putImageData(new ImageData(new Uint8ClampedArray(rgba), CHECK_WIDTH, CHECK_HEIGHT), 0, 0);
  const label = document.createElement('figcaption');
  label.textContent = caption;
  figure.append(canvas, label);
  return figure;
}

function failingView(v: ViewVerdict): HTMLElement {
  const row = document.createElement('div');
  row.className = 'check-view';
  row.dataset.view = v.name;
  row.append(picture(v.mine, `${v.name}: yours`), picture(v.heatMap, 'difference'), picture(v.expected, 'reference'));
  return row;
}

export class CheckPanel {
  running = false;

  // BUTTON: the Check button, disabled (and saying so) while a check runs.
  constructor(private gl: WebGL2RenderingContext, private catalog: Catalog, private messages: HTMLElement,
    private views: HTMLElement, private button: HTMLButtonElement) {}

  // Checks STAGE's code from SOURCES (read once the check has begun: one
  // check at a time); says so while it runs. Resolves to whether every
  // check passed (null: the check could not run).
  async run(stage: StageJson, sources: () => Promise<Sources>): Promise<boolean | null> {
    if (this.running) return null;
    this.running = true;
    const label = this.button.textContent;
    this.button.disabled = true;
    this.button.textContent = 'checking…';
    this.views.replaceChildren();
    try {
      const code = await sources();
      this.messages.className = '';
      this.messages.textContent = `checking ${stage.id} (${sourceLabel(code)})…`;
      const run = await runCheck(this.gl, this.catalog, stage, code, sourceLabel(code), backendName(this.gl));
      this.messages.className = run.failed ? 'error' : '';
      this.messages.textContent = run.report;
      this.views.replaceChildren(...run.views.filter((v) => !v.passed).map(failingView));
      return run.failed === 0;
    } catch (e) {
      this.messages.className = 'error';
      this.messages.textContent = `raylab check: ${(e as Error).message}`;
      return null;
    } finally {
      this.running = false;
      this.button.disabled = false;
      this.button.textContent = label;
    }
  }
}
