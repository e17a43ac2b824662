// The scene's objects besides spheres (stage 05 on), uploaded by the
// framework from the scene file. (Students need not change this file.)
//
// A Hit's id names the object: its kind times OBJECT_KIND_STRIDE plus its
// index in that kind's list. Spheres are kind 0 (KIND_SPHERE), so a sphere's
// id is simply its index, as in labs 01-04. KIND_SPHERE, KIND_PLANE,
// KIND_DISC, KIND_TRIANGLE, KIND_TORUS and OBJECT_KIND_STRIDE are defined by
// the framework at the top of every shader (framework/src/core/shader_constants.h).

int objectId(int kind, int index) { return kind * OBJECT_KIND_STRIDE + index; }
int objectKind(int id) { return id / OBJECT_KIND_STRIDE; }
int objectIndex(int id) { return id - objectKind(id) * OBJECT_KIND_STRIDE; }


// Planes: all points p with dot(normal, p) = offset.
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uPlaneCount;
uniform vec4 uPlanes[MAX_PLANES];            // xyz = unit normal, w = offset
uniform float uPlaneTileSize[MAX_PLANES];    // a texture repeats every this many units
uniform int uPlaneMaterial[MAX_PLANES];
#endif

// Discs: the points of a plane within `radius` of the centre.
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uDiscCount;
uniform vec4 uDiscs[MAX_DISCS];              // xyz = centre, w = radius
uniform vec3 uDiscNormals[MAX_DISCS];        // unit
uniform int uDiscMaterial[MAX_DISCS];
#endif

// Triangles: corners 3i, 3i+1, 3i+2, counter-clockwise seen from the front.
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uTriangleCount;
uniform vec3 uTriangleVertices[3 * MAX_TRIANGLES];
uniform int uTriangleMaterial[MAX_TRIANGLES];
// The triangles in groups (runs of one material, such as the faces of one
// box) with the box around each group's corners: stage 08 skips a group
// whose box the ray misses. Group g holds the triangles first .. first +
// count - 1.
uniform int uTriangleGroupCount;
uniform vec4 uTriangleGroupLow[MAX_TRIANGLES];   // xyz = box min, w = first
uniform vec4 uTriangleGroupHigh[MAX_TRIANGLES];  // xyz = box max, w = count
#endif

// Tori: a ring of radius `major` (centre to the middle of the tube) with a
// tube of radius `minor`. uTorusToLocal turns world directions into the
// torus's own frame, where its axis is +z.
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uTorusCount;
uniform vec4 uTori[MAX_TORI];                // xyz = centre, w = major radius
uniform float uTorusMinor[MAX_TORI];
#endif
uniform mat3 uTorusToLocal[MAX_TORI];
#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uTorusMaterial[MAX_TORI];
#endif
