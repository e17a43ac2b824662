// raylab-texgen (tools/texgen): the committed textures in assets/textures/
// are exactly what the generator makes (and the comparison that says so can
// fail), normal maps point the documented way, planets and patterns wrap
// without a seam, and the sky box faces join without seams under OpenGL's
// cube map rules - both by the specification's table and on a real GL.
#include "framebuffer.h"
#include "gl.h"
#include "gl_context.h"
#include "image.h"
#include "test_support.h"
#include "texgen/cube_map.h"
#include "texgen/normal_map.h"
#include "texture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

using namespace raylab;
using namespace raylab::test;

namespace {

const fs::path kCommitted = sourceDir() / "assets/textures";

CommandResult runTexgen(const std::string& args) {
    return runCommand(quote(RAYLAB_TEXGEN_EXE) + " " + args);
}

std::set<std::string> pngNames(const fs::path& dir) {
    std::set<std::string> names;
    std::error_code ec;
    if (fs::is_directory(dir, ec))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".png") names.insert(e.path().filename().string());
    return names;
}

std::string rgba(const std::uint8_t* p) {
    std::ostringstream s;
    s << "(" << int(p[0]) << ", " << int(p[1]) << ", " << int(p[2]) << ", " << int(p[3]) << ")";
    return s.str();
}

// One line per problem between the committed textures and freshly generated
// ones; empty when every file exists on both sides, has the same size, and
// every channel of all but 0.1% of the pixels is within 1/255. Room for a
// libm that rounds a last bit differently on another CPU (glibc picks FMA
// code paths by CPU), which may also tip a few star pixels over a brightness
// threshold; a change to the generator itself moves far more pixels.
std::vector<std::string> textureDifferences(const fs::path& committed, const fs::path& generated) {
    std::vector<std::string> problems;
    const std::set<std::string> have = pngNames(committed), made = pngNames(generated);
    for (const std::string& name : made)
        if (!have.count(name))
            problems.push_back(
                name + ": generated but not committed (run build/raylab-texgen assets/textures)");
    for (const std::string& name : have)
        if (!made.count(name))
            problems.push_back(name + ": committed but raylab-texgen does not make it");
    for (const std::string& name : have) {
        if (!made.count(name)) continue;
        const Image expected = loadPng(committed / name), actual = loadPng(generated / name);
        if (expected.width != actual.width || expected.height != actual.height) {
            problems.push_back(name + ": committed " + std::to_string(expected.width) + "x" +
                               std::to_string(expected.height) + ", generated " +
                               std::to_string(actual.width) + "x" + std::to_string(actual.height));
            continue;
        }
        int off = 0;
        std::string first;
        for (int y = 0; y < expected.height; ++y)
            for (int x = 0; x < expected.width; ++x) {
                const std::uint8_t *e = expected.pixel(x, y), *a = actual.pixel(x, y);
                bool differs = false;
                for (int c = 0; c < 4; ++c) differs |= std::abs(int(e[c]) - int(a[c])) > 1;
                if (differs && off++ == 0)
                    first = "first at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            "): expected " + rgba(e) + ", got " + rgba(a);
            }
        const int allowed = expected.width * expected.height / 1000;
        if (off > allowed)
            problems.push_back(name + ": " + std::to_string(off) +
                               " pixels differ by more than 1/255 (at most " +
                               std::to_string(allowed) + " may), " + first);
    }
    return problems;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string all;
    for (const std::string& l : lines) all += l + "\n";
    return all;
}

bool anyContains(const std::vector<std::string>& lines, const std::string& a,
                 const std::string& b = "") {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) {
        return l.find(a) != std::string::npos && l.find(b) != std::string::npos;
    });
}

}  // namespace

