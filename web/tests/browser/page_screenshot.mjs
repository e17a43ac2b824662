// A screenshot of the whole page as a visitor sees it (for the README):
// the lite demo running at 800x600, with the overlay.
// Usage: node tests/browser/page_screenshot.mjs OUT.png [--scene pro] [--seconds 3]
import { renameSync } from 'node:fs';
import { launchBrowser, startServer } from './browser.mjs';

const args = process.argv.slice(2);
const out = args[0];
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
if (!out || !out.endsWith('.png')) {
  console.error('usage: page_screenshot.mjs OUT.png [--scene lite|pro] [--seconds S]');
  process.exit(2);
}
const server = await startServer();
let browser;
try {
  browser = await launchBrowser();
  const page = await browser.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  page.on('pageerror', (e) => problems.push(e.message));
  await page.setViewport({ width: 1360, height: 720 });
  await page.goto(server.url, { waitUntil: 'load' });
  await page.click(`#demo-${option('--scene', 'lite')}`);
  await page.waitForFunction(() => /frame [\d.]+ ms/.test(document.getElementById('overlay').textContent), { timeout: 120_000 });
  await new Promise((r) => setTimeout(r, 1000 * Number(option('--seconds', '3'))));
  await page.screenshot({ path: `${out}.tmp.png` });
  renameSync(`${out}.tmp.png`, out);
  console.log(`wrote ${out}`);
  console.log(await page.$eval('#overlay', (o) => o.textContent));
  console.log(await page.$eval('#messages', (o) => o.textContent));
  if (problems.length) {
    console.error(problems.join('\n'));
    process.exitCode = 1;
  }
} finally {
  await browser?.close();
  server.stop();
}
