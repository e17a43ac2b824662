#include "reference_intersect.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab::reference {

double intersectSphere(const DRay& ray, const glm::dvec3& center, double radius) {
    const glm::dvec3 oc = ray.origin - center;
    const double b = glm::dot(oc, ray.dir);
    // radius^2 - (distance from the centre to the line)^2: no cancellation
    // between two large terms when the sphere is far away.
    const glm::dvec3 closest = oc - b * ray.dir;
    const double h = radius * radius - glm::dot(closest, closest);
    if (h < 0.0) return kNoHit;
    const double sq = std::sqrt(h);
    // The root of larger magnitude directly, the other from the product of
    // the roots (c / q): neither loses digits to cancellation.
    const double c = glm::dot(oc, oc) - radius * radius;
    const double q = -(b + std::copysign(sq, b));
    double t0 = q, t1 = q;
    if (q != 0.0) {
        t0 = std::min(q, c / q);
        t1 = std::max(q, c / q);
    }
    double t = t0;           // the near root: entering the sphere
    if (t <= kTMin) t = t1;  // behind us: we are inside, take the exit
    return t > kTMin ? t : kNoHit;
}

double intersectPlane(const DRay& ray, const glm::dvec3& normal, double offset) {
    const double facing = glm::dot(normal, ray.dir);
    if (std::fabs(facing) < 1e-6) return kNoHit;  // intersect_plane.glsl's threshold
    const double t = (offset - glm::dot(normal, ray.origin)) / facing;
    return t > kTMin ? t : kNoHit;
}

double intersectDisc(const DRay& ray, const glm::dvec3& center, const glm::dvec3& normal,
                     double radius) {
    const double t = intersectPlane(ray, normal, glm::dot(normal, center));
    if (t == kNoHit) return kNoHit;
    const glm::dvec3 fromCenter = ray.origin + t * ray.dir - center;
    return glm::dot(fromCenter, fromCenter) <= radius * radius ? t : kNoHit;
}

double intersectTriangle(const DRay& ray, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(ray.dir, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-10) return kNoHit;
    const double invDet = 1.0 / det;
    const glm::dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) * invDet;
    if (u < 0.0 || u > 1.0) return kNoHit;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.dir, q) * invDet;
    if (v < 0.0 || u + v > 1.0) return kNoHit;
    const double t = glm::dot(e2, q) * invDet;
    return t > kTMin ? t : kNoHit;
}

double torusDistance(const glm::dvec3& p, double R, double r) {
    return std::hypot(std::hypot(p.x, p.y) - R, p.z) - r;
}

glm::dvec3 torusNormalLocal(const glm::dvec3& p, double R, double r) {
    return glm::normalize((glm::dot(p, p) + R * R - r * r) * p -
                          2.0 * R * R * glm::dvec3(p.x, p.y, 0.0));
}

glm::dmat3 torusToLocal(const glm::dvec3& axis) {
    const glm::dvec3 helper = std::fabs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(helper, axis));
    const glm::dvec3 y = glm::cross(axis, x);
    return glm::transpose(glm::dmat3(x, y, axis));  // rows x, y, axis
}

namespace {

// A polynomial c[0] + c[1] t + ... + c[n] t^n.
double evaluate(const std::vector<double>& c, double t) {
    double v = 0.0;
    for (std::size_t i = c.size(); i-- > 0;) v = v * t + c[i];
    return v;
}

int signOf(double v) { return v < 0.0 ? -1 : 1; }

// Bisects [a, b], where SIGN(a) != SIGN(b), down to adjacent doubles.
template <class Sign>
double bisect(double a, double b, Sign sign) {
    const int sa = sign(a);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        if (sign(mid) == sa) a = mid;
        else b = mid;
    }
    return 0.5 * (a + b);
}

// The real roots of polynomial C in [lo, hi], ascending: between two
// consecutive roots of the derivative the polynomial is monotone, so each
// such piece holds at most one root, found by bisection where the sign
// changes. (A root of even multiplicity, a tangency, is not reported.)
std::vector<double> rootsIn(const std::vector<double>& c, double lo, double hi) {
    std::vector<double> roots;
    const std::size_t degree = c.size() - 1;
    if (degree == 0) return roots;
    if (degree == 1) {
        if (c[1] != 0.0) {
            const double t = -c[0] / c[1];
            if (t >= lo && t <= hi) roots.push_back(t);
        }
        return roots;
    }
    std::vector<double> slope(degree);
    for (std::size_t i = 1; i <= degree; ++i) slope[i - 1] = double(i) * c[i];
    std::vector<double> ends = {lo};
    for (double t : rootsIn(slope, lo, hi)) ends.push_back(t);
    ends.push_back(hi);
    auto sign = [&](double t) { return signOf(evaluate(c, t)); };
    for (std::size_t i = 0; i + 1 < ends.size(); ++i)
        if (sign(ends[i]) != sign(ends[i + 1])) roots.push_back(bisect(ends[i], ends[i + 1], sign));
    return roots;
}

}  // namespace

double intersectTorusLocal(const DRay& ray, double R, double r) {
    // Only the bounding sphere (any radius >= R + r) can hold hits; solving
    // from where the ray enters it keeps the quartic's coefficients small.
    const double bound = 1.01 * (R + r);
    const double b = glm::dot(ray.origin, ray.dir);
    const glm::dvec3 closest = ray.origin - b * ray.dir;
    const double h = bound * bound - glm::dot(closest, closest);
    if (h < 0.0) return kNoHit;
    const double tExit = -b + std::sqrt(h);
    if (tExit <= kTMin) return kNoHit;
    const double tEnter = std::max(-b - std::sqrt(h), 0.0);
    const glm::dvec3 o = ray.origin + tEnter * ray.dir;
    const glm::dvec3 d = ray.dir;

    // (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p.x^2 + p.y^2) along p = o + t d, |d| = 1.
    const double m = glm::dot(o, o), n = glm::dot(o, d);
    const double k = m + R * R - r * r;
    const double R4 = 4.0 * R * R;
    const std::vector<double> quartic = {
        k * k - R4 * (o.x * o.x + o.y * o.y), 4.0 * n * k - 2.0 * R4 * (o.x * d.x + o.y * d.y),
        4.0 * n * n + 2.0 * k - R4 * (d.x * d.x + d.y * d.y), 4.0 * n, 1.0};
    const double lo = std::max(kTMin - tEnter, 0.0), hi = tExit - tEnter;
    if (!(lo < hi)) return kNoHit;
    // The quartic factors into (distance to the tube's core^2 - r^2) times a
    // positive term, so it has the sign of the distance function; the
    // distance is evaluated without cancellation, so the pieces between the
    // quartic's turning points are bisected on it.
    std::vector<double> slope = {quartic[1], 2.0 * quartic[2], 3.0 * quartic[3], 4.0 * quartic[4]};
    std::vector<double> ends = {lo};
    for (double t : rootsIn(slope, lo, hi)) ends.push_back(t);
    ends.push_back(hi);
    auto sign = [&](double t) { return signOf(torusDistance(o + t * d, R, r)); };
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
        if (sign(ends[i]) == sign(ends[i + 1])) continue;
        const double t = tEnter + bisect(ends[i], ends[i + 1], sign);
        if (t > kTMin) return t;
    }
    return kNoHit;
}

}  // namespace raylab::reference
