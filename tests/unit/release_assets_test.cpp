// What a release to students holds of assets/ (framework/src/cli/
// release_assets.h): the scenes its stages draw and the files those scenes
// name, nothing of a stage it does not hand out. The bundle and student
// repository tests check the same from the other side, with a search of
// their own (web/tests/answer_search.mjs, releasedAssets).
#include "error.h"
#include "handout.h"
#include "paths.h"
#include "release_assets.h"
#include "stage_list.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace {

using namespace raylab::test;
using raylab::releasedAssets;

bool has(const std::set<std::string>& files, const std::string& f) { return files.count(f) > 0; }

TEST(ReleaseAssets, AStageGetsItsOwnScenesAndWhatTheyName) {
    EXPECT_EQ(releasedAssets({"01-raycast"}), std::set<std::string>{"assets/scenes/stage01.json"});
    // Stage 03 draws stage 02's scene and, in one check view, its far copy.
    EXPECT_EQ(
        releasedAssets({"03-shadows"}),
        (std::set<std::string>{"assets/scenes/stage02.json", "assets/scenes/stage03-far.json"}));

    const std::set<std::string> textures = releasedAssets({"06-textures"});
    EXPECT_TRUE(has(textures, "assets/scenes/stage06.json"));
    EXPECT_TRUE(has(textures, "assets/textures/earth.png"));
    for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
        EXPECT_TRUE(has(textures, std::string("assets/textures/sky_") + face + ".png")) << face;
    for (const std::string& f : textures) {
        EXPECT_EQ(f.find("fur"), std::string::npos) << f;
        EXPECT_EQ(f.find("pro.json"), std::string::npos) << f;
    }

    const std::set<std::string> full = releasedAssets({"08-full"});
    for (const char* f : {"assets/scenes/lite.json", "assets/scenes/pro.json",
                          "assets/scenes/mesh.json", "assets/meshes/blob.obj"})
        EXPECT_TRUE(has(full, f)) << f;

    const std::set<std::string> fur = releasedAssets({"f1-mesh"});
    EXPECT_TRUE(has(fur, "assets/scenes/fur/sphere.json"));
    EXPECT_TRUE(has(fur, "assets/textures/fur_color.png"));
    for (const std::string& f : fur) EXPECT_EQ(f.find("stage0"), std::string::npos) << f;
    // Every file listed exists in the project.
    for (const auto& set : {textures, full, fur})
        for (const std::string& f : set)
            EXPECT_TRUE(fs::is_regular_file(raylab::projectRoot() / f)) << f;
}

TEST(ReleaseAssets, TheCopyHoldsTheLicenceAndTheScenesTableOfItsFilesOnly) {
    ScratchDir out;
    raylab::copyReleasedAssets(
        out.path(), raylab::planHandout(raylab::parseStageList("01-03"), raylab::Carry::Own), true);
    EXPECT_TRUE(fs::is_regular_file(out / "assets/LICENSES.md"));
    EXPECT_TRUE(fs::is_regular_file(out / "assets/scenes/stage02.json"));
    EXPECT_FALSE(fs::exists(out / "assets/textures"));
    const std::string readme = readFile(out / "assets/scenes/README.md");
    EXPECT_NE(readme.find("| `stage01.json` | stage 01 |"), std::string::npos) << readme;
    EXPECT_NE(readme.find("## Keys"), std::string::npos);  // the format's reference stays whole
    for (const char* gone : {"`pro.json`", "`stage04.json` |", "`fur/sphere.json` |"})
        EXPECT_EQ(readme.find(gone), std::string::npos) << gone;
    // The licence: its statement whole, nothing on files the release lacks,
    // no maintainers' paragraph (tools a release does not hold).
    const std::string project = readFile(raylab::projectRoot() / "assets/LICENSES.md");
    const std::string licence = readFile(out / "assets/LICENSES.md");
    EXPECT_NE(licence.find("**Nothing third-party is included**"), std::string::npos) << licence;
    EXPECT_NE(licence.find("## Scenes (`assets/scenes/`)"), std::string::npos) << licence;
    for (const char* gone :
         {"## Textures", "## Meshes", "earth.png", "blob.obj", "tools/", "with-solution"}) {
        EXPECT_NE(project.find(gone), std::string::npos)
            << gone;  // so that its absence says something
        EXPECT_EQ(licence.find(gone), std::string::npos) << gone << "\n" << licence;
    }
}

TEST(ReleaseAssets, TheLicenceOfATexturedStageListsItsTexturesOnly) {
    ScratchDir out;
    raylab::copyReleasedAssets(
        out.path(), raylab::planHandout(raylab::parseStageList("06"), raylab::Carry::Own), false);
    const std::string licence = readFile(out / "assets/LICENSES.md");
    for (const char* kept : {"## Textures (`assets/textures/`)", "| `earth.png` | 512x256 |",
                             "| `sky_px.png`, `sky_nx.png`", "### Conventions", "`raylab-texgen`"})
        EXPECT_NE(licence.find(kept), std::string::npos) << kept << "\n" << licence;
    for (const char* gone : {"fur_color.png", "fur_fin.png", "## Meshes", "tools/texgen", "tests/"})
        EXPECT_EQ(licence.find(gone), std::string::npos) << gone << "\n" << licence;
}

}  // namespace

namespace {

TEST(ReleaseAssets, ASceneOutsideTheProjectIsRefusedNotCopiedOutOfTheRelease) {
    ScratchDir dir;  // not under the project
    writeFile(dir / "mine.json", "{}");
    try {
        raylab::sceneAssets("raytrace", dir / "mine.json");
        ADD_FAILURE() << "no error";
    } catch (const raylab::Error& e) {
        EXPECT_NE(std::string(e.what()).find("is outside the project"), std::string::npos)
            << e.what();
    }
}

}  // namespace
