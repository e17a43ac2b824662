// The procedural meshes: the triangle counts they promise, closed surfaces
// (every edge shared by two triangles once seams are welded), outward
// counter-clockwise triangles, unit normals.
#include "adjacency.h"
#include "error.h"
#include "mesh_shapes.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {

// The signed volume of a closed mesh (divergence theorem): positive when
// its triangles are counter-clockwise seen from outside.
double signedVolume(const Mesh& m) {
    double v = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
            c(m.positions[m.indices[t + 2]]);
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

}  // namespace

TEST(MeshShapes, TriangleCountsAreAsDocumented) {
    for (int d : {2, 5, 32}) {
        EXPECT_EQ(makeShape("sphere", d).triangleCount(), std::size_t(4 * d * d - 4 * d)) << d;
        EXPECT_EQ(makeShape("torus", d).triangleCount(), std::size_t(4 * d * d)) << d;
        EXPECT_EQ(makeShape("cube", d).triangleCount(), std::size_t(12 * d * d)) << d;
    }
    EXPECT_EQ(makeShape("sphere", 32).name, "sphere-3968");
}

TEST(MeshShapes, EveryShapeIsClosedAndFacesOutwards) {
    const double pi = 3.14159265358979;
    for (const std::string& shape : shapeNames()) {
        SCOPED_TRACE(shape);
        const Mesh m = makeShape(shape, 12);
        const EdgeAdjacency adj = buildEdgeAdjacency(m);
        EXPECT_EQ(adj.boundaryEdges, 0) << "the seams are welded by position";
        EXPECT_EQ(adj.nonManifoldEdges, 0);
        EXPECT_EQ(adj.degenerateTriangles, 0) << "the sphere's poles are fans";
        // A closed triangle mesh has 3/2 edges per triangle.
        EXPECT_EQ(adj.edgeCount() * 2, m.triangleCount() * 3);
        const double volume = signedVolume(m);
        const double expected = shape == "sphere"  ? 4.0 / 3.0 * pi
                                : shape == "torus" ? 2.0 * pi * pi * 1.0 * 0.4 * 0.4
                                                   : 8.0;
        EXPECT_NEAR(volume, expected, 0.06 * expected) << "positive: counter-clockwise outside";
        for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
}

TEST(MeshShapes, DetailForTrianglesHitsTheSeries) {
    for (const std::string& shape : shapeNames())
        for (long t : {100L, 1000L, 20000L, 200000L}) {
            const long got = long(makeShape(shape, detailForTriangles(shape, t)).triangleCount());
            EXPECT_GT(got, t / 2) << shape << " " << t;
            EXPECT_LT(got, t * 2) << shape << " " << t;
        }
}

TEST(MeshShapes, BadShapesAndDetailsAreRefused) {
    EXPECT_THROW(makeShape("teapot", 8), Error);
    EXPECT_THROW(makeShape("sphere", 1), Error);
    EXPECT_THROW(makeShape("cube", 0), Error);
    EXPECT_THROW(makeShape("torus", 100000), Error);
}
