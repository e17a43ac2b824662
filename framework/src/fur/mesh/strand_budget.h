#pragma once
// How many strands one geometry-shader invocation of the fur shader may
// emit. A geometry shader declares the most vertices it writes
// (max_vertices), and the driver bounds both that number
// (GL_MAX_GEOMETRY_OUTPUT_VERTICES, at least 256) and the vertices times
// the components each carries (GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, at
// least 1024). A strand of S segments is a line strip of S + 1 vertices.
#include <string>
#include <vector>

namespace raylab {

// What strand.geom writes per vertex: gl_Position (4), the world position
// (3), the tangent (3), the skin's normal (3), the texture coordinate (2),
// the place along the strand (1) and the unfinished-TODO flag (1).
inline constexpr int kStrandVertexComponents = 17;
// The most strands per triangle the course asks for; the budget may allow fewer.
inline constexpr int kStrandsWanted = 32;

struct StrandBudget {
    int maxOutputVertices = 0;  // as the driver reports them
    int maxTotalComponents = 0;
    int segments = 0;            // per strand
    int strandsPerTriangle = 0;  // what fits
    int maxVertices() const { return strandsPerTriangle * (segments + 1); }
    // STRAND_SEGMENTS, STRANDS_PER_TRIANGLE, STRAND_MAX_VERTICES for strand.geom.
    std::vector<std::string> defines() const;
    std::string describe() const;  // one line for the overlay and the bench
};

// The budget for SEGMENTS per strand within the driver's limits. Throws
// Error when not even one strand fits.
StrandBudget strandBudget(int maxOutputVertices, int maxTotalComponents, int segments);

}  // namespace raylab
