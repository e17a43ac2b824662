// Scene files with "meshes" (stage 08): an OBJ file placed in the world
// loads with its normals and texture coordinates, and every kind of bad
// entry is a one-line error naming the file and the place.
#include "error.h"
#include "paths.h"
#include "scene.h"
#include "scene_baking.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab;
using raylab::test::ScratchDir;
using raylab::test::writeFile;

namespace {

// One quad (two triangles) with normals and texture coordinates.
const std::string kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                          "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                          "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";

std::string sceneWith(const std::string& meshes, const std::string& materials = "") {
    return R"({"background": [0, 0, 0], "camera": {"position": [0, 1, 5], "yaw": 0, "pitch": 0},
      "materials": {"clay": {"ambient": [0, 0, 0], "diffuse": [0.8, 0.4, 0.2], "specular": [0, 0, 0], "shininess": 10})" +
           materials + R"(},
      "spheres": [], "meshes": )" +
           meshes + "}";
}

Scene load(const ScratchDir& dir, const std::string& text) {
    writeFile(dir / "quad.obj", kQuad);
    writeFile(dir / "scene.json", text);
    return loadScene(dir / "scene.json");
}

std::string errorFor(const std::string& text, const std::string& obj = kQuad) {
    ScratchDir dir;
    writeFile(dir / "quad.obj", obj);
    writeFile(dir / "scene.json", text);
    try {
        loadScene(dir / "scene.json");
    } catch (const Error& e) {
        std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "error must be one line: " << msg;
        return msg;
    }
    return "(no error)";
}

}  // namespace

TEST(SceneMeshes, AnObjFileIsPlacedScaledAndKeepsNormalsAndUvs) {
    ScratchDir dir;
    Scene s = load(dir, sceneWith(R"([{"file": "quad.obj", "translate": [1, 2, 3], "scale": 2,
                                      "material": "clay"}])"));
    ASSERT_EQ(s.meshes.size(), 1u);
    const MeshObject& m = s.meshes[0];
    EXPECT_EQ(m.triangleCount(), 2u);
    EXPECT_EQ(meshTriangleCount(s), 2u);
    EXPECT_EQ(s.meshes[0].material, 0);
    // (1, 1, 0) * 2 + (1, 2, 3)
    bool found = false;
    for (const glm::dvec3& p : m.positions) found = found || p == glm::dvec3(3, 4, 3);
    EXPECT_TRUE(found) << "the corner (1, 1, 0) should be at (3, 4, 3)";
    for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
    ASSERT_EQ(m.uvs.size(), m.positions.size());
}

TEST(SceneMeshes, TwoMeshesNumberTheirTrianglesInOneList) {
    ScratchDir dir;
    Scene s = load(dir, sceneWith(R"([{"file": "quad.obj", "material": "clay"},
                                      {"file": "quad.obj", "color": [0, 1, 0]}])"));
    EXPECT_EQ(meshTriangleCount(s), 4u);
    EXPECT_EQ(s.meshes[1].material, 1) << "a flat colour is a material of its own";
}

TEST(SceneMeshes, OnlyScenesWithMeshesBakeAMeshCount) {
    ScratchDir dir;
    Scene with = load(dir, sceneWith(R"([{"file": "quad.obj", "material": "clay"}])"));
    EXPECT_NE(bakedSceneGlsl(with).find("const int uMeshTriangleCount = 2;"), std::string::npos);
    Scene without = load(dir, sceneWith("[]"));
    EXPECT_EQ(bakedSceneGlsl(without).find("uMeshTriangleCount"), std::string::npos);
}

TEST(SceneMeshes, BadEntriesAreOneLineErrorsThatSayWhere) {
    EXPECT_NE(errorFor(sceneWith(R"([{"file": "missing.obj", "material": "clay"}])"))
                  .find("meshes[0].file: file"),
              std::string::npos);
    EXPECT_NE(errorFor(sceneWith(R"([{"file": "quad.obj", "material": "clay", "rotate": 1}])"))
                  .find("meshes[0]"),
              std::string::npos);
    EXPECT_NE(errorFor(sceneWith(R"([{"file": "quad.obj", "material": "clay", "scale": -1}])"))
                  .find("meshes[0].scale: expected a positive number"),
              std::string::npos);
    EXPECT_NE(errorFor(sceneWith(R"([{"file": "quad.obj", "material": "stone"}])"))
                  .find("meshes[0].material: unknown material \"stone\""),
              std::string::npos);
    EXPECT_NE(errorFor(sceneWith(R"([{"file": "quad.obj", "material": "clay"}])"),
                       "v 0 0 0\nv 1 0 0\nf 1 2 7\n")
                  .find("meshes[0].file:"),
              std::string::npos)
        << "a face naming a vertex that does not exist";
    EXPECT_NE(errorFor(sceneWith(R"({"file": "quad.obj"})")).find("meshes: expected a list"),
              std::string::npos);
}

TEST(SceneMeshes, TheExampleSceneLoads) {
    Scene s = loadScene(projectRoot() / "assets/scenes/mesh.json");
    ASSERT_EQ(s.meshes.size(), 2u);
    EXPECT_GT(meshTriangleCount(s), 1000u);
}
