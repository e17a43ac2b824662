// Shadow rays through a light buffer (Haines and Greenberg, 1986): a cube of
// cells around each light, each listing the spheres and triangles seen from
// the light through it (built on the CPU: framework/src/raytrace/scene/light_buffer.h).
// Part of the light-buffer variant (RAYLAB_LIGHT_BUFFER; the demo and raylab
// bench's "lbuf" lever). Not part of any lab: students never see this file.
//
// A shadow ray toward light L tests the spheres and triangles of the one
// cell its direction falls in, instead of walking the BVH and testing every
// group of triangles: one read of the cell and two short loops, where a walk
// is many steps of reads whose addresses differ between llvmpipe's 8
// lock-step pixels. The lists hold every blocker the ray needs (a convex
// shell's faces turned away from the light are left out: the ray would
// cross a face turned toward it as well), so the answer - blocked or not -
// is the same as findBlocker's, bit for bit.
#include "light_buffer_access.glsl"  // lightCellList(cell), lightItem(k)
uniform int uLightBufferSize;        // cells along a cube face's edge
uniform int uLightBufferEveryCell;   // the cell listing every sphere and triangle
uniform float uLightBufferReach;     // shading points farther out use that cell

#include "cube_cell.glsl"

// The cell of light `light`'s cube that direction d (from the light) falls in.
int lightCell(int light, vec3 d)
{
    return light * 6 * uLightBufferSize * uLightBufferSize + cubeCell(d, uLightBufferSize);
}

// findBlocker (find_closest.glsl) for a ray toward light `light`: the same
// objects in the same order of kinds, the spheres and triangles from the
// ray's cell, the planes, discs and tori one by one (testOthers, less its
// triangles: a loop over few cheap objects, or a torus whose test costs the
// same skipped or not, since llvmpipe runs a loop's body at least once;
// hence the torus loop is compiled only where a torus can block a light).
bool findLightBlocker(Ray ray, float maxT, int light)
{
    Hit hit = Hit(maxT, -1);
    // A point far out on an infinite plane: its ray origin moved further off
    // the surface than the lists allow for, so every object is tested.
    int cell = length(ray.origin) > uLightBufferReach ? uLightBufferEveryCell : lightCell(light, -ray.dir);
    ivec4 list = lightCellList(cell);
    for (int k = 0; k < list.y && hit.id < 0; ++k) {
        int i = lightItem(list.x + k);
        vec4 sphere = uSpheres[i];  // one read: WebGL clamps every indexed read
        keepNearer(hit, intersectSphere(ray, sphere.xyz, sphere.w), KIND_SPHERE, i);
    }
    for (int i = 0; i < uPlaneCount && hit.id < 0; ++i)
        keepNearer(hit, intersectPlane(ray, uPlanes[i].xyz, uPlanes[i].w), KIND_PLANE, i);
    for (int i = 0; i < uDiscCount && hit.id < 0; ++i)
        keepNearer(hit, intersectDisc(ray, uDiscs[i].xyz, uDiscNormals[i], uDiscs[i].w), KIND_DISC, i);
    // The ray's shear once, not per triangle (the shared-work variant's
    // triangle_shear.glsl, which the light buffer always comes with).
    TriangleShear shear = triangleShear(ray.dir);
    for (int k = 0; k < list.w && hit.id < 0; ++k) {
        int i = lightItem(list.z + k);
        keepNearer(hit, intersectTriangleSheared(ray, shear, uTriangleVertices[3 * i], uTriangleVertices[3 * i + 1], uTriangleVertices[3 * i + 2]),
                   KIND_TRIANGLE, i);
    }
#ifndef RAYLAB_TORI_HIDDEN_FROM_LIGHTS
    // (Left out where every torus sits in a closed shell of triangles that
    // every shadow ray meeting it must cross: scene/hidden_tori.h.)
    for (int i = 0; i < uTorusCount && hit.id < 0; ++i)
        keepNearer(hit, intersectTorus(ray, i), KIND_TORUS, i);
#endif
    return hit.id >= 0;
}
