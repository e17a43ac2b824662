#pragma once
// A cube of direction cells around a point - the machinery shared by the
// light buffer (light_buffer.h: a cube around each light, for shadow rays)
// and the eye's cells (eye_cells.h: a cube around the eye, for primary
// rays). Each face of the cube is a square grid; a direction falls in the
// cell its line from the centre crosses. An object, bounded by a ball, is
// listed in every cell through which a ray from the centre may meet it.
// (Students need not read this file.)
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

// An object as seen by the cells: a ball that holds it.
struct CellBall {
    glm::dvec3 centre;
    double radius = 0.0;
};

// The ball around sphere S over its whole swing (spheres may move).
CellBall sweptBall(const Sphere& s);
// The ball around triangle T's corners (triangles never move).
CellBall triangleBall(const Triangle& t);
// Balls around the 4^SPLITS pieces of triangle T cut at its edges' middles,
// SPLITS times over: together they hold the triangle, and hug it far more
// closely than the one ball (a cube face's triangle in pro is 2.5 units
// long; its ball is a sphere, its pieces' balls a thin slab).
std::vector<CellBall> triangleBalls(const Triangle& t, int splits);

// The largest distance from the origin of any point on a bounded object or
// a light, 1% more: shading points beyond it lie on an infinite plane.
double sceneReach(const Scene& scene);

// How far a GLSL ray may run off its exact line within a scene of reach
// REACH: the ray origin's offset off a surface (ray_offset.glsl: up to 256
// float steps of each coordinate, 3.05e-5 of the point's distance from the
// origin, or 1/65536 per coordinate near it) and rounding in its direction,
// with room to spare.
double rayOffMargin(double reach);

// The cell of a cube of RESOLUTION x RESOLUTION cells per face that
// DIRECTION (any length > 0) falls in, numbered face by face, row by row:
// the same float arithmetic as the GLSL's cubeCell (cube_cell.glsl).
int cubeCell(int resolution, glm::vec3 direction);

class CellCube {
public:
    explicit CellCube(int resolution);
    int resolution() const { return resolution_; }
    int cellCount() const { return 6 * resolution_ * resolution_; }

    // The cells through whose directions a ray from CENTRE may come within
    // MARGIN of BALL (every cell when CENTRE is in the grown ball), in
    // ascending order, into CELLS. A cell's directions count with a small
    // angular margin, for a direction that float rounding puts in the next cell.
    void cellsNear(glm::dvec3 centre, const CellBall& ball, double margin,
                   std::vector<int>& cells) const;

private:
    // A cell, or a square block of cells, as a cone of directions.
    struct Cone {
        glm::dvec3 direction;  // unit, through its middle
        double cosR, sinR;     // of the largest angle from it to its border, with margin
        double radius;         // that angle
    };
    static constexpr int kBlock = 8;  // cells along a block's edge

    int resolution_;
    int block_;                 // kBlock, or 1 for a resolution it does not divide
    std::vector<Cone> cells_;   // numbered as cubeCell numbers them
    std::vector<Cone> blocks_;  // face by face, row by row
};

}  // namespace raylab
