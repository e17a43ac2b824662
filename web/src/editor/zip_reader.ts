// Reading a zip the student gives back to the page ("Import a zip…": a
// submission downloaded on another device, or a zipped labs/ folder): its
// central directory (APPNOTE 4.3.12-16), each entry stored or deflated
// (the browser's DecompressionStream('deflate-raw')), so the page carries no
// zip library. What submission_zip.ts writes, and what zip tools write
// without encryption or zip64, reads back.
import type { ZipEntry } from '../app/submission_zip.js';

async function inflate(data: Uint8Array<ArrayBuffer>): Promise<Uint8Array> {
  const stream = new Blob([data]).stream().pipeThrough(new DecompressionStream('deflate-raw'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

export async function readZip(bytes: Uint8Array<ArrayBuffer>): Promise<ZipEntry[]> {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  // The end of central directory record: the last signature within its 64 KiB comment.
  let end = -1;
  for (let at = bytes.length - 22; at >= Math.max(0, bytes.length - 22 - 0xffff) && end < 0; --at)
    if (view.getUint32(at, true) === 0x06054b50) end = at;
  if (end < 0) throw new Error('this is not a zip file');
  const count = view.getUint16(end + 10, true);
  let at = view.getUint32(end + 16, true);
  const decoder = new TextDecoder();
  const entries: ZipEntry[] = [];
  for (let i = 0; i < count; ++i) {
    if (view.getUint32(at, true) !== 0x02014b50) throw new Error('the zip\'s directory is damaged');
    const method = view.getUint16(at + 10, true);
    const size = view.getUint32(at + 20, true);
    const nameLength = view.getUint16(at + 28, true);
    const skip = nameLength + view.getUint16(at + 30, true) + view.getUint16(at + 32, true);
    const local = view.getUint32(at + 42, true);
    const path = decoder.decode(bytes.subarray(at + 46, at + 46 + nameLength));
    const start = local + 30 + view.getUint16(local + 26, true) + view.getUint16(local + 28, true);
    const data = bytes.slice(start, start + size);
    if (!path.endsWith('/')) {
      if (method !== 0 && method !== 8) throw new Error(`${path}: a zip entry packed in a way the page cannot read (method ${method})`);
      entries.push({ path, data: method === 8 ? await inflate(data) : data });
    }
    at += 46 + skip;
  }
  return entries;
}
