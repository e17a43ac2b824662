#pragma once
// Embree 3 casting a frame's rays (reference_rays.h) on the CPU: the limit
// `raylab bench` sets the GLSL frame against. Intel's Embree is what a
// production CPU renderer would use to find hits, so "the GLSL frame is
// R x Embree casting the same rays on the same cores" says how far the GPU
// program is from what the machine can do at all - without shading, which
// Embree does not do.
//
// Embree is optional (CMake: find_package(embree 3)); without it
// embreeBuilt() is false and EmbreeCaster's constructor throws.
#include "reference_rays.h"
#include "scene.h"

#include <memory>
#include <string>
#include <vector>

namespace raylab {

// Whether this build has Embree; the version ("3.13.5") when it has.
bool embreeBuilt();
std::string embreeVersion();

// What Embree answered for each ray: the object id (kind * 2^20 + index, as
// the GLSL and the reference number objects) or -1; for a shadow ray 0 when
// the light is blocked (Embree's occlusion query does not say by what), -1
// when it is not.
struct EmbreeAnswers {
    std::vector<int> ids;
    std::vector<float> t;  // closest rays: the hit's t; 0 for none and for shadow rays
};

class EmbreeCaster {
public:
    // The scene's objects at time 0, in float as the GPU gets them:
    // spheres as Embree's sphere points, triangles (rectangles and boxes) and
    // mesh triangles as triangles, planes, discs and tori as user geometry intersected by the
    // reference's functions (Embree has no such shapes). BUILDMS: the
    // time Embree took to build its BVH. Throws Error when Embree is not built.
    explicit EmbreeCaster(const Scene& scene);
    ~EmbreeCaster();
    EmbreeCaster(const EmbreeCaster&) = delete;
    EmbreeCaster& operator=(const EmbreeCaster&) = delete;

    double buildMs() const;

    // Casts every ray of RAYS on THREADS threads, single rays
    // (rtcIntersect1 for closest rays, rtcOccluded1 for shadow rays, each
    // from T_MIN to its tMax), and returns the wall time in ms. With
    // ANSWERS, also what each ray found (for tests; slower).
    double cast(const std::vector<TracedRay>& rays, int threads,
                EmbreeAnswers* answers = nullptr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The share of RAYS whose ANSWERS agree with the reference's (TracedRay's
// hitId): the same object for closest rays (both none counts), the same
// blocked-or-not for shadow rays.
double agreementWithReference(const std::vector<TracedRay>& rays, const EmbreeAnswers& answers);

}  // namespace raylab
