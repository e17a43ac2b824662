#include "silhouette.h"

#include <cmath>

namespace raylab {

namespace {
struct Factors {
    double first, second, bound1, bound2;
};
Factors factors(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                const glm::dvec3& d) {
    const glm::dvec3 pb = b - p, bc = c - b;
    const glm::dvec3 nAbc = glm::cross(b - a, bc), nBcd = glm::cross(d - b, bc);
    const double lpb = glm::length(pb);
    return {glm::dot(pb, nAbc), glm::dot(pb, nBcd), lpb * glm::length(nAbc),
            lpb * glm::length(nBcd)};
}
}  // namespace

double silhouetteProduct(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c, const glm::dvec3& d) {
    Factors f = factors(p, a, b, c, d);
    return f.first * f.second;
}

bool silhouetteUncertain(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c, const glm::dvec3& d) {
    Factors f = factors(p, a, b, c, d);
    // Each dot product is computed in float from float inputs: its error is
    // a small multiple of float's epsilon times its bound. Either factor
    // near zero makes the sign of the product a coin toss.
    // A factor that is exactly zero (a degenerate triangle, the eye on B)
    // is zero in float too: no silhouette, beyond doubt.
    const double tolerance = 1e-4;
    auto nearZero = [&](double v, double bound) {
        return bound > 0.0 && std::fabs(v) <= tolerance * bound;
    };
    return nearZero(f.first, f.bound1) || nearZero(f.second, f.bound2);
}

SilhouetteCount countSilhouettes(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                 const glm::dmat4& model, const glm::dvec3& eye) {
    SilhouetteCount count;
    auto world = [&](std::uint32_t i) {
        return glm::dvec3(model * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
    };
    for (std::size_t e = 0; e + 3 < adjacency.indices.size(); e += 4) {
        const glm::dvec3 a = world(adjacency.indices[e]), b = world(adjacency.indices[e + 1]),
                         c = world(adjacency.indices[e + 2]), d = world(adjacency.indices[e + 3]);
        if (silhouetteUncertain(eye, a, b, c, d)) ++count.uncertain;
        else if (silhouetteProduct(eye, a, b, c, d) < 0.0) ++count.certain;
    }
    return count;
}

}  // namespace raylab
