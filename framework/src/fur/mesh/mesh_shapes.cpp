#include "mesh_shapes.h"

#include "error.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxDetail = 2048;  // 16M triangles for the sphere: far past any use

void addTriangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
}

// A (columns+1) x (rows+1) grid of vertices from POINT(u, v) with u, v in
// [0, 1]; NORMAL likewise. SKIP(row, column) leaves out one triangle of a
// cell (the sphere's pole fans): 0 keeps both, 1 drops the first, 2 the second.
// WRAPU / WRAPV: the shape closes along u / v, so the last column / row is
// the first one again - computed from 0, not 1, so that the seam's vertices
// share their positions exactly (sin(2 pi) is not 0 in floating point) and
// adjacency finds the neighbours across it.
template <class Point, class Normal, class Skip>
void addGrid(Mesh& m, int columns, int rows, bool wrapU, bool wrapV, Point point, Normal normal,
             Skip skip) {
    const std::uint32_t base = std::uint32_t(m.positions.size());
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= columns; ++c) {
            double u = double(c) / columns, v = double(r) / rows;
            double pu = wrapU && c == columns ? 0.0 : u, pv = wrapV && r == rows ? 0.0 : v;
            m.positions.push_back(glm::vec3(point(pu, pv)));
            m.normals.push_back(glm::vec3(glm::normalize(normal(pu, pv))));
            m.uvs.push_back(glm::vec2(float(u), float(v)));
        }
    auto at = [&](int r, int c) { return base + std::uint32_t(r * (columns + 1) + c); };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            int s = skip(r);
            if (s != 1) addTriangle(m, at(r, c), at(r, c + 1), at(r + 1, c + 1));
            if (s != 2) addTriangle(m, at(r, c), at(r + 1, c + 1), at(r + 1, c));
        }
}

Mesh sphere(int detail) {
    Mesh m;
    // u runs around (longitude), v from the south pole (v = 0) to the north.
    auto p = [](double u, double v) {
        // The poles exactly: sin(pi) is not 0 in floating point either.
        if (v <= 0.0 || v >= 1.0) return glm::dvec3(0.0, v <= 0.0 ? -1.0 : 1.0, 0.0);
        double phi = 2.0 * kPi * u, theta = kPi * v;
        return glm::dvec3(-std::sin(theta) * std::sin(phi), -std::cos(theta),
                          -std::sin(theta) * std::cos(phi));
    };
    // Row 0 touches the south pole, the last row the north pole: each of
    // their quads has one real triangle and one of zero area, left out.
    const int rows = detail;
    addGrid(m, 2 * detail, rows, true, false, p, p, [rows](int r) {
        return r == 0 ? 1 : r == rows - 1 ? 2 : 0;
    });
    return m;
}

Mesh torus(int detail) {
    Mesh m;
    const double ring = 1.0, tube = 0.4;
    auto centre = [&](double u) {
        double a = 2.0 * kPi * u;
        return glm::dvec3(ring * std::cos(a), 0.0, -ring * std::sin(a));
    };
    auto n = [&](double u, double v) {
        double a = 2.0 * kPi * u, b = 2.0 * kPi * v;
        return glm::dvec3(std::cos(b) * std::cos(a), std::sin(b), -std::cos(b) * std::sin(a));
    };
    auto p = [&](double u, double v) { return centre(u) + tube * n(u, v); };
    addGrid(m, 2 * detail, detail, true, true, p, n, [](int) { return 0; });
    return m;
}

Mesh cube(int detail) {
    Mesh m;
    // Each face: its normal and two axes along it, counter-clockwise from outside.
    struct Face {
        glm::dvec3 n, u, v;
    } faces[] = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                 {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                 {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    for (const Face& f : faces)
        addGrid(
            m, detail, detail, false, false,
            [&](double u, double v) { return f.n + (2.0 * u - 1.0) * f.u + (2.0 * v - 1.0) * f.v; },
            [&](double, double) { return f.n; }, [](int) { return 0; });
    return m;
}

}  // namespace

const std::vector<std::string>& shapeNames() {
    static const std::vector<std::string> names = {"sphere", "torus", "cube"};
    return names;
}

Mesh makeShape(const std::string& shape, int detail) {
    const int least = shape == "cube" ? 1 : 2;
    if (std::find(shapeNames().begin(), shapeNames().end(), shape) == shapeNames().end())
        throw Error("unknown mesh shape '" + shape + "' (known: sphere, torus, cube)");
    if (detail < least || detail > kMaxDetail)
        throw Error("mesh " + shape + ": detail must be between " + std::to_string(least) +
                    " and " + std::to_string(kMaxDetail) + " (not " + std::to_string(detail) + ")");
    Mesh m = shape == "sphere" ? sphere(detail) : shape == "torus" ? torus(detail) : cube(detail);
    m.name = shape + "-" + std::to_string(m.triangleCount());
    return m;
}

int defaultDetail(const std::string& shape) {
    return shape == "cube" ? 8 : shape == "torus" ? 24 : 32;
}

int detailForTriangles(const std::string& shape, long triangles) {
    double t = double(std::max(1L, triangles));
    double d = shape == "cube"    ? std::sqrt(t / 12.0)
               : shape == "torus" ? std::sqrt(t / 4.0)
                                  : 0.5 + std::sqrt(0.25 + t / 4.0);  // 4d^2 - 4d = t
    return std::clamp(int(std::lround(d)), shape == "cube" ? 1 : 2, kMaxDetail);
}

}  // namespace raylab
