#include "light_buffer.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

// A face's cells span uv in [-1, 1]; the direction through uv on face F.
glm::dvec3 faceDirection(int face, double u, double v) {
    const double s = face % 2 == 0 ? 1.0 : -1.0;
    switch (face / 2) {
    case 0: return {s, u, v};
    case 1: return {u, s, v};
    default: return {u, v, s};
    }
}

double edge(int resolution, int k) { return 2.0 * k / resolution - 1.0; }

double angleBetween(glm::dvec3 a, glm::dvec3 b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// How far sphere S reaches from its centre over its whole swing.
double sweptRadius(const Sphere& s) {
    return s.radius + glm::length(s.motion.axis) * std::fabs(s.motion.amplitude);
}

// The unit direction through the middle of cell (FACE, ROW, COLUMN).
glm::dvec3 cellCentre(int resolution, int face, int row, int column) {
    const double u = 0.5 * (edge(resolution, column) + edge(resolution, column + 1));
    const double v = 0.5 * (edge(resolution, row) + edge(resolution, row + 1));
    return glm::normalize(faceDirection(face, u, v));
}

// The largest angle between that direction and a corner of the cell.
double cellRadius(int resolution, int face, int row, int column) {
    // A cell is a convex spherical quadrilateral: its farthest point from
    // any point inside it is a corner.
    const glm::dvec3 centre = cellCentre(resolution, face, row, column);
    double radius = 0.0;
    for (int du = 0; du < 2; ++du)
        for (int dv = 0; dv < 2; ++dv)
            radius = std::max(
                radius, angleBetween(centre, faceDirection(face, edge(resolution, column + du),
                                                           edge(resolution, row + dv))));
    return radius;
}

// How far a GLSL shadow ray may run off the line through the light: the
// ray origin's offset (ray_offset.glsl: up to 256 float steps of each
// coordinate, 3.05e-5 of the point's distance from the origin, or 1/65536
// per coordinate near it) and rounding in its direction, with room to spare.
double rayOffMargin(double reach) { return 1e-4 * reach + 3e-5; }

// The largest distance from the origin of any point on a bounded object or
// a light: shading points beyond it lie on an infinite plane.
double sceneReach(const Scene& scene) {
    double r = 0.0;
    auto grow = [&](glm::dvec3 p, double radius) { r = std::max(r, glm::length(p) + radius); };
    for (const PointLight& l : scene.lights) grow(l.position, 0.0);
    for (const Sphere& s : scene.spheres) grow(s.center, sweptRadius(s));
    for (const Triangle& t : scene.triangles)
        for (glm::vec3 p : t.vertices) grow(p, 0.0);
    for (const Disc& d : scene.discs) grow(d.center, d.radius);
    for (const Torus& t : scene.tori) grow(t.center, t.majorRadius + t.minorRadius);
    return r * 1.01;
}

// Margin in radians for a direction that GLSL rounds into the neighbouring cell.
constexpr double kCellBorderMargin = 1e-5;

constexpr double kPi = 3.14159265358979323846;

}  // namespace

int LightBuffer::longestList() const {
    int longest = 0;
    for (std::size_t c = 0; c + 1 < cells.size(); ++c)
        longest = std::max(longest, cells[c].y + cells[c].w);
    return longest;
}

double LightBuffer::meanList() const {
    double sum = 0.0;
    int used = 0;
    for (std::size_t c = 0; c + 1 < cells.size(); ++c)
        if (cells[c].y + cells[c].w > 0) {
            sum += cells[c].y + cells[c].w;
            ++used;
        }
    return used > 0 ? sum / used : 0.0;
}

bool lightBufferSuits(const Scene& scene) {
    return !scene.spheres.empty() && scene.spheres.size() <= kLightBufferMaxSpheres &&
           scene.meshes.empty() && !scene.lights.empty();
}

int lightBufferCell(int resolution, int light, glm::vec3 d) {
    // Float, in the order light_buffer.glsl computes it.
    const glm::vec3 a = glm::abs(d);
    const bool xMajor = a.x >= a.y && a.x >= a.z, yMajor = !xMajor && a.y >= a.z;
    const float major = xMajor ? d.x : yMajor ? d.y : d.z;
    const glm::vec2 uv = (xMajor   ? glm::vec2(d.y, d.z)
                          : yMajor ? glm::vec2(d.x, d.z)
                                   : glm::vec2(d.x, d.y)) /
                         std::fabs(major);
    const int face = 2 * (xMajor ? 0 : yMajor ? 1 : 2) + (major < 0.0f ? 1 : 0);
    const glm::ivec2 c = glm::clamp(glm::ivec2(glm::floor((uv * 0.5f + 0.5f) * float(resolution))),
                                    glm::ivec2(0), glm::ivec2(resolution - 1));
    return ((light * 6 + face) * resolution + c.y) * resolution + c.x;
}

