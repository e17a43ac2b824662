// The web build's stand-in for buffer textures (WebGL 2 has none): a list of
// texels stored row by row in a 2D texture DATA_TEXTURE_WIDTH texels wide
// (web/src/gl/textures.ts, dataTexture, fills them). Element i sits at
// dataTexel(i). (Students need not read this file.)
const int DATA_TEXTURE_WIDTH = 1024;
const int DATA_TEXTURE_SHIFT = 10;  // 1024 = 2^10

// A mask and a shift, not % and /: i is never negative, and a signed
// division costs several instructions for each of the BVH walk's fetches.
ivec2 dataTexel(int i)
{
    return ivec2(i & (DATA_TEXTURE_WIDTH - 1), i >> DATA_TEXTURE_SHIFT);
}
