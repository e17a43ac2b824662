// Edge adjacency for the fin shader: A B C D per edge, and the rules for the
// awkward cases (boundary, non-manifold, degenerate, seams) - with the CPU
// silhouette count built on it.
#include "adjacency.h"
#include "mesh_shapes.h"
#include "silhouette.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {

// A mesh from positions and triangles (normals up, texture coordinates 0).
Mesh meshOf(std::vector<glm::vec3> positions, std::vector<std::uint32_t> indices) {
    Mesh m;
    m.name = "test";
    m.positions = std::move(positions);
    m.indices = std::move(indices);
    m.normals.assign(m.positions.size(), glm::vec3(0, 0, 1));
    m.uvs.assign(m.positions.size(), glm::vec2(0));
    return m;
}

// Two triangles sharing the edge 1-2 of a unit square in the z = 0 plane.
Mesh square() { return meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2, 2, 1, 3}); }

}  // namespace

TEST(Adjacency, SharedEdgeGetsBothFarCorners) {
    const EdgeAdjacency adj = buildEdgeAdjacency(square());
    EXPECT_EQ(adj.interiorEdges, 1);
    EXPECT_EQ(adj.boundaryEdges, 4);
    bool found = false;
    for (std::size_t e = 0; e < adj.indices.size(); e += 4) {
        const std::uint32_t a = adj.indices[e], b = adj.indices[e + 1], c = adj.indices[e + 2],
                            d = adj.indices[e + 3];
        if ((b == 1 && c == 2) || (b == 2 && c == 1)) {
            found = true;
            EXPECT_TRUE((a == 0 && d == 3) || (a == 3 && d == 0)) << a << " " << d;
        }
    }
    EXPECT_TRUE(found);
}

TEST(Adjacency, BoundaryEdgesRepeatTheirCornerAndAreAlwaysSilhouettes) {
    const Mesh m = square();
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    // Seen from above or below, the four rim edges are silhouettes and the
    // flat inner edge is not.
    for (glm::dvec3 eye : {glm::dvec3(0.3, 0.4, 2.0), glm::dvec3(0.3, 0.4, -2.0)}) {
        SilhouetteCount c = countSilhouettes(m, adj, glm::dmat4(1.0), eye);
        EXPECT_EQ(c.certain, 4);
        EXPECT_EQ(c.uncertain, 0);
    }
    int repeated = 0;  // D = A: the four rim edges
    for (std::size_t e = 0; e < adj.indices.size(); e += 4)
        repeated += adj.indices[e] == adj.indices[e + 3];
    EXPECT_EQ(repeated, 4);
}

TEST(Adjacency, SeamsAreWeldedByPosition) {
    // The same square with the shared edge's vertices repeated (a texture seam).
    Mesh m = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}},
                    {0, 1, 2, 3, 4, 5});
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    EXPECT_EQ(adj.interiorEdges, 1);
    EXPECT_EQ(adj.boundaryEdges, 4);
}

TEST(Adjacency, DegenerateTrianglesAreLeftOut) {
    // The square plus a zero-area triangle on its diagonal and one that
    // repeats a vertex.
    Mesh m = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5f, 0.5f, 0}},
                    {0, 1, 2, 2, 1, 3, 1, 4, 2, 0, 0, 3});
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    EXPECT_EQ(adj.degenerateTriangles, 2);
    EXPECT_EQ(adj.interiorEdges, 1);
    EXPECT_EQ(adj.boundaryEdges, 4);
}

TEST(Adjacency, NonManifoldEdgesArePairedByDirection) {
    // Three triangles on the edge 0-1: two oriented one way, one the other.
    Mesh m = meshOf({{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}},
                    {0, 1, 2, 1, 0, 3, 0, 1, 4});
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    EXPECT_EQ(adj.nonManifoldEdges, 1);
    // 0-1: one pair plus one left over; the six outer edges are boundary.
    EXPECT_EQ(adj.interiorEdges, 1);
    EXPECT_EQ(adj.boundaryEdges, 7);
}

TEST(Silhouette, ProductFollowsTheSeedsFormula) {
    // A roof along x seen from above: both faces toward the eye, positive.
    const glm::dvec3 a(0.5, -0.5, -1), b(0, 0, 0), c(1, 0, 0), d(0.5, -0.5, 1);
    EXPECT_GT(silhouetteProduct({0.5, 5, 0}, a, b, c, d), 0.0);
    EXPECT_GT(silhouetteProduct({0.5, -5, 0}, a, b, c, d), 0.0);
    EXPECT_LT(silhouetteProduct({0.5, -0.2, -5}, a, b, c, d), 0.0);
    EXPECT_TRUE(silhouetteUncertain({0.5, -1.5, -3}, a, b, c, d)) << "eye in the plane of ABC";
}

TEST(Silhouette, SphereOutlineHasAboutTheEdgesOnItsRim) {
    // From far away, the silhouette of a sphere of 2d slices crosses about
    // 2 * 2d edges of its grid... at least one per slice.
    const Mesh m = makeShape("sphere", 16);
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    const SilhouetteCount c = countSilhouettes(m, adj, glm::dmat4(1.0), {0.3, 0.2, 40.0});
    EXPECT_GE(c.certain, 32);
    EXPECT_LE(c.certain, 200);
}
