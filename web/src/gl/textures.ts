// The scene's pictures as one texture array, the sky box as a cube map, and
// the BVH's data textures (native: framework/src/gl/texture.cpp,
// raytrace/bvh_buffers.cpp). Images are decoded without colour management,
// so the texels are the file's bytes, as natively.

async function fetchPicture(url: string): Promise<Blob> {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url.replace(/^\//, '')}: cannot load the picture (HTTP ${r.status})`);
  return r.blob();
}

// The file's bytes as texels: no colour management, no premultiplied alpha.
async function decode(url: string, blob: Blob, flipY: boolean, size?: { w: number; h: number }): Promise<ImageBitmap> {
  const options: ImageBitmapOptions = {
    colorSpaceConversion: 'none',
    premultiplyAlpha: 'none',
    imageOrientation: flipY ? 'flipY' : 'from-image',
  };
  if (size) Object.assign(options, { resizeWidth: size.w, resizeHeight: size.h, resizeQuality: 'medium' });
  try {
    return await createImageBitmap(blob, options);
  } catch (e) {
    throw new Error(`${url.replace(/^\//, '')}: the browser cannot decode this picture (${(e as Error).message})`);
  }
}

// Layers of one size (the largest picture's; smaller ones are stretched, as
// natively), bottom row first (GL's texture origin), level 0 only: the tracer
// samples inside a data-dependent loop, where derivatives are undefined.
export async function textureArray(gl: WebGL2RenderingContext, urls: string[]): Promise<WebGLTexture> {
  const blobs = await Promise.all(urls.map(fetchPicture));
  const layers = await Promise.all(blobs.map((b, i) => decode(urls[i]!, b, true)));
  const w = Math.max(1, ...layers.map((b) => b.width)), h = Math.max(1, ...layers.map((b) => b.height));
  for (let i = 0; i < layers.length; ++i)
    if (layers[i]!.width !== w || layers[i]!.height !== h) {
      layers[i]!.close();
      layers[i] = await decode(urls[i]!, blobs[i]!, true, { w, h });
    }
  const t = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D_ARRAY, t);
  gl.texStorage3D(gl.TEXTURE_2D_ARRAY, 1, gl.RGBA8, w, h, Math.max(1, layers.length));
  layers.forEach((img, i) => {
    gl.texSubImage3D(gl.TEXTURE_2D_ARRAY, 0, 0, 0, i, w, h, 1, gl.RGBA, gl.UNSIGNED_BYTE, img);
    img.close();
  });
  gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_WRAP_S, gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_WRAP_T, gl.REPEAT);
  return t;
}

// Faces +x, -x, +y, -y, +z, -z, top row first (cube maps are not flipped).
// WebGL 2 filters across face edges always: there is no seamless switch.
export async function cubeMap(gl: WebGL2RenderingContext, urls: string[]): Promise<WebGLTexture> {
  const faces = await Promise.all(urls.map(async (u) => decode(u, await fetchPicture(u), false)));
  faces.forEach((f, i) => {
    if (f.width !== f.height) throw new Error(`sky box face ${urls[i]} is ${f.width}x${f.height}, faces must be square`);
    if (f.width !== faces[0].width) throw new Error(`sky box face ${urls[i]}: faces must have one size`);
  });
  const t = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_CUBE_MAP, t);
  faces.forEach((f, i) => {
    gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + i, 0, gl.RGBA8, f.width, f.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, f);
    f.close();
  });
  gl.texParameteri(gl.TEXTURE_CUBE_MAP, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_CUBE_MAP, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  for (const wrap of [gl.TEXTURE_WRAP_S, gl.TEXTURE_WRAP_T, gl.TEXTURE_WRAP_R])
    gl.texParameteri(gl.TEXTURE_CUBE_MAP, wrap, gl.CLAMP_TO_EDGE);
  return t;
}

// A list of texels for texelFetch (no filtering), stored row by row
// DATA_TEXTURE_WIDTH texels wide (web/shaders/texel_rows.glsl): WebGL 2's
// stand-in for a buffer texture. CHANNELS: 1 (R), 2 (RG) or 4 (RGBA) per texel.
export const DATA_TEXTURE_WIDTH = 1024;
export function dataTexture(gl: WebGL2RenderingContext, values: Float32Array | Int32Array, channels: 1 | 2 | 4): WebGLTexture {
  const texels = Math.max(1, Math.ceil(values.length / channels));
  const width = Math.min(texels, DATA_TEXTURE_WIDTH), height = Math.ceil(texels / DATA_TEXTURE_WIDTH);
  const float = values instanceof Float32Array;
  const data = float ? new Float32Array(width * height * channels) : new Int32Array(width * height * channels);
  data.set(values);
  const t = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D, t);
  const formats = {
    1: float ? [gl.R32F, gl.RED] : [gl.R32I, gl.RED_INTEGER],
    2: float ? [gl.RG32F, gl.RG] : [gl.RG32I, gl.RG_INTEGER],
    4: float ? [gl.RGBA32F, gl.RGBA] : [gl.RGBA32I, gl.RGBA_INTEGER],
  }[channels];
  gl.texImage2D(gl.TEXTURE_2D, 0, formats[0]!, width, height, 0, formats[1]!, float ? gl.FLOAT : gl.INT, data);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  return t;
}

// One picture, bottom row first, mipmapped (the fur track's colour map,
// pattern and fin map; native: Texture2D).
export async function texture2D(gl: WebGL2RenderingContext, url: string): Promise<WebGLTexture> {
  const img = await decode(url, await fetchPicture(url), true);
  const t = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, img.width, img.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, img);
  img.close();
  gl.generateMipmap(gl.TEXTURE_2D);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
  return t;
}
