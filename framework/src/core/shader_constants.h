#pragma once
// Constants that the GLSL and the C++ must agree on, defined once here.
// assembleShader() writes them at the top of every shader (after the
// #defines), so the GLSL uses the same names: NO_HIT, T_MIN, T_FAR,
// MAX_DEPTH, MAX_RAYS, KIND_SPHERE ... KIND_TORUS and OBJECT_KIND_STRIDE.
#include <string>

namespace raylab::shader {

// Returned by intersection functions when the ray misses (NO_HIT).
inline constexpr double kNoHit = -1.0;
// Hits closer than this are ignored: a ray never hits its own origin (T_MIN).
// A stage may set another with the define RAYLAB_T_MIN (stage 03: 0.0, every
// hit in front counts, so that a shadow ray without its offset shows acne).
inline constexpr double kTMin = 1e-4;
// A very large distance: "nothing hit yet" (T_FAR).
inline constexpr double kTFar = 1e30;
// Rays per path, and the entries of trace()'s stack (MAX_DEPTH).
inline constexpr int kMaxDepth = 8;
// The most rays one pixel traces (MAX_RAYS): every ray ends its path or
// splits in two, at most MAX_DEPTH - 1 times.
inline constexpr int kMaxRays = 1 << kMaxDepth;

// A hit's object id is kind * kObjectKindStride + index (OBJECT_KIND_STRIDE,
// KIND_*): spheres are kind 0, so a sphere's id is its index. 2^20: a mesh
// may have a million triangles, and every id (6 kinds) stays below 2^24, so
// the id debug view's float channel holds it exactly.
inline constexpr int kObjectKindStride = 1 << 20;
// kMesh: one triangle of a scene's OBJ meshes (stage 08), all meshes' triangles
// numbered in one list.
enum ObjectKind : int { kSphere = 0, kPlane = 1, kDisc = 2, kTriangle = 3, kTorus = 4, kMesh = 5 };
inline constexpr const char* kKindNames[] = {"sphere",   "plane", "disc",
                                             "triangle", "torus", "mesh triangle"};

// The GLSL declarations of the constants above, one per line.
std::string constantsGlsl();

}  // namespace raylab::shader
