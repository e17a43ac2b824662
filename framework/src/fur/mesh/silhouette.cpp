#include "silhouette.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

// The two dot products of the test, and how far float rounding can move
// each. The GPU gets world positions already rounded to float (by uModel):
// every coordinate is off by up to eps * M, M the largest coordinate, so an
// edge vector by about 2 eps M, a normal by 2 eps M (|e1| + |e2|), and the
// dot product with PB by that times |PB| plus eps M |N|. Far from the origin
// this, not the size of the product, is what makes a sign uncertain.
struct Factors {
    double first, second, slack1, slack2;
};
Factors factors(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                const glm::dvec3& d) {
    const glm::dvec3 pb = b - p, bc = c - b, ab = b - a, bd = d - b;
    const glm::dvec3 nAbc = glm::cross(ab, bc), nBcd = glm::cross(bd, bc);
    const double lpb = glm::length(pb);
    double m = 0.0;
    for (const glm::dvec3* v : {&p, &a, &b, &c, &d})
        m = std::max({m, std::fabs(v->x), std::fabs(v->y), std::fabs(v->z)});
    constexpr double kEps = 1.0 / 8388608.0;  // float's epsilon, 2^-23
    constexpr double kRelative = 1e-4;        // the float arithmetic itself, with margin
    constexpr double kSafety = 8.0;
    auto slack = [&](const glm::dvec3& n, const glm::dvec3& e1, const glm::dvec3& e2) {
        const double ln = glm::length(n);
        if (ln == 0.0 || lpb == 0.0) return 0.0;  // exactly zero in float too
        return kRelative * lpb * ln +
               kSafety * kEps * m * (2.0 * lpb * (glm::length(e1) + glm::length(e2)) + ln);
    };
    return {glm::dot(pb, nAbc), glm::dot(pb, nBcd), slack(nAbc, ab, bc), slack(nBcd, bd, bc)};
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
    // Either factor within its slack of zero makes the sign of the product
    // a coin toss. A factor that is exactly zero (a degenerate triangle, the
    // eye on B) is zero in float too (slack 0): no silhouette, beyond doubt.
    auto nearZero = [](double v, double slack) { return slack > 0.0 && std::fabs(v) <= slack; };
    return nearZero(f.first, f.slack1) || nearZero(f.second, f.slack2);
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