// The generator is deterministic and the committed files are its output.
TEST(Texgen, CommittedTexturesAreReproduced) {
    ScratchDir out;
    CommandResult r = runTexgen(quote(out.path()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::set<std::string> made = pngNames(out.path());
    // One line per file written.
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), long(made.size())) << r.out;
    // The set the later stages rely on, with the documented sizes, opaque
    // except the fins' strands (alpha is their coverage: some of it clear,
    // some of it solid).
    const std::map<std::string, std::pair<int, int>> sizes = {
        {"earth.png", {512, 256}},       {"earth_normal.png", {512, 256}},
        {"moon.png", {256, 128}},        {"moon_normal.png", {256, 128}},
        {"sun.png", {256, 128}},         {"sky_px.png", {256, 256}},
        {"sky_nx.png", {256, 256}},      {"sky_py.png", {256, 256}},
        {"sky_ny.png", {256, 256}},      {"sky_pz.png", {256, 256}},
        {"sky_nz.png", {256, 256}},      {"tiles.png", {256, 256}},
        {"marble.png", {256, 256}},      {"fur_color.png", {256, 256}},
        {"fur_pattern.png", {128, 128}}, {"fur_fin.png", {128, 64}},
    };
    EXPECT_EQ(made.size(), sizes.size());
    for (const auto& [name, size] : sizes) {
        ASSERT_TRUE(made.count(name)) << name << " not generated";
        const Image img = loadPng(out / name);
        EXPECT_EQ(img.width, size.first) << name;
        EXPECT_EQ(img.height, size.second) << name;
        bool opaque = true, clear = false;
        for (std::size_t i = 3; i < img.rgba.size(); i += 4) {
            opaque &= img.rgba[i] == 255;
            clear |= img.rgba[i] == 0;
        }
        if (name == "fur_fin.png") EXPECT_TRUE(clear && !opaque) << name;
        else EXPECT_TRUE(opaque) << name;
    }
    const std::vector<std::string> problems = textureDifferences(kCommitted, out.path());
    EXPECT_TRUE(problems.empty()) << "assets/textures differs from what raylab-texgen makes:\n"
                                  << joined(problems);
}

// The comparison above is not vacuous: a changed patch, a missing file and a
// stray file are all reported; a 1/255 rounding difference and a few stray
// pixels are not.
TEST(Texgen, ComparisonCatchesChangedAndMissingFiles) {
    ScratchDir copy;
    for (const std::string& name : pngNames(kCommitted))
        fs::copy_file(kCommitted / name, copy / name);
    ASSERT_TRUE(textureDifferences(kCommitted, copy.path()).empty());

    Image earth = loadPng(copy / "earth.png");
    std::uint8_t* p = earth.pixel(100, 50);
    p[1] = std::uint8_t(p[1] < 128 ? p[1] + 1 : p[1] - 1);  // within tolerance
    writePngAtomic(earth, copy / "earth.png");
    EXPECT_TRUE(textureDifferences(kCommitted, copy.path()).empty())
        << joined(textureDifferences(kCommitted, copy.path()));

    p[2] = std::uint8_t(p[2] < 128 ? p[2] + 2 : p[2] - 2);  // beyond it, but one pixel: allowed
    writePngAtomic(earth, copy / "earth.png");
    EXPECT_TRUE(textureDifferences(kCommitted, copy.path()).empty())
        << joined(textureDifferences(kCommitted, copy.path()));

    for (int y = 50; y < 70; ++y)  // a 20x20 patch: 0.3% of the picture
        for (int x = 100; x < 120; ++x)
            earth.pixel(x, y)[2] = std::uint8_t(earth.pixel(x, y)[2] ^ 0x40);
    writePngAtomic(earth, copy / "earth.png");
    fs::remove(copy / "moon.png");
    writePngAtomic(Image(4, 4), copy / "stray.png");
    const std::vector<std::string> problems = textureDifferences(kCommitted, copy.path());
    EXPECT_EQ(problems.size(), 3u) << joined(problems);
    EXPECT_TRUE(anyContains(problems, "earth.png", "pixel (100, 50)")) << joined(problems);
    EXPECT_TRUE(anyContains(problems, "moon.png", "committed but")) << joined(problems);
    EXPECT_TRUE(anyContains(problems, "stray.png", "not committed")) << joined(problems);
}

