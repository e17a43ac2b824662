// OBJ files through tinyobjloader: what is computed when missing, and
// one-line errors for what cannot be read.
#include "adjacency.h"
#include "error.h"
#include "obj_mesh.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::test;

namespace {

// A unit cube of six quads, without normals or texture coordinates.
const char* kCube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

std::string message(const fs::path& file) {
    try {
        loadObjMesh(file);
    } catch (const Error& e) { return e.what(); }
    return "";
}

}  // namespace

TEST(ObjMesh, QuadsAreSplitAndMissingNormalsAndUvsComputed) {
    ScratchDir dir;
    writeFile(dir / "cube.obj", kCube);
    const Mesh m = loadObjMesh(dir / "cube.obj");
    EXPECT_EQ(m.triangleCount(), 12u);
    EXPECT_EQ(m.vertexCount(), 8u) << "one vertex per position when the file has no more";
    // Smooth normals of a cube's corner point out of the corner (area-weighted
    // over its triangles, of which a corner has one or two per face: not
    // exactly along the diagonal).
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        const glm::vec3 out = glm::normalize(m.positions[i] - glm::vec3(0.5f));
        EXPECT_GT(glm::dot(m.normals[i], out), 0.9f) << i;
        for (int k = 0; k < 3; ++k) EXPECT_GT(m.normals[i][k] * out[k], 0.0f) << i;
        EXPECT_GE(m.uvs[i].x, 0.0f);
        EXPECT_LE(m.uvs[i].y, 1.0f);
    }
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    EXPECT_EQ(adj.boundaryEdges, 0);
    EXPECT_EQ(adj.interiorEdges, 18);
}

// The box projection: every triangle reads the two coordinates across its
// face's axis, so each face of the cube shows the pattern undistorted; the
// corners are split per side, and the fins still see one closed surface.
TEST(ObjMesh, TheBoxProjectionHasNoPolesAndSplitsOnlyItsSeams) {
    ScratchDir dir;
    writeFile(dir / "cube.obj", kCube);
    const Mesh m = loadObjMesh(dir / "cube.obj", UvProjection::Box);
    EXPECT_EQ(m.triangleCount(), 12u);
    EXPECT_EQ(m.vertexCount(), 24u) << "each corner once per side it touches (3 sides)";
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        const glm::vec3 n = glm::abs(glm::cross(b - a, c - a));
        const int axis = n.x > 0.5f ? 0 : (n.y > 0.5f ? 1 : 2);
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 p = m.positions[m.indices[t + std::size_t(k)]];
            const glm::vec2 expected = axis == 0   ? glm::vec2(p.z, p.y)
                                       : axis == 1 ? glm::vec2(p.x, p.z)
                                                   : glm::vec2(p.x, p.y);
            EXPECT_EQ(m.uvs[m.indices[t + std::size_t(k)]], expected / kBoxUvSpan) << t;
        }
    }
    const EdgeAdjacency adj = buildEdgeAdjacency(m);
    EXPECT_EQ(adj.boundaryEdges, 0) << "adjacency goes by position";
    EXPECT_EQ(adj.interiorEdges, 18);
}

TEST(ObjMesh, AZeroNormalIsReplacedAndTheOthersKept) {
    ScratchDir dir;
    writeFile(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nvn 0 0 0\nf 1//1 2//2 3//1\n");
    const Mesh m = loadObjMesh(dir / "tri.obj");
    ASSERT_EQ(m.vertexCount(), 3u);
    EXPECT_EQ(m.normals[0], glm::vec3(1, 0, 0)) << "the file's normal is kept";
    EXPECT_NEAR(m.normals[1].z, 1.0f, 1e-6f) << "the zero one becomes the face's";
    EXPECT_NE(m.name.find("tri.obj"), std::string::npos);
}

TEST(ObjMesh, NormalsAndUvsInTheFileAreKeptAndNormalised) {
    ScratchDir dir;
    writeFile(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 2\n"
                               "f 1/1/1 2/2/1 3/3/1\n");
    const Mesh m = loadObjMesh(dir / "tri.obj");
    ASSERT_EQ(m.vertexCount(), 3u);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.uvs[1], glm::vec2(1, 0));
}

