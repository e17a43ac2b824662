// Shared by the browser tests and the benchmark: the local server, and
// Debian's Chromium driven by puppeteer-core (no browser download). WebGL 2
// runs without a GPU on Mesa's llvmpipe through ANGLE's EGL back end.
import { spawn } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchWebKit } from './webdriver_browser.mjs';
import puppeteer from 'puppeteer-core';

export const webDir = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const projectRoot = join(webDir, '..');

// `node tools/serve.mjs --port 0 [--with-solutions]` (the tests compare the
// solution: with, unless asked); resolves to the page's address.
export function startServer({ withSolutions = true } = {}) {
  const args = [join(webDir, 'tools/serve.mjs'), '--port', '0', ...(withSolutions ? ['--with-solutions'] : [])];
  const child = spawn(process.execPath, args, { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolve, reject) => {
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
      const m = /http:\/\/\S+\/web\//.exec(out);
      if (m) resolve({ url: m[0], stop: () => child.kill() });
    });
    child.stderr.on('data', (d) => (out += d));
    child.on('exit', (code) => reject(new Error(`the server stopped (exit ${code}): ${out.trim()}`)));
  });
}

// The browser the tests drive: RAYLAB_BROWSER=firefox for Debian's Firefox ESR
// (WebDriver BiDi; WebGL 2 on Mesa llvmpipe through EGL), webkit for
// WebKitGTK (webdriver_browser.mjs: under an X display), else Chromium.
export const browserName = ['firefox', 'webkit'].includes(process.env.RAYLAB_BROWSER) ? process.env.RAYLAB_BROWSER : 'chromium';

// Chromium: ANGLE selects the back end: gl-egl (Mesa llvmpipe, about 8x
// faster here) or swiftshader. RAYLAB_CHROMIUM overrides the browser's path.
// Firefox: headless with WebGL forced on (it blocks software GL otherwise)
// and EGL (MOZ_WEBGL_FORCE_EGL), so it draws with llvmpipe too;
// RAYLAB_FIREFOX overrides its path.
// DOWNLOADS: a folder the page's downloads are saved to, unasked (Firefox:
// from its start; Chromium: allowDownloads() on the page).
// EXTRAARGS: more Chromium switches (the check benchmark turns its shader caches off).
export async function launchBrowser(angle = process.env.RAYLAB_ANGLE ?? 'gl-egl', { downloads, extraArgs = [] } = {}) {
  if (browserName === 'webkit') return launchWebKit();
  if (browserName === 'firefox') {
    const saveTo = downloads ? {
      'browser.download.folderList': 2, 'browser.download.dir': downloads, 'browser.download.useDownloadDir': true,
      'browser.download.always_ask_before_handling_new_types': false, 'browser.helperApps.neverAsk.saveToDisk': 'application/zip',
    } : {};
    return puppeteer.launch({
      browser: 'firefox',
      executablePath: process.env.RAYLAB_FIREFOX ?? '/usr/bin/firefox-esr',
      headless: true,
      extraPrefsFirefox: { 'webgl.force-enabled': true, ...saveTo },
      env: { ...process.env, MOZ_WEBGL_FORCE_EGL: '1' },
      protocolTimeout: 600_000,
    });
  }
  const args = [`--use-angle=${angle}`, '--ignore-gpu-blocklist', '--enable-unsafe-swiftshader', ...extraArgs];
  if (process.getuid?.() === 0) args.push('--no-sandbox');  // Chromium refuses root with its sandbox
  return puppeteer.launch({
    executablePath: process.env.RAYLAB_CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args,
    protocolTimeout: 600_000,
  });
}

// Chromium: PAGE's downloads saved to DOWNLOADS unasked (Firefox: launchBrowser's).
export async function allowDownloads(page, downloads) {
  if (browserName === 'firefox') return;
  const cdp = await page.target().createCDPSession();
  await cdp.send('Page.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads });
}

// PAGE's console errors, page errors and failed requests, collected as they come.
export function collectProblems(page) {
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  return problems;
}

// A page of the web build with its console errors and page errors collected.
// QUERY: ?test=1 (the default) leaves the page's own controls idle, for the
// test API; '' starts them, as a student's visit does.
export async function openPage(browser, url, query = '?test=1') {
  const page = await browser.newPage();
  const problems = collectProblems(page);
  await page.goto(`${url}${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => window.raylab !== undefined, { timeout: 30_000 });
  const renderer = await page.evaluate(() => {
    const gl = document.getElementById('view').getContext('webgl2');
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    return gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
  });
  return { page, problems, renderer };
}

export function dataUrlBytes(dataUrl) {
  return Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64');
}