TEST(Texgen, UnwritableOutputFolderIsAOneLineError) {
    ScratchDir dir;
    writeFile(dir / "file", "not a folder");
    CommandResult r = runTexgen(quote(dir / "file" / "textures"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("raylab-texgen: error: cannot write"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(runTexgen("").exitCode, 0) << "OUTDIR is required";
}

// ---- Normal maps (encoding documented in tools/texgen/normal_map.h) --------

TEST(NormalMap, FlatHeightFieldPointsStraightOut) {
    texgen::HeightField flat(32, 16);
    const Image n = texgen::sphereNormalMap(flat, 1.0);
    ASSERT_EQ(n.width, 32);
    ASSERT_EQ(n.height, 16);
    for (int y = 0; y < n.height; ++y)
        for (int x = 0; x < n.width; ++x) {
            const std::uint8_t* p = n.pixel(x, y);
            EXPECT_NEAR(p[0], 127.5, 1.0) << x << "," << y;
            EXPECT_NEAR(p[1], 127.5, 1.0) << x << "," << y;
            EXPECT_EQ(p[2], 255) << x << "," << y;
            EXPECT_EQ(p[3], 255);
        }
}

// Height rising toward +u (east): the surface faces west, R < 128, G flat.
// Rising toward the top row (north, +v): it faces south, G < 128.
TEST(NormalMap, SlopesTiltTheNormalAgainstTheRise) {
    const int w = 64, h = 32;
    texgen::HeightField east(w, h), north(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            east.at(x, y) = 0.02 * x;
            north.at(x, y) = 0.02 * (h - 1 - y);
        }
    const Image e = texgen::sphereNormalMap(east, 1.0), n = texgen::sphereNormalMap(north, 1.0);
    // Column 0 and the last see the wrap-around jump of the ramp, the polar
    // rows the neighbour across the pole: leave those out.
    for (int y = 1; y < h - 1; ++y)
        for (int x = 1; x < w - 1; ++x) {
            EXPECT_LT(e.pixel(x, y)[0], 128) << x << "," << y;
            EXPECT_NEAR(e.pixel(x, y)[1], 127.5, 1.0) << x << "," << y;
            EXPECT_LT(e.pixel(x, y)[2], 255) << x << "," << y;
            EXPECT_NEAR(n.pixel(x, y)[0], 127.5, 1.0) << x << "," << y;
            EXPECT_LT(n.pixel(x, y)[1], 128) << x << "," << y;
        }
    // Slopes are per arc on the sphere: one column is a shorter arc near the
    // poles, so the same step per column is steeper there than at the equator.
    EXPECT_LT(e.pixel(10, 3)[0], e.pixel(10, h / 2)[0]);
    // The north slope does not depend on latitude.
    EXPECT_NEAR(n.pixel(10, 3)[1], n.pixel(10, h / 2)[1], 1.0);
}

TEST(NormalMap, CommittedNormalMapsHaveRelief) {
    for (const char* name : {"earth_normal.png", "moon_normal.png"}) {
        const Image n = loadPng(kCommitted / name);
        int tilted = 0, flat = 0;
        for (int y = 0; y < n.height; ++y)
            for (int x = 0; x < n.width; ++x) {
                const std::uint8_t* p = n.pixel(x, y);
                tilted += p[2] < 230;  // more than about 25 degrees off the surface normal
                flat += p[2] >= 254;
                ASSERT_GE(p[2], 128) << name << " points into the surface at " << x << "," << y;
            }
        const int total = n.width * n.height;
        EXPECT_GT(tilted, total / 100) << name << ": bumps too weak to see";
        if (std::string(name) == "earth_normal.png") {
            EXPECT_GT(flat, total / 2) << "the sea must stay flat";
        }
    }
}

// ---- Wrap-around -----------------------------------------------------------

namespace {
// Mean over the rows (or columns) of the largest channel difference between
// two columns (or rows) of IMG. Compared with the mean over every pair of
// neighbours inside the image, since single columns vary with the content.
double meanStep(const Image& img, bool columns, int a, int b) {
    const int count = columns ? img.height : img.width;
    double sum = 0;
    for (int i = 0; i < count; ++i) {
        const std::uint8_t* p = columns ? img.pixel(a, i) : img.pixel(i, a);
        const std::uint8_t* q = columns ? img.pixel(b, i) : img.pixel(i, b);
        int diff = 0;
        for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(p[c]) - int(q[c])));
        sum += diff;
    }
    return sum / count;
}
}  // namespace

// The step from the last column to the first (u = 1 to u = 0) is no bigger
// than an ordinary step between neighbouring columns: no seam on the
// planets' date line, and the patterns also wrap from bottom to top.
TEST(Texgen, TexturesWrapWithoutSeams) {
    for (const char* name : {"earth.png", "earth_normal.png", "moon.png", "moon_normal.png",
                             "sun.png", "tiles.png", "marble.png"}) {
        const Image img = loadPng(kCommitted / name);
        const int w = img.width, h = img.height;
        const double seam = meanStep(img, true, w - 1, 0);
        double inside = 0;
        for (int x = 1; x < w; ++x) inside += meanStep(img, true, x - 1, x) / (w - 1);
        EXPECT_LE(seam, 2.0 * inside + 1.0) << name << ": columns " << w - 1 << " -> 0";
        if (img.width == img.height) {  // the tileable patterns
            const double seamV = meanStep(img, false, h - 1, 0);
            double insideV = 0;
            for (int y = 1; y < h; ++y) insideV += meanStep(img, false, y - 1, y) / (h - 1);
            EXPECT_LE(seamV, 2.0 * insideV + 1.0) << name << ": rows " << h - 1 << " -> 0";
        }
    }
}

// ---- Sky box ---------------------------------------------------------------

namespace {

// The OpenGL specification's cube map table (4.6 core, table 8.19), written
// as data: the major axis and its sign select the face, and
// sc = sSign * r[sAxis], tc = tSign * r[tAxis]. Faces in
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + i order. Independent of the generator's
// hand-inverted formulas, which this checks.
struct FaceRule {
    int major, sAxis, tAxis;
    double sSign, tSign;
};
const FaceRule kGlTable[6] = {
    {0, 2, 1, -1, -1},  // +X: sc = -rz, tc = -ry
    {0, 2, 1, +1, -1},  // -X: sc = +rz, tc = -ry
    {1, 0, 2, +1, +1},  // +Y: sc = +rx, tc = +rz
    {1, 0, 2, +1, -1},  // -Y: sc = +rx, tc = -rz
    {2, 0, 1, +1, -1},  // +Z: sc = +rx, tc = -ry
    {2, 0, 1, -1, -1},  // -Z: sc = -rx, tc = -ry
};

using Dir = std::array<double, 3>;

// Point (s, t) of FACE's plane (s, t may run past [-1, 1]) as a direction.
Dir faceDirection(int face, double s, double t) {
    const FaceRule& f = kGlTable[face];
    Dir d{};
    d[std::size_t(f.major)] = face % 2 == 0 ? 1.0 : -1.0;
    d[std::size_t(f.sAxis)] = s * f.sSign;
    d[std::size_t(f.tAxis)] = t * f.tSign;
    return d;
}

struct Texel {
    int face, x, y;
};

// What the GPU samples for direction D (nearest texel).
Texel lookUp(const Dir& d, int size) {
    int major = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(d[std::size_t(i)]) > std::abs(d[std::size_t(major)])) major = i;
    const int face = 2 * major + (d[std::size_t(major)] < 0 ? 1 : 0);
    const FaceRule& f = kGlTable[face];
    const double ma = std::abs(d[std::size_t(major)]);
    const double s = (f.sSign * d[std::size_t(f.sAxis)] / ma + 1.0) / 2.0,
                 t = (f.tSign * d[std::size_t(f.tAxis)] / ma + 1.0) / 2.0;
    auto texel = [size](double c) { return std::clamp(int(std::floor(c * size)), 0, size - 1); };
    return {face, texel(s), texel(t)};
}

struct EdgeStats {
    int pairs = 0, off = 0;  // border pixels; those unlike their neighbour across the edge
};

// Every border pixel against the pixel across the edge on the adjacent face
// (found through the GL table from the point one pixel beyond the border).
// Off: some channel differs by more than TOLERANCE. A few star pixels are
// expected (a star's core can sit right at the edge: its neighbour then sees
// the flank, as inside a face).
EdgeStats compareEdges(const std::array<Image, 6>& faces, int tolerance) {
    const int n = faces[0].width;
    EdgeStats stats;
    for (int face = 0; face < 6; ++face)
        for (int i = 0; i < n; ++i) {
            const int border[4][4] = {
                {0, i, -1, 0}, {n - 1, i, 1, 0}, {i, 0, 0, -1}, {i, n - 1, 0, 1}};  // x, y, step
            for (const auto& b : border) {
                const double s = 2.0 * (b[0] + b[2] + 0.5) / n - 1.0,
                             t = 2.0 * (b[1] + b[3] + 0.5) / n - 1.0;
                const Texel other = lookUp(faceDirection(face, s, t), n);
                if (other.face == face)
                    ADD_FAILURE() << "beyond the border of face " << face << " is the same face";
                const std::uint8_t* p = faces[std::size_t(face)].pixel(b[0], b[1]);
                const std::uint8_t* q = faces[std::size_t(other.face)].pixel(other.x, other.y);
                int diff = 0;
                for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(p[c]) - int(q[c])));
                ++stats.pairs;
                stats.off += diff > tolerance;
            }
        }
    return stats;
}

