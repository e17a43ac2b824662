// Debug views and ray dumps: `raylab render --view depth|normal|id|bounces|stack
// [--reference]` and `raylab rays`. The GPU views are checked against
// double-precision geometry computed here from the rays the GPU itself dumped,
// and against the CPU reference tracer; figures are printed (ctest -V).
#include "shader_constants.h"
#include "test_support.h"

#include "camera.h"
#include "error.h"
#include "image.h"
#include "pfm.h"
#include "ray_dump.h"
#include "reference_tracer.h"
#include "scene.h"
#include "stage_catalog.h"
#include "stage_setup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <set>

using namespace raylab;
using namespace raylab::test;

namespace {

// Three spheres, one partly in front of another, the camera turned a little.
const char* kSpheresScene = R"({
  "background": [0.1, 0.1, 0.1],
  "camera": { "position": [0.3, 0.9, 6.0], "yaw": 4.0, "pitch": -3.0, "fov_y": 40.0 },
  "spheres": [
    { "center": [0.0, 1.0, 0.0],   "radius": 1.0, "color": [0.9, 0.2, 0.2] },
    { "center": [1.2, 0.6, 1.5],   "radius": 0.5, "color": [0.2, 0.9, 0.2] },
    { "center": [-1.5, 0.5, -1.0], "radius": 0.8, "color": [0.2, 0.2, 0.9] }
  ]
})";

using raylab::shader::kTMin;

struct ExactHit {
    int id = -1;
    double t = 0.0;
    glm::dvec3 normal{0.0};
};

// The nearest sphere along a ray, in double (the stages' rule: smallest t > T_MIN).
ExactHit nearestSphere(const std::vector<Sphere>& spheres, const glm::dvec3& o,
                       const glm::dvec3& d) {
    ExactHit best;
    best.t = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        glm::dvec3 c(spheres[i].center), oc = o - c;
        double r = spheres[i].radius;
        double b = glm::dot(oc, d), cc = glm::dot(oc, oc) - r * r, h = b * b - cc;
        if (h < 0.0) continue;
        h = std::sqrt(h);
        double t = -b - h;
        if (t <= kTMin) t = -b + h;
        if (t > kTMin && t < best.t) {
            best.t = t;
            best.id = int(i);
            best.normal = glm::normalize(o + t * d - c);
        }
    }
    if (best.id < 0) best.t = 0.0;
    return best;
}

// |got - exact| in units in the last place of the float nearest EXACT.
double floatUlps(double exact, double got) {
    float e = std::fabs(float(exact));
    double ulp = double(std::nextafter(e, std::numeric_limits<float>::infinity())) - double(e);
    return std::fabs(got - exact) / ulp;
}

// What float32 evaluation of intersect_sphere.glsl's formula may be off by
// (a forward error bound, u = 2^-24 per operation, small constants rounded
// up): b = oc.d and c = oc.oc - r^2 lose digits in h = b^2 - c when the ray
// nearly grazes the sphere, and sqrt(h) divides that loss by sqrt(h).
constexpr double kU = 1.0 / 16777216.0;
double sphereDepthErrorBound(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c,
                             double r, double t) {
    glm::dvec3 oc = o - c;
    double len = glm::length(oc) + kU * (glm::length(o) + glm::length(c));
    double b = std::fabs(glm::dot(oc, d));
    double h = std::max(b * b - (glm::dot(oc, oc) - r * r), 1e-300);
    double errB = 6.0 * kU * len + kU * (glm::length(o) + glm::length(c));
    double errC = 8.0 * kU * (len * len + r * r);
    double errH = 2.0 * b * errB + errC + 2.0 * kU * (b * b + std::fabs(h));
    double errS = std::min(errH / (2.0 * std::sqrt(h)), std::sqrt(errH)) + kU * std::sqrt(h);
    return errB + errS + 2.0 * kU * t;
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

// A pixel on a silhouette: some pixel of its 3x3 neighbourhood shows another object.
bool onSilhouette(const std::vector<int>& ids, int w, int h, int x, int y) {
    const int id = ids[std::size_t(y) * std::size_t(w) + std::size_t(x)];
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
            if (ids[std::size_t(ny) * std::size_t(w) + std::size_t(nx)] != id) return true;
        }
    return false;
}