LightBuffer buildLightBuffer(const Scene& scene, int resolution) {
    LightBuffer buffer;
    buffer.resolution = resolution;
    const double reach = sceneReach(scene);
    buffer.reach = float(reach);
    const double offMargin = rayOffMargin(reach);
    const int perLight = 6 * resolution * resolution;

    struct Cell {
        glm::dvec3 centre;
        double cosR, sinR, radius;
    };
    std::vector<Cell> geometry(static_cast<std::size_t>(perLight));
    for (int face = 0; face < 6; ++face)
        for (int row = 0; row < resolution; ++row)
            for (int column = 0; column < resolution; ++column) {
                const double r = cellRadius(resolution, face, row, column) + kCellBorderMargin;
                geometry[std::size_t((face * resolution + row) * resolution + column)] = {
                    cellCentre(resolution, face, row, column), std::cos(r), std::sin(r), r};
            }
    // A face's directions lie within this angle of its axis (a corner: acos(1/sqrt(3))).
    const double faceRadius = std::acos(1.0 / std::sqrt(3.0)) + kCellBorderMargin;

    // An object as a ball: the spheres over their whole swing, the
    // triangles by a ball around their corners.
    struct Ball {
        glm::dvec3 centre;
        double radius;
    };
    std::vector<Ball> spheres, triangles;
    for (const Sphere& s : scene.spheres) spheres.push_back({s.center, sweptRadius(s)});
    for (const Triangle& t : scene.triangles) {
        const glm::dvec3 centre =
            (glm::dvec3(t.vertices[0]) + glm::dvec3(t.vertices[1]) + glm::dvec3(t.vertices[2])) /
            3.0;
        double radius = 0.0;
        for (glm::vec3 v : t.vertices)
            radius = std::max(radius, glm::length(glm::dvec3(v) - centre));
        triangles.push_back({centre, radius});
    }

    const std::size_t cellCount = std::size_t(perLight) * scene.lights.size();
    std::vector<std::vector<int>> sphereLists(cellCount), triangleLists(cellCount);
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const glm::dvec3 light = scene.lights[l].position;
        // Adds I to the lists of the cells whose directions come near BALL,
        // grown by how far a shadow ray may run off the line through the light.
        auto list = [&](const Ball& ball, int i, std::vector<std::vector<int>>& lists) {
            std::vector<int>* cube = &lists[l * std::size_t(perLight)];
            const double radius = ball.radius + offMargin;
            const glm::dvec3 toBall = ball.centre - light;
            const double distance = glm::length(toBall);
            if (distance <= radius) {  // the light inside: every direction may meet it
                for (int c = 0; c < perLight; ++c) cube[c].push_back(i);
                return;
            }
            const glm::dvec3 axis = toBall / distance;
            const double theta = std::asin(radius / distance);  // the cone's half-angle
            const double cosT = std::cos(theta), sinT = std::sin(theta);
            for (int face = 0; face < 6; ++face) {
                if (angleBetween(axis, faceDirection(face, 0.0, 0.0)) > theta + faceRadius)
                    continue;
                for (int c = face * resolution * resolution;
                     c < (face + 1) * resolution * resolution; ++c) {
                    const Cell& g = geometry[std::size_t(c)];
                    // angle(axis, centre) <= theta + r, as cosines (theta + r < pi here).
                    if (theta + g.radius >= kPi ||
                        glm::dot(axis, g.centre) >= cosT * g.cosR - sinT * g.sinR)
                        cube[c].push_back(i);
                }
            }
        };
        for (std::size_t i = 0; i < spheres.size(); ++i) list(spheres[i], int(i), sphereLists);
        for (std::size_t i = 0; i < triangles.size(); ++i)
            list(triangles[i], int(i), triangleLists);
    }
    auto append = [&](const std::vector<int>& list) {
        const glm::ivec2 at(int(buffer.items.size()), int(list.size()));
        buffer.items.insert(buffer.items.end(), list.begin(), list.end());
        return at;
    };
    for (std::size_t c = 0; c < cellCount; ++c)
        buffer.cells.emplace_back(append(sphereLists[c]), append(triangleLists[c]));
    std::vector<int> everySphere(spheres.size()), everyTriangle(triangles.size());
    for (std::size_t i = 0; i < everySphere.size(); ++i) everySphere[i] = int(i);
    for (std::size_t i = 0; i < everyTriangle.size(); ++i) everyTriangle[i] = int(i);
    buffer.cells.emplace_back(append(everySphere), append(everyTriangle));
    return buffer;
}

}  // namespace raylab
