// The same stage, scene, camera and size give the same image headless through
// EGL, headless through OSMesa, and in a real window (under Xvfb).
#include "image.h"
#include "image_compare.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

namespace {
const std::string kView = "--stage 01 --solution --size 96x72 --camera 1.2,1.5,6,-10,-6 --time 0.7";

raylab::Image render(const ScratchDir& dir, const std::string& backend) {
    fs::path out = dir / (backend + ".png");
    CommandResult r = runRaylab("render " + kView + " --backend " + backend + " --out " + quote(out));
    EXPECT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find(backend + " backend"), std::string::npos) << r.all();
    return raylab::loadPng(out);
}
} // namespace

TEST(Backends, EglAndOsMesaGiveTheSameImage) {
    ScratchDir dir;
    raylab::Image egl = render(dir, "egl"), osmesa = render(dir, "osmesa");
    raylab::ImageDiff d = raylab::compareImages(egl, osmesa, raylab::CompareTolerance{}.channel);
    // Both are Mesa's llvmpipe here: expect bit-identical output, not merely close.
    EXPECT_EQ(d.maxDiff, 0) << raylab::describe(d);
    EXPECT_EQ(egl.rgba, osmesa.rgba);
}

TEST(Backends, WindowUnderXvfbGivesTheHeadlessImage) {
    if (runCommand("command -v xvfb-run").exitCode != 0) GTEST_SKIP() << "xvfb-run is not installed (install.sh installs it)";
    ScratchDir dir;
    raylab::Image headless = render(dir, "egl");
    fs::path shot = dir / "window.png";
    // 24-bit screen: xvfb-run's default 8-bit screen has no OpenGL visual.
    CommandResult r = runCommand("xvfb-run -a -s '-screen 0 640x480x24' " + quote(RAYLAB_EXE) + " run " + kView +
                                 " --frames 3 --screenshot " + quote(shot));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    raylab::Image window = raylab::loadPng(shot);
    raylab::ImageDiff d = raylab::compareImages(window, headless, raylab::CompareTolerance{}.channel);
    EXPECT_EQ(d.maxDiff, 0) << raylab::describe(d);
}