std::vector<int> idsOf(const FloatImage& idView) {
    std::vector<int> ids;
    for (float v : idView.values) ids.push_back(int(std::lround(v)));
    return ids;
}

// Runs raylab with ARGS and "--out FILE"; the command must succeed.
std::string raylabOk(const std::string& args, const fs::path& out) {
    CommandResult r = runRaylab(args + " --out " + quote(out));
    EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.all();
    EXPECT_TRUE(fs::exists(out)) << out;
    return r.out;
}

FloatImage renderView(const std::string& args, const std::string& view, const fs::path& dir) {
    fs::path out = dir / (view + ".pfm");
    raylabOk("render " + args + " --view " + view, out);
    return fs::exists(out) ? loadPfm(out) : FloatImage();
}

struct Agreement {
    double idMismatchShare = 0, idMismatchOffSilhouette = 0;
    double depthMaxUlps = 0, depthP99Ulps = 0;
    double normalMaxError = 0;        // objects without a normal map
    double normalMaxErrorMapped = 0;  // objects with one (stage 07 on)
    double worstDepthToBound = 0,
           worstNormalToBound = 0;  // error / tolerance, where tolerances are given
    long compared = 0;
};

struct Expected {
    std::vector<double> depth;
    std::vector<glm::dvec3> normal;
    std::vector<int> ids;
    std::vector<double> depthTolerance, normalTolerance;  // optional, per pixel
};

// Compares depth/normal/id views with expected ones pixel by pixel: ids
// everywhere (mismatches counted on and off silhouettes of the expected
// ids), depth and normal where both name the same object off the silhouettes.
Agreement compareViews(const FloatImage& depth, const FloatImage& normal,
                       const std::vector<int>& ids, const Expected& e, int w, int h,
                       const std::function<bool(int)>& normalMapped = {}) {
    Agreement a;
    std::vector<double> ulps;
    long mismatches = 0, offSilhouette = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            bool silhouette = onSilhouette(e.ids, w, h, x, y);
            if (ids[i] != e.ids[i]) {
                ++mismatches;
                if (!silhouette) ++offSilhouette;
                continue;
            }
            if (e.ids[i] < 0) {
                EXPECT_EQ(depth.values[i], 0.0f) << "a miss has depth 0 at " << x << "," << y;
                EXPECT_EQ(normal.values[3 * i], 0.0f) << "a miss has normal 0 at " << x << "," << y;
                continue;
            }
            if (silhouette) continue;
            ++a.compared;
            ulps.push_back(floatUlps(e.depth[i], depth.values[i]));
            glm::dvec3 n(normal.values[3 * i], normal.values[3 * i + 1], normal.values[3 * i + 2]);
            double nErr = glm::length(n - e.normal[i]);
            double& worst =
                normalMapped && normalMapped(e.ids[i]) ? a.normalMaxErrorMapped : a.normalMaxError;
            worst = std::max(worst, nErr);
            if (!e.depthTolerance.empty())
                a.worstDepthToBound =
                    std::max(a.worstDepthToBound,
                             std::fabs(double(depth.values[i]) - e.depth[i]) / e.depthTolerance[i]);
            if (!e.normalTolerance.empty())
                a.worstNormalToBound = std::max(a.worstNormalToBound, nErr / e.normalTolerance[i]);
        }
    a.idMismatchShare = double(mismatches) / double(w * h);
    a.idMismatchOffSilhouette = double(offSilhouette);
    a.depthMaxUlps = ulps.empty() ? 0 : *std::max_element(ulps.begin(), ulps.end());
    a.depthP99Ulps = percentile(ulps, 0.99);
    return a;
}

}  // namespace

