#pragma once
// Every ray one frame casts, as the reference tracer casts it: the export
// that lets `raylab bench` time another ray caster (Embree) on exactly the
// rays of a GLSL frame, and lets a test check that caster against the
// reference's own answers.
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace raylab {

struct TracedRay {
    // Primary, Secondary (reflected or refracted) and Glow (glow.glsl's
    // second look along the primary ray for what hides the sun) want the
    // nearest hit; Shadow (light_visibility.glsl) only asks whether anything
    // lies before the light.
    enum class Kind : std::uint8_t { Primary, Secondary, Glow, Shadow };
    glm::vec3 origin{0.0f};  // float: what the GPU casts (the reference rounded)
    glm::vec3 dir{0.0f};     // unit
    float tMax = 1e30f;      // shadow rays: the distance to the light; others T_FAR
    Kind kind = Kind::Primary;
    // The reference's answer (double precision): the id of the object hit
    // (kind * 2^20 + index) or -1; for a shadow ray the blocker's id when
    // the light is blocked, else -1. HITT: its t, 0 for none.
    int hitId = -1;
    float hitT = 0.0f;
};

// How many rays of each kind RAYS holds.
struct TracedRayCounts {
    std::size_t primary = 0, secondary = 0, glow = 0, shadow = 0;
    std::size_t total() const { return primary + secondary + glow + shadow; }
};
inline TracedRayCounts countRays(const std::vector<TracedRay>& rays) {
    TracedRayCounts c;
    for (const TracedRay& r : rays) {
        switch (r.kind) {
        case TracedRay::Kind::Primary: ++c.primary; break;
        case TracedRay::Kind::Secondary: ++c.secondary; break;
        case TracedRay::Kind::Glow: ++c.glow; break;
        case TracedRay::Kind::Shadow: ++c.shadow; break;
        }
    }
    return c;
}

}  // namespace raylab
