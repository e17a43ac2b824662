// Fur scene files: the shipped ones load, and mistakes are one line that
// names the file and the key.
#include "error.h"
#include "fur_scene.h"
#include "paths.h"
#include "strand_budget.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::test;

TEST(FurScene, TheShippedScenesLoad) {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(projectRoot() / "assets/scenes/fur"))
        if (entry.path().extension() == ".json") {
            EXPECT_NO_THROW(loadFurScene(entry.path())) << entry.path();
            ++n;
        }
    EXPECT_GE(n, 4);
}

TEST(FurScene, MistakesNameFileAndKey) {
    ScratchDir dir;
    const std::string textures = (projectRoot() / "assets/textures").string();
    auto scene = [&](const std::string& mesh, const std::string& fur) {
        return "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0, 0, 3], \"yaw\": 0, "
               "\"pitch\": 0}, \"mesh\": " +
               mesh + ", \"light\": {\"direction\": [0, 1, 0]}, \"fur\": {" + fur +
               "\"color_map\": \"" + textures + "/fur_color.png\", \"pattern\": \"" + textures +
               "/fur_pattern.png\", \"fin_map\": \"" + textures + "/fur_fin.png\"}}";
    };
    struct Case {
        std::string mesh, fur, message;
    } cases[] = {
        {"{\"shape\": \"sphere\"}", "", ""},
        {"{\"shape\": \"teapot\"}", "", "mesh.shape: unknown shape 'teapot'"},
        {"{\"shape\": \"sphere\", \"obj\": \"x.obj\"}", "", "mesh: give either"},
        {"{\"obj\": \"nowhere.obj\"}", "", "mesh.obj: file"},
        {"{\"obj\": \"/dev/zero\"}", "", "mesh.obj: /dev/zero is not a regular file"},
        {"{\"obj\": \"/tmp\"}", "", "mesh.obj: /tmp is a folder"},
        {"{\"shape\": \"sphere\", \"fit\": true}", "", "mesh.fit: is for OBJ models"},
        {"{\"shape\": \"sphere\", \"uvs\": \"box\"}", "", "mesh.uvs: is for OBJ models"},
        {"{\"shape\": \"sphere\", \"detail\": 1}", "", "mesh.detail: must be between 2 and 512"},
        {"{\"shape\": \"sphere\"}", "\"shells\": 0, ", "fur.shells: must be between 1 and 256"},
        {"{\"shape\": \"sphere\"}", "\"length\": -1, ", "fur.length: expected a positive number"},
        {"{\"shape\": \"sphere\"}", "\"lenght\": 1, ", "fur.lenght: unknown key"},
        {"{\"shape\": \"sphere\"}", "\"shadow_intensity\": 2, ", "fur.shadow_intensity"},
    };
    for (const Case& c : cases) {
        writeFile(dir / "s.json", scene(c.mesh, c.fur));
        std::string got;
        try {
            loadFurScene(dir / "s.json");
        } catch (const Error& e) { got = e.what(); }
        if (c.message.empty()) {
            EXPECT_EQ(got, "") << c.mesh;
        } else {
            EXPECT_NE(got.find("s.json: " + c.message), std::string::npos)
                << got << "\nexpected: " << c.message;
            EXPECT_EQ(got.find('\n'), std::string::npos);
        }
    }
}

TEST(StrandBudget, FitsTheDriversLimits) {
    // The GL minimums: 256 vertices, 1024 components.
    StrandBudget b = strandBudget(256, 1024, 4);
    EXPECT_EQ(b.strandsPerTriangle, 1024 / (5 * kStrandVertexComponents));
    EXPECT_LE(b.maxVertices() * kStrandVertexComponents, 1024);
    EXPECT_LE(b.maxVertices(), 256);
    // A generous driver is capped at what the course asks for.
    EXPECT_EQ(strandBudget(4096, 1 << 20, 4).strandsPerTriangle, kStrandsWanted);
    EXPECT_THROW(strandBudget(4, 1024, 8), Error);
}

// An OBJ model comes in its own units; by default it is fitted into the box
// from -1 to 1 (the built-in shapes' size), and the placement says how.
TEST(FurScene, AnObjModelIsFittedUnlessTheSceneSaysNot) {
    ScratchDir dir;
    // A model 32 units wide, far from the origin (a teapot's units).
    writeFile(dir / "big.obj", "v 100 0 0\nv 132 0 0\nv 100 8 4\nf 1 2 3\n");
    const std::string textures = (projectRoot() / "assets/textures").string();
    auto scene = [&](const std::string& fit) {
        return "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0, 0, 3], \"yaw\": 0, "
               "\"pitch\": 0}, \"mesh\": "
               "{\"obj\": \"big.obj\"" +
               fit +
               "}, \"light\": {\"direction\": [0, 1, 0]}, "
               "\"fur\": {\"color_map\": \"" +
               textures + "/fur_color.png\", \"pattern\": \"" + textures +
               "/fur_pattern.png\", \"fin_map\": \"" + textures + "/fur_fin.png\"}}";
    };
    writeFile(dir / "fit.json", scene(""));
    MeshPlacement p;
    const Mesh fitted = loadFurMesh(loadFurScene(dir / "fit.json"), &p);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& v : fitted.positions) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    EXPECT_NEAR(hi.x - lo.x, 2.0f, 1e-5f) << "the longest side is 2";
    EXPECT_NEAR(lo.x + hi.x, 0.0f, 1e-5f) << "centred";
    EXPECT_NEAR(lo.y + hi.y, 0.0f, 1e-5f);
    EXPECT_TRUE(p.fitted);
    EXPECT_FLOAT_EQ(p.scale, 2.0f / 32.0f);
    const std::string note = describePlacement(p, "big.obj");
    EXPECT_NE(note.find("bounds (100, 0, 0) .. (132, 8, 4)"), std::string::npos) << note;
    EXPECT_NE(note.find("scaled by 0.0625"), std::string::npos) << note;

    writeFile(dir / "keep.json", scene(", \"fit\": false"));
    const Mesh kept = loadFurMesh(loadFurScene(dir / "keep.json"), &p);
    EXPECT_EQ(kept.positions.front(), glm::vec3(100, 0, 0));
    EXPECT_FALSE(p.fitted);
    EXPECT_NE(describePlacement(p, "big.obj").find("as the file gives them"), std::string::npos);

    writeFile(dir / "bad.json", scene(", \"fit\": 1"));
    EXPECT_THROW(loadFurScene(dir / "bad.json"), Error);
    writeFile(dir / "box.json", scene(", \"uvs\": \"box\""));
    EXPECT_EQ(loadFurScene(dir / "box.json").mesh.uvs, UvProjection::Box);
    writeFile(dir / "tube.json", scene(", \"uvs\": \"cylinder\""));
    try {
        loadFurScene(dir / "tube.json");
        ADD_FAILURE() << "no error for uvs cylinder";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("mesh.uvs: expected \"sphere\" or \"box\""),
                  std::string::npos)
            << e.what();
    }
    // The built-in shapes say nothing.
    EXPECT_EQ(describePlacement(MeshPlacement{}, "x"), "");
}