// Stage 01 (sphere normal computed in view_main.frag) and stage 04
// (surfaceAt()): depth, normal and id equal the exact geometry of the GPU's
// own rays within float precision.
TEST(Views, DepthNormalAndIdEqualTheAnalyticSphereHits) {
    ScratchDir dir;
    writeFile(dir / "spheres.json", kSpheresScene);
    Scene scene = loadScene(dir / "spheres.json");
    const int w = 96, h = 72;
    for (const char* stage : {"01", "04"}) {
        SCOPED_TRACE(std::string("stage ") + stage);
        fs::path sub = dir / stage;
        fs::create_directories(sub);
        std::string args = std::string("--stage ") + stage + " --solution --size 96x72 --scene " +
                           quote(dir / "spheres.json");
        raylabOk("rays " + args, sub / "rays.bin");
        RayDump rays = loadRayDump(sub / "rays.bin");
        FloatImage depth = renderView(args, "depth", sub), normal = renderView(args, "normal", sub),
                   id = renderView(args, "id", sub);
        ASSERT_EQ(depth.channels, 1);
        ASSERT_EQ(normal.channels, 3);
        ASSERT_EQ(id.channels, 1);
        ASSERT_EQ(depth.width, w);
        ASSERT_EQ(id.height, h);

        Expected exp;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float *o = rays.origin(x, y), *d = rays.dir(x, y);
                glm::dvec3 origin(o[0], o[1], o[2]);
                ExactHit e = nearestSphere(scene.spheres, origin, glm::dvec3(d[0], d[1], d[2]));
                exp.depth.push_back(e.t);
                exp.normal.push_back(e.normal);
                exp.ids.push_back(e.id);
                double tol = 1.0, ntol = 1.0;
                if (e.id >= 0) {
                    const Sphere& s = scene.spheres[std::size_t(e.id)];
                    tol = sphereDepthErrorBound(origin, glm::dvec3(d[0], d[1], d[2]),
                                                glm::dvec3(s.center), s.radius, e.t);
                    // p = o + t d carries t's error; |p - c| = r; then normalize.
                    ntol = (tol +
                            8.0 * kU *
                                (glm::length(origin) + glm::length(glm::dvec3(s.center)) + e.t)) /
                               s.radius +
                           8.0 * kU;
                }
                exp.depthTolerance.push_back(tol);
                exp.normalTolerance.push_back(ntol);
            }
        std::vector<int> ids = idsOf(id);
        std::set<int> seen(ids.begin(), ids.end());
        EXPECT_EQ(seen, (std::set<int>{-1, 0, 1, 2}))
            << "the id view names the three spheres and the background";

        Agreement a = compareViews(depth, normal, ids, exp, w, h);
        std::printf("[views] stage %s, %dx%d, GPU views vs double geometry of the GPU's rays: %ld "
                    "pixels compared; depth error "
                    "max %.2f / p99 %.2f float ulps (at most %.2f of the float formula's error "
                    "bound); normal error max %.2e "
                    "(%.2f of its bound); id mismatches %.3f%% (%g off silhouettes)\n",
                    stage, w, h, a.compared, a.depthMaxUlps, a.depthP99Ulps, a.worstDepthToBound,
                    a.normalMaxError, a.worstNormalToBound, 100.0 * a.idMismatchShare,
                    a.idMismatchOffSilhouette);
        EXPECT_GT(a.compared, 1000);
        EXPECT_EQ(a.idMismatchOffSilhouette, 0);
        EXPECT_LE(a.idMismatchShare, 0.01);
        EXPECT_LE(a.worstDepthToBound, 1.0) << "depth beyond float precision";
        EXPECT_LE(a.worstNormalToBound, 1.0) << "normal beyond float precision";
    }
}

