// The scene's pictures (stage 06 on), bound by the framework. (Students
// need not change this file.)
//
// Every texture and normal map of the scene is one layer of uTextures; a
// material names its layers (Material.texture, Material.normalMap; -1 for
// none). Sample with textureLod(uTextures, vec3(u, v, layer), 0.0): the
// tracer's loop makes the automatic mipmap choice of texture() undefined.
uniform sampler2DArray uTextures;
vec4 textureLayer(int layer, vec2 uv)
{
    return textureLod(uTextures, vec3(uv, float(layer)), 0.0);
}

// The sky box: a cube map, looked up by direction. uHasSky is 0 when the
// scene has none (then the background colour is the sky).
uniform samplerCube uSky;
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uHasSky;
#endif

// The glowing sphere (the "sun"; key G): uGlowSphere < 0 means none.
uniform int uGlow;
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uGlowSphere;
uniform vec3 uGlowColor;
uniform float uGlowSize;   // how far the halo reaches, in sun radii
#endif
