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
    for (const Sphere& s : scene.spheres)
        grow(s.center, s.radius + glm::length(s.motion.axis) * std::fabs(s.motion.amplitude));
    for (const Triangle& t : scene.triangles)
        for (glm::vec3 p : t.vertices) grow(p, 0.0);
    for (const Disc& d : scene.discs) grow(d.center, d.radius);
    for (const Torus& t : scene.tori) grow(t.center, t.majorRadius + t.minorRadius);
    return r * 1.01;
}

// Margin in radians for a direction that GLSL rounds into the neighbouring cell.
constexpr double kCellBorderMargin = 1e-5;

}  // namespace

int LightBuffer::longestList() const {
    int longest = 0;
    for (std::size_t c = 0; c + 1 < cells.size(); ++c) longest = std::max(longest, cells[c].y);
    return longest;
}

double LightBuffer::meanList() const {
    if (cells.size() < 2) return 0.0;
    double sum = 0.0;
    for (std::size_t c = 0; c + 1 < cells.size(); ++c) sum += cells[c].y;
    return sum / double(cells.size() - 1);
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

glm::dvec3 lightBufferCellCentre(int resolution, int face, int row, int column) {
    const double u = 0.5 * (edge(resolution, column) + edge(resolution, column + 1));
    const double v = 0.5 * (edge(resolution, row) + edge(resolution, row + 1));
    return glm::normalize(faceDirection(face, u, v));
}

double lightBufferCellRadius(int resolution, int face, int row, int column) {
    // A cell is a convex spherical quadrilateral: its farthest point from
    // any point inside it is a corner.
    const glm::dvec3 centre = lightBufferCellCentre(resolution, face, row, column);
    double radius = 0.0;
    for (int du = 0; du < 2; ++du)
        for (int dv = 0; dv < 2; ++dv)
            radius = std::max(
                radius, angleBetween(centre, faceDirection(face, edge(resolution, column + du),
                                                           edge(resolution, row + dv))));
    return radius;
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
                const double r =
                    lightBufferCellRadius(resolution, face, row, column) + kCellBorderMargin;
                geometry[std::size_t((face * resolution + row) * resolution + column)] = {
                    lightBufferCellCentre(resolution, face, row, column), std::cos(r), std::sin(r),
                    r};
            }
    // A face's directions lie within this angle of its axis (a corner: acos(1/sqrt(3))).
    const double faceRadius = std::acos(1.0 / std::sqrt(3.0)) + kCellBorderMargin;

    std::vector<std::vector<int>> lists(std::size_t(perLight) * scene.lights.size());
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const glm::dvec3 light = scene.lights[l].position;
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            const Sphere& s = scene.spheres[i];
            // The sphere over its whole swing, grown by how far a shadow ray
            // may run off the line through the light.
            const double radius =
                s.radius + glm::length(s.motion.axis) * std::fabs(s.motion.amplitude) + offMargin;
            const glm::dvec3 toSphere = glm::dvec3(s.center) - light;
            const double distance = glm::length(toSphere);
            std::vector<int>* cube = &lists[l * std::size_t(perLight)];
            if (distance <= radius) {  // the light inside: every direction may meet it
                for (int c = 0; c < perLight; ++c) cube[c].push_back(int(i));
                continue;
            }
            const glm::dvec3 axis = toSphere / distance;
            const double theta = std::asin(radius / distance);  // the cone's half-angle
            const double cosT = std::cos(theta), sinT = std::sin(theta);
            for (int face = 0; face < 6; ++face) {
                if (angleBetween(axis, faceDirection(face, 0.0, 0.0)) > theta + faceRadius)
                    continue;
                for (int c = face * resolution * resolution;
                     c < (face + 1) * resolution * resolution; ++c) {
                    const Cell& g = geometry[std::size_t(c)];
                    // angle(axis, centre) <= theta + r, as cosines (theta + r < pi here).
                    if (theta + g.radius >= 3.14159 ||
                        glm::dot(axis, g.centre) >= cosT * g.cosR - sinT * g.sinR)
                        cube[c].push_back(int(i));
                }
            }
        }
    }
    for (const std::vector<int>& list : lists) {
        buffer.cells.emplace_back(int(buffer.items.size()), int(list.size()));
        buffer.items.insert(buffer.items.end(), list.begin(), list.end());
    }
    buffer.cells.emplace_back(int(buffer.items.size()), int(scene.spheres.size()));
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) buffer.items.push_back(int(i));
    return buffer;
}

}  // namespace raylab