// The dump holds the GPU's rays: unit directions, the eye as origin, the
// rays of primaryRay() within a few float ulps; and intersecting them in
// double here reproduces the GPU id view's mask of every sphere except on
// silhouettes.
TEST(Views, RayDumpHoldsTheGpusPrimaryRays) {
    ScratchDir dir;
    const int w = 80, h = 60;
    const std::string camera = "0.4,1.2,6.5,3,-5";
    std::string args = "--stage 01 --solution --size 80x60 --camera " + camera;
    std::string line = raylabOk("rays " + args, dir / "rays.bin");
    EXPECT_NE(line.find("80x60"), std::string::npos) << line;
    std::string bytes = readFile(dir / "rays.bin");
    ASSERT_EQ(bytes.size(), 16u + 24u * w * h);
    EXPECT_EQ(bytes.substr(0, 8), "RLRAYS01");
    RayDump rays = loadRayDump(dir / "rays.bin");
    ASSERT_EQ(rays.width, w);
    ASSERT_EQ(rays.height, h);

    Scene scene = loadScene(sourceDir() / "assets/scenes/stage01.json");
    Camera cam = cameraFor(parseCamera(camera), scene);
    double maxLengthError = 0, maxUlps = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float *o = rays.origin(x, y), *d = rays.dir(x, y);
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(o[c], float(cam.pose().position[c])) << "the origin is the eye";
            glm::dvec3 dir3(d[0], d[1], d[2]);
            maxLengthError = std::max(maxLengthError, std::fabs(glm::length(dir3) - 1.0));
            PrimaryRay ref = primaryRay(cam, w, h, x, y);
            for (int c = 0; c < 3; ++c)
                maxUlps = std::max(maxUlps, std::fabs(dir3[c] - ref.dir[c]) / std::ldexp(1.0, -24));
        }
    std::printf("[views] ray dump %dx%d: | |dir| - 1 | max %.2e; direction vs primaryRay() "
                "(double) max %.2f ulps of 1 (2^-24)\n",
                w, h, maxLengthError, maxUlps);
    EXPECT_LE(maxLengthError, 1e-6);
    EXPECT_LE(maxUlps, 8.0);

    // An outside program's intersection of the dumped rays against the id view.
    FloatImage id = renderView(args, "id", dir.path());
    ASSERT_EQ(id.width, w);
    std::vector<int> ids = idsOf(id), exact;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float *o = rays.origin(x, y), *d = rays.dir(x, y);
            exact.push_back(nearestSphere(scene.spheres, glm::dvec3(o[0], o[1], o[2]),
                                          glm::dvec3(d[0], d[1], d[2]))
                                .id);
        }
    long differ = 0, differOff = 0, spheresSeen = 0;
    for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
        long pixels = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                bool gpu = ids[i] == int(s), here = exact[i] == int(s);
                pixels += here;
                if (gpu != here) {
                    ++differ;
                    if (!onSilhouette(exact, w, h, x, y)) ++differOff;
                }
            }
        spheresSeen += pixels > 0;
    }
    std::printf("[views] sphere masks of the dumped rays (double) vs the GPU id view: %ld pixels "
                "differ, %ld off silhouettes, %ld spheres seen\n",
                differ, differOff, spheresSeen);
    EXPECT_GE(spheresSeen, 3);
    EXPECT_EQ(differOff, 0);
}

