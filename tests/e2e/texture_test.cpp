// Textures through SDL2_image: a 2D texture arrives upright (bottom row
// first), the six sky box faces arrive in OpenGL's face order, and bad files
// are errors that name the file. Runs on both headless backends' GL (EGL here).
#include "error.h"
#include "gl_context.h"
#include "image.h"
#include "test_support.h"
#include "texture.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::test;

namespace {
Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixel(x, y);
            p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
        }
    return img;
}

// The texels of TARGET (GL_TEXTURE_2D or one cube face) of the bound texture.
std::vector<std::uint8_t> readBack(GLenum target, int w, int h) {
    std::vector<std::uint8_t> data(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
    return data;
}
}  // namespace

TEST(Texture, TwoDimensionalTextureIsStoredBottomRowFirst) {
    auto context = createEglContext();
    ScratchDir dir;
    Image img = solid(3, 2, 0, 0, 0);
    img.pixel(0, 0)[0] = 255;  // top-left red
    img.pixel(2, 1)[2] = 255;  // bottom-right blue
    writePngAtomic(img, dir / "t.png");
    Texture2D tex(dir / "t.png");
    EXPECT_EQ(tex.width(), 3);
    EXPECT_EQ(tex.height(), 2);
    glBindTexture(GL_TEXTURE_2D, tex.id());
    auto data = readBack(GL_TEXTURE_2D, 3, 2);
    // Texel row 0 is the picture's bottom row.
    EXPECT_EQ(data[(0 * 3 + 2) * 4 + 2], 255) << "bottom-right texel should be blue";
    EXPECT_EQ(data[(1 * 3 + 0) * 4 + 0], 255) << "top-left texel should be red";
    EXPECT_EQ(data[(0 * 3 + 0) * 4 + 0], 0);
}

TEST(Texture, SkyBoxFacesArriveInOpenGlOrder) {
    auto context = createEglContext();
    ScratchDir dir;
    CubeFaces faces;
    const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int i = 0; i < 6; ++i) {
        faces[std::size_t(i)] = dir / (std::string(names[i]) + ".png");
        writePngAtomic(solid(4, 4, std::uint8_t(40 * i), 7, 9), faces[std::size_t(i)]);
    }
    CubeMap sky(faces);
    EXPECT_EQ(sky.size(), 4);
    glBindTexture(GL_TEXTURE_CUBE_MAP, sky.id());
    for (int i = 0; i < 6; ++i) {
        auto data = readBack(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), 4, 4);
        EXPECT_EQ(data[0], 40 * i) << "face " << names[i];
    }
}

TEST(Texture, BadFilesAreErrorsThatNameTheFile) {
    auto context = createEglContext();
    ScratchDir dir;
    writeFile(dir / "garbage.png", "this is not a PNG");
    for (const fs::path& bad : {dir / "missing.png", dir / "garbage.png"}) {
        try {
            Texture2D tex(bad);
            ADD_FAILURE() << "no error for " << bad;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(bad.filename().string()), std::string::npos)
                << e.what();
        }
    }
    CubeFaces faces;
    for (std::size_t i = 0; i < 6; ++i) {
        faces[i] = dir / ("f" + std::to_string(i) + ".png");
        writePngAtomic(solid(i == 3 ? 8 : 4, i == 3 ? 8 : 4, 1, 2, 3), faces[i]);
    }
    try {
        CubeMap sky(faces);
        ADD_FAILURE() << "faces of different sizes must be rejected";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("f3.png"), std::string::npos) << e.what();
    }
}
