// The scene's spheres, uploaded by the framework from the scene file
// (framework/src/raytrace/sphere_blocks.cpp). (Students need not change this file.)
// The arrays sit in uniform blocks (buffers) rather than plain uniforms:
// plain ones allow only about a hundred spheres, a block thousands. Read
// them as plain arrays all the same: uSpheres[i], uSphereColors[i].
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uSphereCount;                   // how many entries below are used
#endif
layout(std140) uniform SphereGeometry {
    vec4 uSpheres[MAX_SPHERES];             // xyz = centre, w = radius
};
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
layout(std140) uniform SphereColors {
    vec3 uSphereColors[MAX_SPHERES];        // flat colour of each sphere
};
uniform vec3 uBackground;                   // seen where a ray hits nothing
#endif
