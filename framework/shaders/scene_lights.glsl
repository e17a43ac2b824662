// The scene's point lights, uploaded by the framework from the scene file.
// (Students need not change this file.)
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uLightCount;                     // how many entries below are used
uniform vec3 uLightPositions[MAX_LIGHTS];
uniform vec3 uLightColors[MAX_LIGHTS];       // colour times intensity
#endif