// Stage 08, lite scene, small: the GPU's depth, normal and id views against
// the CPU reference tracer's.
TEST(Views, GpuViewsAgreeWithTheReferenceOnStage08Lite) {
    ScratchDir dir;
    const int w = 96, h = 72;
    std::string args = "--stage 08 --solution --size 96x72";
    fs::path gpuDir = dir / "gpu", refDir = dir / "ref";
    fs::create_directories(gpuDir);
    fs::create_directories(refDir);
    FloatImage depth = renderView(args, "depth", gpuDir),
               normal = renderView(args, "normal", gpuDir), id = renderView(args, "id", gpuDir);
    FloatImage rDepth = renderView(args + " --reference", "depth", refDir),
               rNormal = renderView(args + " --reference", "normal", refDir),
               rId = renderView(args + " --reference", "id", refDir);
    ASSERT_EQ(depth.width, w);
    ASSERT_EQ(rDepth.width, w);
    Expected exp;
    exp.depth.assign(rDepth.values.begin(), rDepth.values.end());
    for (std::size_t i = 0; i < std::size_t(w * h); ++i)
        exp.normal.emplace_back(rNormal.values[3 * i], rNormal.values[3 * i + 1],
                                rNormal.values[3 * i + 2]);
    exp.ids = idsOf(rId);
    std::vector<int> ids = idsOf(id);
    std::set<int> kinds;
    for (int v : exp.ids)
        if (v >= 0) kinds.insert(v / raylab::shader::kObjectKindStride);
    EXPECT_GE(kinds.size(), 2u) << "lite shows spheres and other kinds of object";

    // Normal-mapped spheres (earth, moon): the GPU's bilinear filter weighs
    // texels with less precision than the reference's doubles.
    Scene lite = loadScene(sourceDir() / "assets/scenes/lite.json");
    auto normalMapped = [&](int objectId) {
        return objectId >= 0 && objectId < raylab::shader::kObjectKindStride &&
               std::size_t(objectId) < lite.spheres.size() &&
               lite.materials[std::size_t(lite.spheres[std::size_t(objectId)].material)]
                       .normalMap >= 0;
    };
    Agreement a = compareViews(depth, normal, ids, exp, w, h, normalMapped);
    std::printf("[views] stage 08 lite %dx%d, GPU vs reference: %ld pixels compared; depth error "
                "max %.2f / p99 %.2f float ulps; "
                "normal error max %.2e (normal-mapped spheres %.2e); id mismatches %.3f%% of the "
                "pixels (%g off silhouettes)\n",
                w, h, a.compared, a.depthMaxUlps, a.depthP99Ulps, a.normalMaxError,
                a.normalMaxErrorMapped, 100.0 * a.idMismatchShare, a.idMismatchOffSilhouette);
    EXPECT_GT(a.compared, 1000);
    EXPECT_EQ(a.idMismatchOffSilhouette, 0);
    EXPECT_LE(a.idMismatchShare, 0.01);
    EXPECT_LE(a.depthP99Ulps, 16.0);
    EXPECT_LE(a.normalMaxError, 1e-4);
    EXPECT_LE(a.normalMaxErrorMapped, 0.05);

    // Bounces and stack exist with the reference only: PNG and PFM.
    std::string out =
        raylabOk("render " + args + " --reference --view bounces", dir / "bounces.png");
    EXPECT_NE(out.find("rays per pixel"), std::string::npos) << out;
    EXPECT_NE(out.find("mapped to blue..yellow"), std::string::npos) << out;
    FloatImage bounces = renderView(args + " --reference", "bounces", dir.path()),
               stack = renderView(args + " --reference", "stack", dir.path());
    ASSERT_EQ(bounces.channels, 1);
    float minRays = *std::min_element(bounces.values.begin(), bounces.values.end());
    float maxRays = *std::max_element(bounces.values.begin(), bounces.values.end());
    float maxStack = *std::max_element(stack.values.begin(), stack.values.end());
    std::printf("[views] stage 08 lite reference: rays per pixel %g..%g, stack depth up to %g\n",
                minRays, maxRays, maxStack);
    EXPECT_GE(minRays, 1.0f);
    EXPECT_GT(maxRays, 1.0f) << "lite has mirrors and glass";
    EXPECT_GE(maxStack, 1.0f) << "lite has glass";
}

TEST(Views, PfmRoundTrip) {
    FloatImage grey(3, 2, 1), rgb(2, 3, 3);
    for (std::size_t i = 0; i < grey.values.size(); ++i) grey.values[i] = float(i) * 1.5f - 2.0f;
    grey.values[4] = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < rgb.values.size(); ++i)
        rgb.values[i] = std::ldexp(float(i) + 0.25f, int(i) - 8);
    std::string bytes = encodePfm(grey);
    EXPECT_EQ(bytes.substr(0, 12), "Pf\n3 2\n-1.0\n");
    EXPECT_EQ(bytes.size(), 12u + 6u * 4u);
    float firstStored = 0;
    std::memcpy(&firstStored, bytes.data() + 12, 4);  // little-endian host
    EXPECT_EQ(firstStored, grey.at(0, 1)[0]) << "rows are stored bottom to top";
    FloatImage back = decodePfm(bytes);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.channels, 1);
    EXPECT_EQ(back.values, grey.values);

    ScratchDir dir;
    writePfmAtomic(rgb, dir / "rgb.pfm");
    EXPECT_EQ(readFile(dir / "rgb.pfm").substr(0, 3), "PF\n");
    FloatImage rgbBack = loadPfm(dir / "rgb.pfm");
    EXPECT_EQ(rgbBack.channels, 3);
    EXPECT_EQ(rgbBack.values, rgb.values);
    EXPECT_THROW(decodePfm("P6\n1 1\n255\nabc"), Error);
    EXPECT_THROW(decodePfm(bytes.substr(0, bytes.size() - 1)), Error);
}