TEST(ObjMesh, BadFilesGiveOneLineErrorsNamingTheFile) {
    ScratchDir dir;
    EXPECT_NE(message(dir / "missing.obj").find("missing.obj: file does not exist"),
              std::string::npos);
    writeFile(dir / "empty.obj", "# nothing\nv 0 0 0\n");
    EXPECT_NE(message(dir / "empty.obj").find("empty.obj: the file has no faces"),
              std::string::npos);
    writeFile(dir / "bad-index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const std::string bad = message(dir / "bad-index.obj");
    EXPECT_NE(bad.find("bad-index.obj"), std::string::npos) << bad;
    EXPECT_EQ(bad.find('\n'), std::string::npos) << bad;
    // tinyobjloader drops a quad with a bad index with only a warning: an error here.
    writeFile(dir / "bad-quad.obj", std::string(kCube) + "f 5 6 7 99\n");
    EXPECT_NE(message(dir / "bad-quad.obj").find("bad-quad.obj: a face was dropped"),
              std::string::npos)
        << message(dir / "bad-quad.obj");
    writeFile(dir / "back.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -5 2 3\n");
    EXPECT_NE(message(dir / "back.obj").find("back.obj: a face's relative vertex index"),
              std::string::npos)
        << message(dir / "back.obj");
    writeFile(dir / "huge.obj", "v 0e999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(message(dir / "huge.obj").find("huge.obj: a vertex (v line) is not a finite"),
              std::string::npos)
        << message(dir / "huge.obj");
    writeFile(dir / "no-normals.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//4 2//4 3//4\n");
    const std::string normals = message(dir / "no-normals.obj");
    EXPECT_NE(normals.find("no-normals.obj"), std::string::npos) << normals;
    EXPECT_EQ(normals.find('\n'), std::string::npos) << normals;
}

// What tinyobjloader reads wrongly without a word - "nan" as 0, an index
// beyond an int wrapped to another vertex - and what is not a file at all
// get a true one-line message with the line.
TEST(ObjMesh, HostileNumbersAndNonFilesAreNamedTruly) {
    ScratchDir dir;
    const struct {
        const char* file;
        std::string text;
        const char* expected;
    } cases[] = {
        {"nan.obj", "v nan 1 0\nv 0 1 0\nv 1 0 0\nf 1 2 3\n",
         "nan.obj:1: v: 'nan' is not a finite"},
        {"inf.obj", "v 0 0 0\nv 1e39 1 0\nv 1 0 0\nf 1 2 3\n",
         "inf.obj:2: v: '1e39' is not a finite"},
        {"word.obj", "v 0 0 0\nv 0 1 0\nvt 0.5 x\nv 1 0 0\nf 1 2 3\n",
         "word.obj:3: vt: 'x' is not a number"},
        {"big.obj", "v 0 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 99999999999\n",
         "big.obj:4: f: index 99999999999 is out of range"},
        {"zero.obj", "v 0 0 0\nv 0 1 0\nv 1 0 0\nf 0 1 2\n", "zero.obj:4: f: index 0"},
        {"junk.obj", "v 0 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 three\n",
         "junk.obj:4: f: 'three' is not an index"},
    };
    for (const auto& c : cases) {
        writeFile(dir / c.file, c.text);
        const std::string got = message(dir / c.file);
        EXPECT_NE(got.find(c.expected), std::string::npos) << got << "\nexpected: " << c.expected;
        EXPECT_EQ(got.find('\n'), std::string::npos) << got;
    }
    fs::create_directories(dir / "folder.obj");
    EXPECT_NE(message(dir / "folder.obj").find("folder.obj: not a regular file"),
              std::string::npos);
    EXPECT_NE(message("/dev/zero").find("/dev/zero: not a regular file"), std::string::npos);
}
