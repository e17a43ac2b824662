// Scene files, stage 05 on: planes, discs, triangles, rectangles and boxes
// (made of triangles), tori, textures, the sky box and the glow.
#include "error.h"
#include "scene.h"
#include "test_support.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

using namespace raylab;
using raylab::test::ScratchDir;
using raylab::test::writeFile;

namespace {

std::string shapesSceneWith(const std::string& extra) {
    return R"({"background": [0, 0, 0], "camera": {"position": [0, 1, 5], "yaw": 0, "pitch": 0},
               "materials": {"m": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 10}},
               "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "m"}])" +
           (extra.empty() ? "" : ", " + extra) + "}";
}

Scene loadShapes(const ScratchDir& dir, const std::string& text) {
    writeFile(dir / "scene.json", text);
    return loadScene(dir / "scene.json");
}

std::string shapesErrorFor(const std::string& text) {
    ScratchDir dir;
    try {
        loadShapes(dir, text);
    } catch (const Error& e) {
        std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        return msg;
    }
    return "(no error)";
}

// The unit normal of a triangle from its corners, counter-clockwise = front.
glm::dvec3 normalOf(const Triangle& t) {
    return glm::normalize(glm::cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]));
}

}  // namespace

TEST(SceneShapes, PlanesAndDiscsHaveUnitNormals) {
    ScratchDir dir;
    Scene s = loadShapes(
        dir,
        shapesSceneWith(
            R"("planes": [{"point": [0, -1, 0], "normal": [0, 2, 0], "material": "m", "tile_size": 3}],
                                    "discs": [{"center": [1, 2, 3], "normal": [0, 0, -5], "radius": 0.5, "material": "m"}])"));
    ASSERT_EQ(s.planes.size(), 1u);
    EXPECT_FLOAT_EQ(s.planes[0].normal.y, 1.0f);
    EXPECT_DOUBLE_EQ(s.planes[0].tileSize, 3.0);
    ASSERT_EQ(s.discs.size(), 1u);
    EXPECT_FLOAT_EQ(s.discs[0].normal.z, -1.0f);
}

TEST(SceneShapes, ARectangleIsTwoTrianglesFacingCrossOfItsEdges) {
    ScratchDir dir;
    Scene s = loadShapes(
        dir,
        shapesSceneWith(
            R"("rectangles": [{"corner": [0, 0, 0], "edge_u": [2, 0, 0], "edge_v": [0, 3, 0], "material": "m"}])"));
    ASSERT_EQ(s.triangles.size(), 2u);
    for (const Triangle& t : s.triangles)
        EXPECT_NEAR(normalOf(t).z, 1.0f, 1e-6f);  // cross(x, y) = +z
}

TEST(SceneShapes, ABoxIsTwelveTrianglesAllFacingOutward) {
    ScratchDir dir;
    Scene s = loadShapes(
        dir,
        shapesSceneWith(
            R"("boxes": [{"center": [1, 2, 3], "size": [2, 4, 6], "rotation_y": 30, "material": "m"}])"));
    ASSERT_EQ(s.triangles.size(), 12u);
    const glm::dvec3 center(1, 2, 3);
    for (const Triangle& t : s.triangles) {
        const glm::dvec3 mid = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
        EXPECT_GT(glm::dot(normalOf(t), mid - center), 0.0) << "a face points into the box";
    }
}

TEST(SceneShapes, ATorusSpinsItsAxisAboutTheSpinAxis) {
    ScratchDir dir;
    Scene s = loadShapes(
        dir,
        shapesSceneWith(
            R"("tori": [{"center": [0, 0, 0], "axis": [1, 0, 0], "major_radius": 1, "minor_radius": 0.3,
                                               "material": "m", "spin": {"axis": [0, 1, 0], "period": 4}}])"));
    ASSERT_EQ(s.tori.size(), 1u);
    glm::vec3 quarter = s.tori[0].axisAt(1.0f);  // a quarter turn about +y takes +x to -z
    EXPECT_NEAR(quarter.x, 0.0f, 1e-5f);
    EXPECT_NEAR(quarter.z, -1.0f, 1e-5f);
    EXPECT_NEAR(s.tori[0].axisAt(4.0f).x, 1.0f, 1e-5f);  // a whole turn: back where it started
}

TEST(SceneShapes, TexturesAreLayersSharedBetweenMaterials) {
    ScratchDir dir;
    writeFile(dir / "a.png",
              "not really a png: only its existence is checked when the scene loads");
    writeFile(dir / "b.png", "x");
    Scene s = loadShapes(
        dir, R"({"background": [0, 0, 0], "camera": {"position": [0, 1, 5], "yaw": 0, "pitch": 0},
        "materials": {
          "one": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 10, "texture": "a.png", "normal_map": "b.png"},
          "two": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 10, "texture": "a.png"}},
        "spheres": []})");
    ASSERT_EQ(s.textures.size(), 2u);
    EXPECT_EQ(s.materials[0].texture, s.materials[1].texture);
    EXPECT_EQ(s.materials[0].normalMap, 1);
    EXPECT_EQ(s.materials[1].normalMap, -1);
}

