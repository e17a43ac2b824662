#include "scene_transform.h"

#include <algorithm>
#include <cmath>

namespace raylab {

CameraPose transformPose(const CameraPose& pose, const SceneTransform& t) {
    CameraPose out = pose;
    out.position = t.point(pose.position);
    return out;
}

Scene transformScene(const Scene& scene, const SceneTransform& t) {
    Scene out = scene;
    out.camera = transformPose(scene.camera, t);
    for (PointLight& l : out.lights) l.position = t.point(l.position);
    for (Sphere& s : out.spheres) {
        s.center = t.point(s.center);
        s.radius = t.length(s.radius);
        s.motion.amplitude = t.length(s.motion.amplitude);
    }
    for (Plane& p : out.planes) {
        p.point = t.point(p.point);
        p.tileSize = t.length(p.tileSize);
    }
    for (Disc& d : out.discs) {
        d.center = t.point(d.center);
        d.radius = t.length(d.radius);
    }
    for (Triangle& tri : out.triangles)
        for (glm::dvec3& v : tri.vertices) v = t.point(v);
    for (Torus& tor : out.tori) {
        tor.center = t.point(tor.center);
        tor.majorRadius = t.length(tor.majorRadius);
        tor.minorRadius = t.length(tor.minorRadius);
    }
    // Mesh corners are held in scene coordinates (placed when read); a
    // uniform scale leaves their normals as they are.
    for (MeshObject& m : out.meshes)
        for (glm::dvec3& v : m.positions) v = t.point(v);
    return out;
}

namespace {

struct Box {
    glm::dvec3 lo{HUGE_VAL}, hi{-HUGE_VAL};
    void add(glm::dvec3 p, double r = 0.0) {
        lo = glm::min(lo, p - r);
        hi = glm::max(hi, p + r);
    }
};

// The box around the camera and every finite object (moving spheres at
// either end of their motion).
Box sceneBox(const Scene& scene) {
    Box b;
    b.add(scene.camera.position);
    for (const Sphere& s : scene.spheres) {
        const glm::dvec3 swing = glm::dvec3(s.motion.axis) * s.motion.amplitude;
        b.add(glm::dvec3(s.center) + swing, s.radius);
        b.add(glm::dvec3(s.center) - swing, s.radius);
    }
    for (const Disc& d : scene.discs) b.add(d.center, d.radius);
    for (const Triangle& t : scene.triangles)
        for (const glm::dvec3& v : t.vertices) b.add(v);
    for (const Torus& t : scene.tori) b.add(t.center, t.majorRadius + t.minorRadius);
    for (const MeshObject& m : scene.meshes)
        for (const glm::dvec3& v : m.positions) b.add(v);
    return b;
}

}  // namespace

SceneTransform sceneFrame(const Scene& scene) {
    const Box box = sceneBox(scene);
    const glm::dvec3 extent = box.hi - box.lo;
    const double size = std::max({extent.x, extent.y, extent.z});
    SceneTransform frame;
    // A scene of one point (a camera and nothing else) keeps its size.
    if (!(size > 0.0) || !std::isfinite(size)) return frame;
    double unit = 1.0;  // the scene's size in the frame is size / unit
    if (size > kSceneSizeMax) unit = std::exp2(std::ceil(std::log2(size / kSceneSizeMax)));
    if (size < kSceneSizeMin) unit = std::exp2(std::floor(std::log2(size / kSceneSizeMin)));
    // The shift: only for a scene farther from the origin than its own size
    // (there float numbers are coarse compared with the scene), by the eye's
    // position rounded to a multiple of GRID / 1024 (GRID: a power of two at
    // least the size).
    const double grid = std::exp2(std::ceil(std::log2(size)));
    const glm::dvec3 centre = (box.lo + box.hi) * 0.5;
    const double distance =
        std::max({std::fabs(centre.x), std::fabs(centre.y), std::fabs(centre.z)});
    const double step = grid / 1024.0;
    const glm::dvec3 eye = scene.camera.position;
    const glm::dvec3 anchor = distance > grid ? glm::round(eye / step) * step : glm::dvec3(0.0);
    frame.scale = 1.0 / unit;
    frame.offset = -anchor / unit;
    return frame;
}

}  // namespace raylab
