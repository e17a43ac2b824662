// Safari's engine for the browser tests: WebKitGTK's MiniBrowser driven by
// Debian's WebKitWebDriver (package webkit2gtk-driver) over W3C WebDriver,
// behind the few calls of puppeteer's Browser and Page the tests make
// (newPage, goto, evaluate, waitForFunction, click, focus, keyboard,
// setViewport, close; uploadFile stands for ElementHandle.uploadFile). Dialogs (confirm) are accepted by the session
// (unhandledPromptBehavior). MiniBrowser has no
// headless mode: it needs an X display (the tests run it under xvfb-run).
// The console and failed requests are not reported over WebDriver classic:
// the tests' "no console errors" checks see none here.
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';

const MINIBROWSER = '/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser';
// WebDriver's code points for the keys the tests press (the spec's table).
const KEYS = { Tab: '\uE004', Enter: '\uE007', '\n': '\uE007', Escape: '\uE00C', End: '\uE010', Home: '\uE011', Control: '\uE009', Shift: '\uE008' };

function freePort() {
  return new Promise((res) => {
    const s = createServer().listen(0, '127.0.0.1', () => {
      const { port } = s.address();
      s.close(() => res(port));
    });
  });
}

class WebDriverPage {
  constructor(base, session) {
    this.base = base;
    this.session = session;
  }

  async command(method, path, body) {
    const r = await fetch(`${this.base}/session/${this.session}${path}`, {
      method, headers: { 'content-type': 'application/json' }, body: body === undefined ? undefined : JSON.stringify(body),
    });
    const j = await r.json();
    if (j.value?.error) throw new Error(`WebDriver ${path}: ${j.value.error}: ${j.value.message}`);
    return j.value;
  }

  on() {}  // no console events over WebDriver classic
  async goto(url) { await this.command('POST', '/url', { url }); }
  async setViewport({ width, height }) { await this.command('POST', '/window/rect', { width, height }); }

  async click(selector) {
    const element = await this.command('POST', '/element', { using: 'css selector', value: selector });
    await this.command('POST', `/element/${Object.values(element)[0]}/click`, {});
  }

  // A file input given PATH, as if the student picked it.
  async uploadFile(selector, path) {
    const element = await this.command('POST', '/element', { using: 'css selector', value: selector });
    await this.command('POST', `/element/${Object.values(element)[0]}/value`, { text: path });
  }

  async focus(selector) {
    await this.evaluate((s) => document.querySelector(s).focus(), selector);
  }

  // Key events through WebDriver's actions (puppeteer's key names).
  keyboard = {
    send: (actions) => this.command('POST', '/actions', { actions: [{ type: 'key', id: 'keyboard', actions }] }),
    down: (key) => this.keyboard.send([{ type: 'keyDown', value: KEYS[key] ?? key }]),
    up: (key) => this.keyboard.send([{ type: 'keyUp', value: KEYS[key] ?? key }]),
    press: (key) => this.keyboard.send([{ type: 'keyDown', value: KEYS[key] ?? key }, { type: 'keyUp', value: KEYS[key] ?? key }]),
    type: (text) => this.keyboard.send([...text].flatMap((c) => [{ type: 'keyDown', value: KEYS[c] ?? c }, { type: 'keyUp', value: KEYS[c] ?? c }])),
  };

  // FN(...ARGS) in the page, awaited; its result as JSON.
  async evaluate(fn, ...args) {
    const script = `const done = arguments[arguments.length - 1];
      Promise.resolve().then(() => (${fn.toString()})(...${JSON.stringify(args)}))
        .then((v) => done({ ok: v === undefined ? null : v }), (e) => done({ error: String(e && e.stack || e) }));`;
    const r = await this.command('POST', '/execute/async', { script, args: [] });
    // null: a dialog was open, accepted in place of running the script.
    if (r?.error) throw new Error(r.error);
    return r?.ok;
  }

  async waitForFunction(fn, { timeout = 30_000 } = {}, ...args) {
    const until = Date.now() + timeout;
    while (!(await this.evaluate(fn, ...args))) {
      if (Date.now() > until) throw new Error(`waitForFunction: ${timeout} ms passed`);
      await new Promise((r) => setTimeout(r, 100));
    }
  }
}

export async function launchWebKit() {
  const port = await freePort();
  const driver = spawn('WebKitWebDriver', [`--port=${port}`], { stdio: 'ignore' });
  const base = `http://127.0.0.1:${port}`;
  for (let i = 0; i < 50; ++i) {
    try {
      await fetch(`${base}/status`);
      break;
    } catch {
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  const pages = [];
  return {
    async version() { return `WebKitGTK MiniBrowser (${MINIBROWSER})`; },
    async newPage() {
      const r = await (await fetch(`${base}/session`, {
        method: 'POST', headers: { 'content-type': 'application/json' },
        body: JSON.stringify({ capabilities: { alwaysMatch: { unhandledPromptBehavior: 'accept', 'webkitgtk:browserOptions': { binary: MINIBROWSER, args: ['--automation'] } } } }),
      })).json();
      if (!r.value?.sessionId) throw new Error(`WebKitWebDriver: no session: ${JSON.stringify(r.value)}`);
      const page = new WebDriverPage(base, r.value.sessionId);
      await page.command('POST', '/timeouts', { script: 600_000 });
      pages.push(page);
      return page;
    },
    async close() {
      for (const p of pages) await fetch(`${base}/session/${p.session}`, { method: 'DELETE' }).catch(() => undefined);
      driver.kill();
    },
  };
}
