#include "cell_cube.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Margin in radians for a direction that GLSL rounds into the neighbouring cell.
constexpr double kCellBorderMargin = 1e-5;

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

// The unit direction through the middle of the span of cells
// [row0, row1) x [column0, column1) of face FACE.
glm::dvec3 spanMiddle(int resolution, int face, int row0, int row1, int column0, int column1) {
    const double u = 0.5 * (edge(resolution, column0) + edge(resolution, column1));
    const double v = 0.5 * (edge(resolution, row0) + edge(resolution, row1));
    return glm::normalize(faceDirection(face, u, v));
}

// The largest angle between MIDDLE and a corner of that span.
double spanRadius(int resolution, int face, int row0, int row1, int column0, int column1,
                  glm::dvec3 middle) {
    // A span of cells is a convex spherical quadrilateral: its farthest
    // point from any point inside it is a corner.
    double radius = 0.0;
    for (int column : {column0, column1})
        for (int row : {row0, row1})
            radius =
                std::max(radius, angleBetween(middle, faceDirection(face, edge(resolution, column),
                                                                    edge(resolution, row))));
    return radius;
}

}  // namespace

CellBall sweptBall(const Sphere& s) {
    return {s.center,
            s.radius + double(glm::length(s.motion.axis)) * std::fabs(s.motion.amplitude)};
}

CellBall triangleBall(const Triangle& t) {
    const glm::dvec3 centre = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
    double radius = 0.0;
    for (const glm::dvec3& v : t.vertices) radius = std::max(radius, glm::length(v - centre));
    return {centre, radius};
}

std::vector<CellBall> triangleBalls(const Triangle& t, int splits) {
    std::vector<Triangle> pieces{t};
    for (int k = 0; k < splits; ++k) {
        std::vector<Triangle> finer;
        finer.reserve(4 * pieces.size());
        for (const Triangle& p : pieces) {
            const glm::dvec3 a = p.vertices[0], b = p.vertices[1], c = p.vertices[2];
            const glm::dvec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
            for (const auto& corners :
                 {std::array<glm::dvec3, 3>{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}}) {
                Triangle piece = p;
                piece.vertices = corners;
                finer.push_back(piece);
            }
        }
        pieces = std::move(finer);
    }
    std::vector<CellBall> balls;
    balls.reserve(pieces.size());
    for (const Triangle& p : pieces) balls.push_back(triangleBall(p));
    return balls;
}

double sceneReach(const Scene& scene) {
    double r = 0.0;
    auto grow = [&](glm::dvec3 p, double radius) { r = std::max(r, glm::length(p) + radius); };
    for (const PointLight& l : scene.lights) grow(l.position, 0.0);
    for (const Sphere& s : scene.spheres) {
        const CellBall ball = sweptBall(s);
        grow(ball.centre, ball.radius);
    }
    for (const Triangle& t : scene.triangles)
        for (const glm::dvec3& p : t.vertices) grow(p, 0.0);
    for (const Disc& d : scene.discs) grow(d.center, d.radius);
    for (const Torus& t : scene.tori) grow(t.center, t.majorRadius + t.minorRadius);
    return r * 1.01;
}

double rayOffMargin(double reach) { return 1e-4 * reach + 3e-5; }

int cubeCell(int resolution, glm::vec3 d) {
    // Float, in the order cube_cell.glsl computes it.
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
    return (face * resolution + c.y) * resolution + c.x;
}

CellCube::CellCube(int resolution)
    : resolution_(resolution), block_(resolution % kBlock == 0 ? kBlock : 1) {
    auto cone = [&](int face, int row0, int row1, int column0, int column1) {
        const glm::dvec3 middle = spanMiddle(resolution, face, row0, row1, column0, column1);
        const double r =
            spanRadius(resolution, face, row0, row1, column0, column1, middle) + kCellBorderMargin;
        return Cone{middle, std::cos(r), std::sin(r), r};
    };
    for (int face = 0; face < 6; ++face)
        for (int row = 0; row < resolution; ++row)
            for (int column = 0; column < resolution; ++column)
                cells_.push_back(cone(face, row, row + 1, column, column + 1));
    for (int face = 0; face < 6; ++face)
        for (int row = 0; row < resolution; row += block_)
            for (int column = 0; column < resolution; column += block_)
                blocks_.push_back(cone(face, row, row + block_, column, column + block_));
}

void CellCube::cellsNear(glm::dvec3 centre, const CellBall& ball, double margin,
                         std::vector<int>& cells) const {
    cells.clear();
    const double radius = ball.radius + margin;
    const glm::dvec3 toBall = ball.centre - centre;
    const double distance = glm::length(toBall);
    if (distance <= radius) {  // the centre inside: every direction may meet it
        for (int c = 0; c < cellCount(); ++c) cells.push_back(c);
        return;
    }
    const glm::dvec3 axis = toBall / distance;
    const double theta = std::asin(radius / distance);  // the ball's cone
    const double cosT = std::cos(theta), sinT = std::sin(theta);
    // Does the ball's cone overlap cone C: angle(axis, C's direction) <=
    // theta + C's radius, as cosines (theta + radius < pi there)?
    auto overlaps = [&](const Cone& c) {
        return theta + c.radius >= kPi ||
               glm::dot(axis, c.direction) >= cosT * c.cosR - sinT * c.sinR;
    };
    // Blocks of cells first, then the cells of the blocks that pass: a
    // small ball's cone meets a few of a face's 4096 cells (pro's eye cells
    // are rebuilt every frame of a moving camera).
    const int blocksPerRow = resolution_ / block_;
    for (int b = 0; b < int(blocks_.size()); ++b) {
        if (!overlaps(blocks_[std::size_t(b)])) continue;
        const int face = b / (blocksPerRow * blocksPerRow),
                  inFace = b % (blocksPerRow * blocksPerRow);
        const int row0 = inFace / blocksPerRow * block_, column0 = inFace % blocksPerRow * block_;
        for (int row = row0; row < row0 + block_; ++row)
            for (int column = column0; column < column0 + block_; ++column) {
                const int c = (face * resolution_ + row) * resolution_ + column;
                if (overlaps(cells_[std::size_t(c)])) cells.push_back(c);
            }
    }
    std::sort(cells.begin(), cells.end());
}

}  // namespace raylab
