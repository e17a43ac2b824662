#include "hidden_tori.h"
#include "convex_shell.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace raylab {

bool toriHiddenFromLights(const Scene& scene) {
    if (scene.tori.empty()) return false;
    const std::vector<ConvexShell> shells = convexShells(scene);
    constexpr double kTMin = 1e-4;  // ray.glsl's T_MIN, in the shaders' units
    for (const Torus& t : scene.tori) {
        const double ball = double(t.majorRadius) + double(t.minorRadius);
        bool hidden = false;
        for (const ConvexShell& s : shells) {
            const double room = 1e-3 * s.size + 10.0 * kTMin;
            bool inside = true;
            for (std::size_t i = 0; i < s.normals.size() && inside; ++i)
                inside = planeDistance(s, i, t.center) <= -(ball + room);
            bool lightsOutside = inside;
            for (const PointLight& l : scene.lights) {
                double out = -1e300;
                for (std::size_t i = 0; i < s.normals.size(); ++i)
                    out = std::max(out, planeDistance(s, i, l.position));
                lightsOutside = lightsOutside && out >= room;
            }
            if (inside && lightsOutside) hidden = true;
        }
        if (!hidden) return false;
    }
    return true;
}

}  // namespace raylab
