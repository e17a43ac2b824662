// The check views' reference pictures: the solution's, rendered natively and
// shipped as PNG files (tests/reference/<stage>/<view>.png, 160x120), so the
// page compares with native's pictures and needs no solution code. Decoded
// by the browser without colour management, to the stored bytes.
import { ROOT } from '../course/catalog.js';

export interface Picture {
  width: number;
  height: number;
  rgba: Uint8Array;  // rows top-down
}

export async function referencePicture(stage: string, view: string): Promise<Picture> {
  const url = `${ROOT}/tests/reference/${stage}/${view}.png`;
  const response = await fetch(url);
  if (!response.ok) throw new Error(`tests/reference/${stage}/${view}.png: not found (HTTP ${response.status})`);
  const bitmap = await createImageBitmap(await response.blob(), { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
  const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
  const context = canvas.getContext('2d', { willReadFrequently: true })!;
  context.drawImage(bitmap, 0, 0);
  const data = context.getImageData(0, 0, bitmap.width, bitmap.height).data;
  return { width: bitmap.width, height: bitmap.height, rgba: new Uint8Array(data.buffer, data.byteOffset, data.byteLength) };
}
