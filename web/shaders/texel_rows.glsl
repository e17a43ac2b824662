// The web build's stand-in for buffer textures (WebGL 2 has none): a list of
// texels stored row by row in a 2D texture DATA_TEXTURE_WIDTH texels wide
// (web/src/gl/textures.ts, dataTexture, fills them). Element i sits at
// dataTexel(i). (Students need not read this file.)
const int DATA_TEXTURE_WIDTH = 1024;

ivec2 dataTexel(int i)
{
    return ivec2(i % DATA_TEXTURE_WIDTH, i / DATA_TEXTURE_WIDTH);
}
