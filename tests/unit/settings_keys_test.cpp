// The window's settings keys, without a window: each key changes what it
// should, stays in range and says what it did.
#include "settings_keys.h"

#include <gtest/gtest.h>

using namespace raylab;

TEST(SettingsKeys, TogglesEchoTheNewState) {
    RenderSettings s;
    EXPECT_EQ(applySettingsKey(s, SDLK_1).value_or(""), "shadows off");
    EXPECT_FALSE(s.shadows);
    EXPECT_EQ(applySettingsKey(s, SDLK_g).value_or(""), "glow off");
    EXPECT_FALSE(s.glow);
    EXPECT_EQ(applySettingsKey(s, SDLK_n).value_or(""), "normal maps off");
    EXPECT_FALSE(s.normalMaps);
    EXPECT_EQ(applySettingsKey(s, SDLK_g).value_or(""), "glow on");
    EXPECT_TRUE(s.glow);
}

TEST(SettingsKeys, DepthStaysBetweenOneAndEight) {
    RenderSettings s;
    EXPECT_EQ(applySettingsKey(s, SDLK_RIGHT).value_or(""), "max depth 8");
    for (int i = 0; i < 10; ++i) applySettingsKey(s, SDLK_LEFT);
    EXPECT_EQ(s.maxDepth, 1);
    EXPECT_EQ(applySettingsKey(s, SDLK_RIGHT).value_or(""), "max depth 2");
}

TEST(SettingsKeys, UpAndDownCycleTheSeedsColourModesInOrder) {
    RenderSettings s;
    for (const char* expected : {"BRB", "BRR", "RBB", "GGR", "RGB"})
        EXPECT_EQ(applySettingsKey(s, SDLK_UP).value_or(""),
                  std::string("colour mode ") + expected);
    EXPECT_EQ(applySettingsKey(s, SDLK_DOWN).value_or(""), "colour mode GGR");
    EXPECT_EQ(s.colorMode, 4);
}

TEST(SettingsKeys, OtherKeysAreNotSettings) {
    RenderSettings s;
    EXPECT_FALSE(applySettingsKey(s, SDLK_w).has_value());
    EXPECT_FALSE(applySettingsKey(s, SDLK_p).has_value());  // pause belongs to the window's clock
    EXPECT_TRUE(s.shadows && s.glow && s.normalMaps && s.maxDepth == 8 && s.colorMode == 0);
}

TEST(SettingsKeys, FurKeysChangeShellsLengthFinsTechniqueAndMesh) {
    RenderSettings s;
    s.shells = 30;
    EXPECT_EQ(applySettingsKey(s, SDLK_RIGHTBRACKET, "fur").value_or(""), "shells 31");
    for (int i = 0; i < 40; ++i) applySettingsKey(s, SDLK_LEFTBRACKET, "fur");
    EXPECT_EQ(s.shells, 1) << "at least the skin";
    EXPECT_EQ(applySettingsKey(s, SDLK_EQUALS, "fur").value_or(""), "fur length x1.25");
    for (int i = 0; i < 20; ++i) applySettingsKey(s, SDLK_MINUS, "fur");
    EXPECT_FLOAT_EQ(s.furLength, 0.25f);
    EXPECT_EQ(applySettingsKey(s, SDLK_f, "fur").value_or(""), "fins off");
    EXPECT_EQ(applySettingsKey(s, SDLK_t, "fur").value_or(""), "technique fur_shader");
    EXPECT_EQ(applySettingsKey(s, SDLK_t, "fur").value_or(""), "technique shells_and_fins");
    for (const char* expected : {"sphere", "torus", "cube", "the scene's"})
        EXPECT_EQ(applySettingsKey(s, SDLK_m, "fur").value_or(""), std::string("mesh ") + expected);
}

TEST(SettingsKeys, EachTrackHasOnlyItsOwnKeys) {
    RenderSettings s;
    EXPECT_FALSE(applySettingsKey(s, SDLK_g, "fur").has_value()) << "glow is the ray tracer's";
    EXPECT_FALSE(applySettingsKey(s, SDLK_f, "raytrace").has_value()) << "fins are the fur's";
    const auto rows = settingsRows(s, "fur");
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_EQ(rows[2].first, "[F] fins");
}