std::array<Image, 6> loadSky() {
    std::array<Image, 6> faces;
    const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (std::size_t i = 0; i < 6; ++i)
        faces[i] = loadPng(kCommitted / (std::string("sky_") + names[i] + ".png"));
    return faces;
}

}  // namespace

TEST(SkyBox, FacesJoinWithoutSeamsInOpenGlOrientation) {
    const std::array<Image, 6> faces = loadSky();
    for (const Image& f : faces) ASSERT_EQ(f.width, faces[0].width);
    const int tolerance = 4;
    // The same statistic one step inside each face, between neighbouring
    // columns: what "continuous" looks like in this picture.
    int inside = 0, insideOff = 0;
    for (const Image& f : faces)
        for (int y = 0; y < f.height; ++y)
            for (int x : {f.width / 2, f.width / 4}) {
                int diff = 0;
                for (int c = 0; c < 3; ++c)
                    diff =
                        std::max(diff, std::abs(int(f.pixel(x, y)[c]) - int(f.pixel(x + 1, y)[c])));
                ++inside;
                insideOff += diff > tolerance;
            }
    const EdgeStats edges = compareEdges(faces, tolerance);
    const double edgeRate = double(edges.off) / edges.pairs,
                 insideRate = double(insideOff) / inside;
    EXPECT_LT(edgeRate, 2.0 * insideRate + 0.005)
        << edges.off << " of " << edges.pairs
        << " border pixels unlike their neighbour across the edge; inside a face " << insideOff
        << " of " << inside;

    // The check can fail: faces stored bottom row first (as a 2D texture
    // would be) break the joins.
    std::array<Image, 6> flipped = faces;
    for (Image& f : flipped)
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x)
                std::copy_n(faces[std::size_t(&f - flipped.data())].pixel(x, f.height - 1 - y), 4,
                            f.pixel(x, y));
    const EdgeStats wrong = compareEdges(flipped, tolerance);
    EXPECT_GT(double(wrong.off) / wrong.pairs, 3.0 * edgeRate + 0.01)
        << wrong.off << " of " << wrong.pairs;
}

