// "Download for submission": the student's stage folders as one zip, laid out
// like labs/ (<stage>/<file>), which `raylab gradescope` and `raylab
// prairielearn` take as an upload (framework/src/cli/submission_layout.h).
// Files are stored, not compressed: a lab is a few kilobytes of text, and
// the format's stored entries need nothing but a CRC-32 (zip's APPNOTE,
// section 4.3), so the page carries no zip library.
const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; ++n) {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

function crc32(data: Uint8Array): number {
  let c = 0xffffffff;
  for (const b of data) c = CRC_TABLE[(c ^ b) & 0xff]! ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

export interface ZipEntry {
  path: string;  // "01-raycast/intersect_sphere.glsl"
  data: Uint8Array;
}

// A zip of ENTRIES (stored, UTF-8 names, the DOS date of 1 Jan 2026: the
// same files give the same bytes).
export function zipStored(entries: ZipEntry[]): Uint8Array<ArrayBuffer> {
  const encoder = new TextEncoder();
  const parts: Uint8Array[] = [];
  const central: Uint8Array[] = [];
  let offset = 0;
  const DOS_TIME = 0, DOS_DATE = ((2026 - 1980) << 9) | (1 << 5) | 1;
  for (const e of entries) {
    const name = encoder.encode(e.path);
    const crc = crc32(e.data);
    const local = new DataView(new ArrayBuffer(30));
    local.setUint32(0, 0x04034b50, true);
    local.setUint16(4, 20, true);         // version needed
    local.setUint16(6, 0x0800, true);     // flags: UTF-8 names
    local.setUint16(8, 0, true);          // stored
    local.setUint16(10, DOS_TIME, true);
    local.setUint16(12, DOS_DATE, true);
    local.setUint32(14, crc, true);
    local.setUint32(18, e.data.length, true);
    local.setUint32(22, e.data.length, true);
    local.setUint16(26, name.length, true);
    local.setUint16(28, 0, true);
    parts.push(new Uint8Array(local.buffer), name, e.data);
    const c = new DataView(new ArrayBuffer(46));
    c.setUint32(0, 0x02014b50, true);
    c.setUint16(4, 20, true);             // made by
    c.setUint16(6, 20, true);             // needed
    c.setUint16(8, 0x0800, true);
    c.setUint16(10, 0, true);
    c.setUint16(12, DOS_TIME, true);
    c.setUint16(14, DOS_DATE, true);
    c.setUint32(16, crc, true);
    c.setUint32(20, e.data.length, true);
    c.setUint32(24, e.data.length, true);
    c.setUint16(28, name.length, true);
    c.setUint32(42, offset, true);        // the local header's offset
    central.push(new Uint8Array(c.buffer), name);
    offset += 30 + name.length + e.data.length;
  }
  const centralSize = central.reduce((n, p) => n + p.length, 0);
  const end = new DataView(new ArrayBuffer(22));
  end.setUint32(0, 0x06054b50, true);
  end.setUint16(8, entries.length, true);
  end.setUint16(10, entries.length, true);
  end.setUint32(12, centralSize, true);
  end.setUint32(16, offset, true);
  const all = [...parts, ...central, new Uint8Array(end.buffer)];
  const out = new Uint8Array(new ArrayBuffer(all.reduce((n, p) => n + p.length, 0)));
  let at = 0;
  for (const p of all) {
    out.set(p, at);
    at += p.length;
  }
  return out;
}

// Offers ENTRIES as raylab-submission.zip to the browser's downloads; says
// what it holds.
export function downloadZip(entries: ZipEntry[]): string {
  const url = URL.createObjectURL(new Blob([zipStored(entries)], { type: 'application/zip' }));
  const a = document.createElement('a');
  a.href = url;
  a.download = 'raylab-submission.zip';
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
  const stages = [...new Set(entries.map((e) => e.path.split('/')[0]))];
  return `raylab-submission.zip: ${entries.length} files of ${stages.join(', ')} ` +
    '(upload it to Gradescope or PrairieLearn as your course says)';
}
