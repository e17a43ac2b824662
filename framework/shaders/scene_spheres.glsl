// The scene's spheres, uploaded by the framework from the scene file
// (framework/src/raytrace/sphere_blocks.cpp). (Students need not change this file.)
// The arrays sit in uniform blocks (buffers) rather than plain uniforms:
// plain ones allow only about a hundred spheres, a block thousands. Read
// them as plain arrays all the same: uSpheres[i], uSphereColors[i].
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uSphereCount;                   // how many entries below are used
#endif
// Thousands of spheres, more than a uniform block holds, come in storage
// blocks instead (OpenGL 4.3): read the same way.
#ifdef RAYLAB_SPHERE_STORAGE
#define SPHERE_BLOCK readonly buffer
#else
#define SPHERE_BLOCK uniform
#endif
layout(std140) SPHERE_BLOCK SphereGeometry {
    vec4 uSpheres[MAX_SPHERES];             // xyz = centre, w = radius
};
#if !defined(SCENE_BAKED) || defined(RAYLAB_SPHERE_STORAGE)  // else constants (scene_baking.cpp)
layout(std140) SPHERE_BLOCK SphereColors {
    vec3 uSphereColors[MAX_SPHERES];        // flat colour of each sphere
};
#endif
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform vec3 uBackground;                   // seen where a ray hits nothing
#endif
