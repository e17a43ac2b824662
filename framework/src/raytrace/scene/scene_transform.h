#pragma once
// A scene moved and resized as a whole: every length multiplied by a factor,
// every position then shifted. `raylab render --scene-scale 1e4
// --scene-offset 1e5,0,0` draws such a copy, and the numerics tests use it to
// show that a picture does not depend on the scene's size or place.
//
// The renderers use the same function the other way round (sceneFrame): the
// GPU draws every scene resized to a standard size, with the origin near the
// eye, so that the tracer's fixed tolerances (T_MIN, the ray offsets of
// framework/shaders/ray_offset.glsl) mean the same share of any scene and no
// coordinate a shader sees is large. Both work in double precision, as the
// scene is held: floats are made only from the framed scene.
#include "scene.h"

#include <glm/glm.hpp>

namespace raylab {

// How a scene is resized and moved: p -> p * scale + offset.
struct SceneTransform {
    double scale = 1.0;
    glm::dvec3 offset{0.0};
    bool identity() const { return scale == 1.0 && offset == glm::dvec3(0.0); }
    glm::dvec3 point(const glm::dvec3& p) const { return p * scale + offset; }
    double length(double l) const { return l * scale; }
};

// SCENE with every position and length transformed: camera, sphere centres
// and radii, motion amplitudes, plane points and tile sizes (so textures map
// the same), disc centres and radii, triangle corners, torus centres and
// radii, mesh corners, lights. Directions, angles, colours and the glow (measured in sphere
// radii) stay as they are.
Scene transformScene(const Scene& scene, const SceneTransform& t);
CameraPose transformPose(const CameraPose& pose, const SceneTransform& t);

// The standard frame a renderer draws SCENE in. Its size is the largest side
// of the box around its camera and finite objects (planes and lights not
// counted). A size outside [kSceneSizeMin, kSceneSizeMax] is brought into
// that band by a power of two (exact). A scene whose centre is farther from
// the origin than GRID (the power of two at or above its size) is moved so
// that its eye becomes the origin: by the eye's position, rounded to a
// multiple of GRID / 2^10 so that a frame does not depend on the eye's last
// digits.
// The move is done in double, where the scene is held, so a scene 1e6 away
// keeps its small digits, and the floats the shaders get are small numbers
// near the eye, where a picture needs them finest. The tracer's fixed
// tolerances become shares of the scene. Every scene shipped with RayLab
// lies in the band near the origin: its frame is the identity, so its
// shaders see exactly the numbers of its file, rounded once to float. A
// resized or moved copy is framed back to within the band (not to its
// original size: T_MIN and the offsets are then the same share of it only
// up to that factor).
inline constexpr double kSceneSizeMin = 2.0;
inline constexpr double kSceneSizeMax = 1024.0;
SceneTransform sceneFrame(const Scene& scene);

}  // namespace raylab
