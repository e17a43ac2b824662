// The page's entry point: a WebGL 2 context on the canvas, the catalog, the
// page, and window.raylab (test_api.ts) for the tests and the benchmark -
// except in a students' bundle (`raylab web-bundle`), which has no test API.
import { loadCatalog } from '../course/catalog.js';
import { Page } from './page.js';

async function main(): Promise<void> {
  const canvas = document.getElementById('view') as HTMLCanvasElement;
  const messages = document.getElementById('messages')!;
  // Opaque; no multisampling, as natively (the native frames have none); a
  // depth buffer for the fur track; the picture kept after drawing, so that
  // screenshots read what is shown.
  const gl = canvas.getContext('webgl2', { alpha: false, antialias: false, preserveDrawingBuffer: true, depth: true });
  if (!gl) {
    messages.className = 'error';
    messages.textContent = 'This browser has no WebGL 2 (try a current Chrome, Edge, Firefox or Safari, with hardware acceleration on).';
    return;
  }
  canvas.addEventListener('webglcontextlost', (e) => {
    e.preventDefault();
    messages.className = 'error';
    messages.textContent = 'The browser took WebGL away from the page (a GPU reset or too many pages with WebGL): reload the page.';
  });
  const catalog = await loadCatalog();
  const page = new Page(gl, canvas, catalog);
  if (!catalog.bundle) (await import('./test_api.js')).installTestApi(gl, canvas, catalog, page);
  if (!new URLSearchParams(location.search).has('test')) page.start();
}

main().catch((e) => {
  const messages = document.getElementById('messages')!;
  messages.className = 'error';
  messages.textContent = String((e as Error).message ?? e);
});