// The generator's pixel -> direction mapping (tools/texgen/cube_map.cpp)
// against a real OpenGL cube map lookup (Mesa, EGL): the direction through
// every texel centre of every face must fetch exactly that texel when the
// faces are uploaded the way the framework's CubeMap does.
TEST(SkyBox, FaceMappingAgreesWithOpenGl) {
    auto context = createEglContext();
    const int n = 16;
    // Made first: creating it rebinds GL_TEXTURE_2D on the active unit.
    Framebuffer target(n, 6 * n);
    ScratchDir dir;
    CubeFaces files;
    for (int face = 0; face < 6; ++face) {
        Image img(n, n);  // each texel names itself: (x, y, face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                std::uint8_t* p = img.pixel(x, y);
                p[0] = std::uint8_t(x * 16), p[1] = std::uint8_t(y * 16),
                p[2] = std::uint8_t(face * 40), p[3] = 255;
            }
        files[std::size_t(face)] = dir / (std::to_string(face) + ".png");
        writePngAtomic(img, files[std::size_t(face)]);
    }
    CubeMap cube(files);
    cube.bind(0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    // One fragment per texel: row face * n + y of a float texture holds the
    // generator's direction for (face, x, y).
    std::vector<float> dirs;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const texgen::Vec3 d = texgen::cubeFaceDirection(face, x, y, n);
                dirs.insert(dirs.end(), {float(d.x), float(d.y), float(d.z)});
            }
    GLuint dirTex = 0;
    glGenTextures(1, &dirTex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, dirTex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, n, 6 * n, 0, GL_RGB, GL_FLOAT, dirs.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    auto compile = [](GLenum type, const char* src) {
        GLuint sh = glCreateShader(type);
        glShaderSource(sh, 1, &src, nullptr);
        glCompileShader(sh);
        GLint ok = 0;
        glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
        char log[1024] = "";
        glGetShaderInfoLog(sh, sizeof log, nullptr, log);
        EXPECT_TRUE(ok) << log;
        return sh;
    };
    const char* vs = "#version 330 core\n"
                     "void main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); "
                     "gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n";
    const char* fs = "#version 330 core\n"
                     "uniform sampler2D uDirs; uniform samplerCube uCube; out vec4 color;\n"
                     "void main() { color = textureLod(uCube, texelFetch(uDirs, "
                     "ivec2(gl_FragCoord.xy), 0).xyz, 0.0); }\n";
    GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, vs));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(program);
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "uCube"), 0);
    glUniform1i(glGetUniformLocation(program, "uDirs"), 1);
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    target.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const Image got = target.read();  // top row first: GL row r is image row 6n - 1 - r
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    int wrong = 0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::uint8_t* p = got.pixel(x, 6 * n - 1 - (face * n + y));
                if (p[0] != x * 16 || p[1] != y * 16 || p[2] != face * 40) {
                    if (++wrong <= 5)
                        ADD_FAILURE()
                            << "face " << texgen::kCubeFaceNames[std::size_t(face)] << " texel ("
                            << x << ", " << y << "): OpenGL fetched face " << int(p[2]) / 40
                            << " texel (" << int(p[0]) / 16 << ", " << int(p[1]) / 16 << ")";
                }
            }
    EXPECT_EQ(wrong, 0);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
    glDeleteTextures(1, &dirTex);
}