// The file name chooses: .png a picture for people, .pfm raw floats.
TEST(Views, FileNameChoosesPngOrPfm) {
    ScratchDir dir;
    writeFile(dir / "spheres.json", kSpheresScene);
    std::string args =
        "render --stage 01 --solution --size 64x48 --scene " + quote(dir / "spheres.json");
    std::string line = raylabOk(args + " --view depth", dir / "depth.png");
    EXPECT_NE(line.find("mapped to white..grey"), std::string::npos) << line;
    EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1) << line;
    Image png = loadPng(dir / "depth.png");
    ASSERT_EQ(png.width, 64);
    EXPECT_EQ(png.pixel(0, 0)[0], 0) << "a miss is black";
    std::uint8_t brightest = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) brightest = std::max(brightest, png.pixel(x, y)[0]);
    EXPECT_EQ(brightest, 255) << "the nearest hit is white";

    line = raylabOk(args + " --view depth", dir / "depth.pfm");
    EXPECT_NE(line.find("0 for misses"), std::string::npos) << line;
    EXPECT_EQ(readFile(dir / "depth.pfm").substr(0, 3), "Pf\n");
    raylabOk(args + " --view normal", dir / "normal.pfm");
    EXPECT_EQ(readFile(dir / "normal.pfm").substr(0, 3), "PF\n");
    raylabOk(args + " --view color", dir / "color.pfm");
    FloatImage color = loadPfm(dir / "color.pfm");
    EXPECT_EQ(color.channels, 3);
    EXPECT_NEAR(color.at(0, 0)[0], 0.1f, 1e-6f) << "the background colour, linear";
    raylabOk(args + " --view id", dir / "id.png");
    Image ids = loadPng(dir / "id.png");
    EXPECT_EQ(ids.pixel(0, 0)[0] + ids.pixel(0, 0)[1] + ids.pixel(0, 0)[2], 0) << "a miss is black";
    const std::uint8_t* centre = ids.pixel(32, 24);
    EXPECT_GT(centre[0] + centre[1] + centre[2], 0) << "an object has a colour";
    // The default view is still the plain frame.
    raylabOk(args, dir / "frame.png");
    Image frame = loadPng(dir / "frame.png");
    EXPECT_EQ(frame.pixel(0, 0)[0], 26) << "background 0.1";
}

TEST(Views, BadInputIsOneLineExitTwoAndNoFile) {
    ScratchDir dir;
    struct Case {
        const char* name;
        std::string args;
        const char* expected;
    };
    const Case cases[] = {
        {"unknown-view",
         "render --stage 01 --solution --size 32x24 --view heat --out " + quote(dir / "a.png"),
         "unknown view 'heat'"},
        {"bounces-gpu",
         "render --stage 04 --solution --size 32x24 --view bounces --out " + quote(dir / "b.png"),
         "needs --reference"},
        {"stack-gpu",
         "render --stage 04 --solution --size 32x24 --view stack --out " + quote(dir / "c.pfm"),
         "needs --reference"},
        {"jpg",
         "render --stage 01 --solution --size 32x24 --view depth --out " + quote(dir / "d.jpg"),
         "must end in .png"},
        {"no-extension",
         "render --stage 01 --solution --size 32x24 --view id --reference --out " +
             quote(dir / "e"),
         ".pfm"},
        {"rays-folder",
         "rays --stage 01 --solution --size 32x24 --out " + quote(dir / "no/such/rays.bin"),
         "does not exist"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        CommandResult r = runRaylab(c.args);
        EXPECT_EQ(r.exitCode, 2) << r.all();
        EXPECT_EQ(r.out, "");
        EXPECT_EQ(r.err.rfind("raylab: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    }
    EXPECT_TRUE(fs::is_empty(dir.path())) << "no file written, not even a temporary one";
}

// view_main.frag builds on every stage's own files, the shipped labs (TODOs
// open) included: a view never fails to compile where the frame compiles.
TEST(Views, EveryStageDrawsItsGpuViewsFromTheLab) {
    ScratchDir dir;
    for (const StageInfo& stage : allStages()) {
        if (stage.track != "raytrace") continue;  // the debug views are the ray tracer's
        SCOPED_TRACE(stage.id);
        fs::path out = dir / (stage.number() + "-normal.pfm");
        raylabOk("render --stage " + stage.number() + " --view normal --size 16x12", out);
        if (fs::exists(out)) { EXPECT_EQ(loadPfm(out).channels, 3); }
    }
}