TEST(SceneShapes, BadShapesAndMissingFilesAreOneLineErrorsThatSayWhere) {
    EXPECT_NE(shapesErrorFor(
                  shapesSceneWith(
                      R"("planes": [{"point": [0, 0, 0], "normal": [0, 0, 0], "material": "m"}])"))
                  .find("planes[0].normal: expected a direction"),
              std::string::npos);
    EXPECT_NE(
        shapesErrorFor(
            shapesSceneWith(
                R"("discs": [{"center": [0, 0, 0], "normal": [0, 1, 0], "radius": -1, "material": "m"}])"))
            .find("discs[0].radius: expected a positive number"),
        std::string::npos);
    EXPECT_NE(
        shapesErrorFor(
            shapesSceneWith(
                R"("triangles": [{"vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": "m"}])"))
            .find("triangles[0]: degenerate"),
        std::string::npos);
    EXPECT_NE(shapesErrorFor(
                  shapesSceneWith(
                      R"("triangles": [{"vertices": [[0, 0, 0], [1, 1, 1]], "material": "m"}])"))
                  .find("triangles[0].vertices: expected three"),
              std::string::npos);
    EXPECT_NE(shapesErrorFor(
                  shapesSceneWith(
                      R"("boxes": [{"center": [0, 0, 0], "size": [1, 0, 1], "material": "m"}])"))
                  .find("boxes[0].size: every side must be positive"),
              std::string::npos);
    EXPECT_NE(
        shapesErrorFor(
            shapesSceneWith(
                R"("tori": [{"center": [0, 0, 0], "axis": [0, 1, 0], "major_radius": 1, "minor_radius": 2, "material": "m"}])"))
            .find("tori[0]: minor_radius must be smaller"),
        std::string::npos);
    EXPECT_NE(shapesErrorFor(shapesSceneWith(R"("planes": {"point": [0, 0, 0]})"))
                  .find("planes: expected a list"),
              std::string::npos);
    EXPECT_NE(shapesErrorFor(shapesSceneWith(R"("sky_box": ["a.png"])"))
                  .find("sky_box: expected six image files"),
              std::string::npos);
    EXPECT_NE(
        shapesErrorFor(
            shapesSceneWith(R"("sky_box": ["a.png", "b.png", "c.png", "d.png", "e.png", "f.png"])"))
            .find("sky_box[0]: file"),
        std::string::npos);
    EXPECT_NE(shapesErrorFor(shapesSceneWith(R"("glow": {"sphere": 7})"))
                  .find("glow.sphere: expected the index of a sphere"),
              std::string::npos);
    std::string missing = shapesErrorFor(
        R"({"background": [0, 0, 0], "camera": {"position": [0, 1, 5], "yaw": 0, "pitch": 0},
        "materials": {"earth": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 10, "texture": "nowhere.png"}},
        "spheres": []})");
    EXPECT_NE(missing.find("materials.earth.texture: file"), std::string::npos) << missing;
    EXPECT_NE(missing.find("nowhere.png does not exist"), std::string::npos) << missing;
}

TEST(SceneShapes, UnknownKeysAndTexturesWhereTheyCannotGoAreErrors) {
    EXPECT_NE(
        shapesErrorFor(
            shapesSceneWith(
                R"("planes": [{"point": [0, 0, 0], "normal": [0, 1, 0], "material": "m", "tile_szie": 2}])"))
            .find("planes[0].tile_szie: unknown key"),
        std::string::npos);
    EXPECT_NE(shapesErrorFor(shapesSceneWith(R"("glwo": {"sphere": 0})")).find("glwo: unknown key"),
              std::string::npos);
    EXPECT_EQ(shapesErrorFor(shapesSceneWith(R"("comment": "comments are fine anywhere")")),
              "(no error)");
    ScratchDir dir;
    writeFile(dir / "n.png", "x");
    const std::string bumpy =
        R"({"background": [0, 0, 0], "camera": {"position": [0, 1, 5], "yaw": 0, "pitch": 0},
        "materials": {"bumpy": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 10, "normal_map": "n.png",
                                "texture": "n.png"}},
        "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "bumpy"}], )";
    auto errorIn = [&](const std::string& text) {
        writeFile(dir / "scene.json", text);
        try {
            loadScene(dir / "scene.json");
        } catch (const Error& e) { return std::string(e.what()); }
        return std::string("(no error)");
    };
    EXPECT_NE(
        errorIn(bumpy +
                R"("planes": [{"point": [0, 0, 0], "normal": [0, 1, 0], "material": "bumpy"}]})")
            .find("planes[0].material: material \"bumpy\" has a normal map, but only spheres take "
                  "normal maps"),
        std::string::npos);
    EXPECT_NE(
        errorIn(
            bumpy +
            R"("tori": [{"center": [0, 0, 0], "axis": [0, 1, 0], "major_radius": 1, "minor_radius": 0.2, "material": "bumpy"}]})")
            .find("tori have no texture coordinates"),
        std::string::npos);
}
