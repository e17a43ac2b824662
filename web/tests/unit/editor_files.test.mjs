// The editor's plain parts under node (dist/, as the page loads them):
// the zips "Import a zip…" reads (the page's own stored zips, and a zip
// tool's deflated ones) and the marks it puts on a file's lines (TODOs,
// compile errors named file:line).
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

const dist = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'dist');
const { readZip } = await import(path.join(dist, 'editor/zip_reader.js'));
const { zipStored } = await import(path.join(dist, 'app/submission_zip.js'));
const { lineNotes } = await import(path.join(dist, 'editor/diagnostics.js'));

const text = (entries) => entries.map((e) => [e.path, new TextDecoder().decode(e.data)]);

test('a zip the page wrote reads back', async () => {
  const entries = [{ path: '01-raycast/main.frag', data: new TextEncoder().encode('void main() {}\n') },
    { path: '02-shading/blinn_phong.glsl', data: new TextEncoder().encode('// é\n') }];
  assert.deepEqual(text(await readZip(zipStored(entries))), text(entries));
});

test('a zip tool\'s deflated zip of a labs/ folder reads back, folders left out', async () => {
  const dir = mkdtempSync(path.join(tmpdir(), 'raylab-zip-'));
  try {
    mkdirSync(path.join(dir, 'labs', '01-raycast'), { recursive: true });
    const body = '// '.concat('x'.repeat(2000), '\nfloat f() { return 1.0; }\n');
    writeFileSync(path.join(dir, 'labs', '01-raycast', 'find_closest.glsl'), body);
    execFileSync('zip', ['-q', '-r', '-9', 'work.zip', 'labs'], { cwd: dir });
    const entries = await readZip(new Uint8Array(readFileSync(path.join(dir, 'work.zip'))));
    assert.deepEqual(text(entries), [['labs/01-raycast/find_closest.glsl', body]]);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a file that is not a zip is refused in one line', async () => {
  await assert.rejects(readZip(new TextEncoder().encode('not a zip at all, just text')), /not a zip file/);
});

test('TODOs and compile errors land on their file and line', () => {
  const notes = lineNotes([{ file: 'my-work/01-raycast/intersect_sphere.glsl', line: 18, title: 'TODO(01.a): solve it.' }],
    'fragment shader does not compile:\nmy-work/01-raycast/find_closest.glsl:5: error: \'{\' : syntax error');
  assert.deepEqual(Object.fromEntries(notes), {
    'intersect_sphere.glsl': [{ line: 18, severity: 'warning', message: 'Unfinished TODO: TODO(01.a): solve it.' }],
    'find_closest.glsl': [{ line: 5, severity: 'error', message: 'error: \'{\' : syntax error' }],
  });
});
