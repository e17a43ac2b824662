// The stage guide in the browser (guide.html?stage=01-raycast): the lab's
// README.md as the course handed it out (labs/<stage>/README.md beside the
// page), rendered with marked, its pictures and links relative to the lab's
// folder. Above it, what the guide's commands are in the page: the guides
// serve the native build too, and a student who has only the page has no
// build/raylab.
import { marked } from '../vendor/marked.js';

const IN_THE_PAGE = `<p><b>In the browser page</b> you need none of the guide's
<code>build/raylab</code> commands (they are for RayLab built on your own
machine): edit your files in the page's editor (<b>Code: my work</b>), the
picture follows your edits (the window of <code>raylab run</code>);
<b>Check</b> is <code>raylab check</code>; the <b>View</b> menu draws the
depth, normal and id views (<code>raylab render --view</code>);
<b>Trace a pixel</b>, then a click on the picture, prints that pixel's rays
as <code>raylab trace</code> prints your shader's; <b>Download for
submission</b> makes the zip to upload; <b>Screenshot</b> saves the picture.</p>`;
// Only the project's own guides name the solution and the course's tracer:
// a bundle's (raylab web-bundle) are a student repository's, without them.
const NATIVE_ONLY = `<p>What needs the solution or the course's own tracer
(<code>--solution</code>, <code>--reference</code>, the <code>bounces</code>
and <code>stack</code> views) is in RayLab's own repository only.</p>`;

async function show(): Promise<void> {
  const stage = new URLSearchParams(location.search).get('stage') ?? '';
  const article = document.getElementById('guide')!;
  if (!/^[\w-]+$/.test(stage)) throw new Error('guide.html?stage=STAGE: which stage (e.g. 01-raycast)');
  const folder = new URL(`../labs/${stage}/`, document.baseURI);
  const r = await fetch(new URL('README.md', folder));
  if (!r.ok) throw new Error(`no guide for stage ${stage} here (labs/${stage}/README.md: HTTP ${r.status})`);
  // The guide's pictures and links are relative to its folder.
  const base = document.createElement('base');
  base.href = folder.href;
  document.head.append(base);
  document.title = `RayLab guide: ${stage}`;
  const text = await r.text();
  document.getElementById('in-the-page')!.innerHTML = IN_THE_PAGE + (/--reference|--solution/.test(text) ? NATIVE_ONLY : '');
  article.innerHTML = await marked.parse(text);
}

show().catch((e) => {
  const article = document.getElementById('guide')!;
  article.textContent = (e as Error).message;
});
