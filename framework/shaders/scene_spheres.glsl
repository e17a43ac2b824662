// The scene's spheres, uploaded by the framework from the scene file
// (framework/src/stage_renderer.cpp). (Students need not change this file.)
uniform int uSphereCount;                   // how many entries below are used
uniform vec4 uSpheres[MAX_SPHERES];         // xyz = centre, w = radius
uniform vec3 uSphereColors[MAX_SPHERES];    // flat colour of each sphere
uniform vec3 uBackground;                   // seen where a ray hits nothing
