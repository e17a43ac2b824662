// Stage 08 with more spheres than plain uniform arrays allow: the spheres'
// arrays live in uniform blocks (framework/src/raytrace/sphere_blocks.h).
// A thousand spheres - far past the old limit of 128 - through the BVH, the
// linear search and the specialised program, against the CPU reference
// tracer with the graders' metric and tolerance; the same comparison shown
// failing when the blocks hold wrong data; more spheres than a uniform
// block holds through storage blocks (OpenGL 4.3), also shown failing; and
// a scene larger than every block the device offers refused with one line
// naming the limits.
#include "error.h"
#include "growth_scenes.h"
#include "image_compare.h"
#include "reference_tracer.h"
#include "sphere_blocks.h"
#include "stage_renderer.h"
#include "stage_setup.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

using namespace raylab;

namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr int kSpheres = 1000;
constexpr float kTime = 0.7f;  // the moving spheres are off their rest positions

const StageInfo& full() { return demoStage(); }

// N - 1 small spheres on the growth bench's jittered grid in [-1, 1]^3
// above a floor, in four materials (some mirrors), every hundredth one
// moving; then one big mirror in front, the last sphere (a wrong entry of
// its own shows in many pixels).
Scene manySpheres(int n) {
    Scene s = growthSphereScene(n - 1);
    s.file = "spheres.json";
    const int clay = 0;  // growthBaseScene's; 1 is the floor
    const int green = int(s.materials.size()), blue = green + 1, mirror = green + 2;
    for (glm::vec3 colour :
         {glm::vec3(0.2f, 0.6f, 0.3f), glm::vec3(0.3f, 0.4f, 0.9f), glm::vec3(0.9f, 0.9f, 0.9f)}) {
        Material m;
        m.name = "m" + std::to_string(s.materials.size());
        m.ambient = 0.1f * colour;
        m.diffuse = colour;
        m.specular = glm::vec3(0.4f);
        s.materials.push_back(m);
    }
    s.materials[std::size_t(mirror)].type = Material::Type::Mirror;
    const int kinds[4] = {clay, green, blue, mirror};
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        Sphere& sphere = s.spheres[i];
        sphere.material = kinds[(i * 7) % 4];
        if (i % 100 == 37)
            sphere.motion = {glm::vec3(0.0f, 1.0f, 0.0f), 1.5f * sphere.radius, 3.0f};
    }
    Sphere big;
    big.center = glm::vec3(0.75f, -0.55f, 1.6f);
    big.radius = 0.45f;
    big.material = mirror;
    s.spheres.push_back(big);
    return s;
}

Image pictureOf(StageRenderer& r) {
    long nonFinite = 0;
    Image image = imageFromFloats(r.target().readFloats(), kWidth, kHeight, &nonFinite);
    EXPECT_EQ(nonFinite, 0);
    return image;
}

Image render(const Scene& scene, const ShaderVariant& variant) {
    raylab::test::ensureGlContext();
    StageRenderer r(full(), solutionSources(full()), scene, kWidth, kHeight, PixelFormat::Rgba32F,
                    "", variant);
    r.render(cameraFor(std::nullopt, scene), kTime);
    return pictureOf(r);
}

// The current context's storage blocks, or a reason to skip the test.
bool hasStorageBlocks() {
    raylab::test::ensureGlContext();
    return sphereArrayLimits().storageBlockBytes > 0;
}

Image reference(const Scene& scene) {
    ReferenceTracer tracer(scene, ReferenceFeatures::forStage(full()), kTime, RenderSettings{});
    return referenceImage(tracer.traceImage(cameraFor(std::nullopt, scene), kWidth, kHeight),
                          kWidth, kHeight);
}

ImageDiff diff(const Image& a, const Image& b) {
    return compareImages(a, b, CompareTolerance{}.channel);
}

// Renders SCENE (generic program, BVH) once, lets SPOIL overwrite part of
// the buffer at binding point BINDING (0: centres, 2: materials,
// sphere_blocks.cpp) of TARGET (GL_UNIFORM_BUFFER, or
// GL_SHADER_STORAGE_BUFFER for a scene past a uniform block), and renders
// the same frame again.
Image renderSpoiled(const Scene& scene, GLuint binding, const std::function<void()>& spoil,
                    GLenum target = GL_UNIFORM_BUFFER) {
    raylab::test::ensureGlContext();
    StageRenderer r(full(), solutionSources(full()), scene, kWidth, kHeight, PixelFormat::Rgba32F);
    const Camera camera = cameraFor(std::nullopt, scene);
    r.render(camera, kTime);
    // The renderer leaves its buffers bound to their binding points; the
    // same time uploads nothing again.
    GLint buffer = 0;
    glGetIntegeri_v(target == GL_UNIFORM_BUFFER ? GL_UNIFORM_BUFFER_BINDING
                                                : GL_SHADER_STORAGE_BUFFER_BINDING,
                    binding, &buffer);
    EXPECT_NE(buffer, 0);
    glBindBuffer(GL_UNIFORM_BUFFER, GLuint(buffer));  // any target writes the buffer's data
    spoil();
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    r.render(camera, kTime);
    return pictureOf(r);
}

}  // namespace

TEST(SphereBlocks, AThousandSpheresDrawWhatTheReferenceTracerDraws) {
    const Scene scene = manySpheres(kSpheres);
    const Image ref = reference(scene);
    ShaderVariant linear, specialised;
    linear.bvh = false;
    specialised.specialized = true;
    const struct {
        const char* name;
        ShaderVariant variant;
    } programs[] = {
        {"BVH", ShaderVariant{}}, {"linear search", linear}, {"specialised", specialised}};
    for (const auto& p : programs) {
        ImageDiff d = diff(render(scene, p.variant), ref);
        std::printf("[ figure ] %d spheres, %s against the reference tracer: %.3f%% of pixels "
                    "differ (max %d/255)\n",
                    kSpheres, p.name, 100.0 * d.badShare, d.maxDiff);
        EXPECT_TRUE(imagesAgree(d, CompareTolerance{}))
            << p.name << ": " << 100.0 * d.badShare << "% of pixels differ";
    }
}

// What a block that kept the old limit would show: spheres 128.. read zeros.
TEST(SphereBlocks, CentresCutAtTheOldLimitAreCaught) {
    const Scene scene = manySpheres(kSpheres);
    const Image spoiled = renderSpoiled(scene, 0, [] {
        std::vector<glm::vec4> zeros(kSpheres - 128, glm::vec4(0.0f));
        glBufferSubData(GL_UNIFORM_BUFFER, 128 * kSphereBlockStride,
                        GLsizeiptr(zeros.size() * sizeof(glm::vec4)), zeros.data());
    });
    ImageDiff d = diff(spoiled, reference(scene));
    std::printf("[ figure ] spheres 128..999 zeroed vs the reference: %.3f%% of pixels differ\n",
                100.0 * d.badShare);
    EXPECT_FALSE(imagesAgree(d, CompareTolerance{})) << "lost spheres went unnoticed";
}

// One sphere's entry wrong in a block: the big mirror half its size, or
// made of clay.
TEST(SphereBlocks, OneSphereUploadedWrongIsCaught) {
    const Scene scene = manySpheres(kSpheres);
    const Sphere& big = scene.spheres.back();
    const GLintptr at = (kSpheres - 1) * kSphereBlockStride;
    const Image ref = reference(scene);
    const Image smaller = renderSpoiled(scene, 0, [&] {
        const glm::vec4 wrong(big.center, 0.5f * big.radius);  // inside its BVH box
        glBufferSubData(GL_UNIFORM_BUFFER, at, sizeof wrong, &wrong);
    });
    const Image clay = renderSpoiled(scene, 2, [&] {
        const glm::ivec4 wrong(0);
        glBufferSubData(GL_UNIFORM_BUFFER, at, sizeof wrong, &wrong);
    });
    ImageDiff d1 = diff(smaller, ref), d2 = diff(clay, ref);
    std::printf("[ figure ] sphere %d wrong vs the reference: half its radius %.3f%% of pixels "
                "differ, material 0 %.3f%%\n",
                kSpheres - 1, 100.0 * d1.badShare, 100.0 * d2.badShare);
    EXPECT_FALSE(imagesAgree(d1, CompareTolerance{})) << "a wrong centre entry went unnoticed";
    EXPECT_FALSE(imagesAgree(d2, CompareTolerance{})) << "a wrong material entry went unnoticed";
}

// Past a uniform block (4096 spheres on llvmpipe and NVIDIA): the same
// arrays as storage blocks, through the BVH and the specialised program,
// against the reference tracer; and a wrong centre there caught.
TEST(SphereBlocks, MoreSpheresThanAUniformBlockHoldsComeInStorageBlocks) {
    if (!hasStorageBlocks()) GTEST_SKIP() << "this context has no storage blocks (OpenGL 4.3)";
    const int n = maxUniformBlockBytes() / kSphereBlockStride + 1000;
    const Scene scene = manySpheres(n);
    ASSERT_TRUE(spheresNeedStorage(scene, sphereArrayLimits()));
    const Image ref = reference(scene);
    ShaderVariant specialised;
    specialised.specialized = true;
    for (const auto& [name, variant] :
         {std::pair{"BVH", ShaderVariant{}}, std::pair{"specialised", specialised}}) {
        ImageDiff d = diff(render(scene, variant), ref);
        std::printf("[ figure ] %d spheres (storage blocks), %s against the reference tracer: "
                    "%.3f%% of pixels differ (max %d/255)\n",
                    n, name, 100.0 * d.badShare, d.maxDiff);
        EXPECT_TRUE(imagesAgree(d, CompareTolerance{}))
            << name << ": " << 100.0 * d.badShare << "% of pixels differ";
    }
    const Sphere& big = scene.spheres.back();  // the last entry: past any uniform block
    const Image smaller = renderSpoiled(
        scene, 0,
        [&] {
            const glm::vec4 wrong(big.center, 0.5f * big.radius);
            glBufferSubData(GL_UNIFORM_BUFFER, GLintptr(n - 1) * kSphereBlockStride, sizeof wrong,
                            &wrong);
        },
        GL_SHADER_STORAGE_BUFFER);
    ImageDiff d = diff(smaller, ref);
    std::printf("[ figure ] sphere %d half its radius in the storage block: %.3f%% of pixels "
                "differ\n",
                n - 1, 100.0 * d.badShare);
    EXPECT_FALSE(imagesAgree(d, CompareTolerance{})) << "a wrong storage entry went unnoticed";
}

// A device without storage blocks (OpenGL 3.3 to 4.2), or with small ones:
// a scene past its blocks is refused in one line naming the limits; the
// arrays' declared length follows the device's uniform blocks.
TEST(SphereBlocks, ScenesPastEveryBlockAreRefusedInOneLine) {
    const Scene fits = manySpheres(1024), tooMany = manySpheres(1025);
    const SphereArrayLimits gl33{16384, 0}, small{16384, 32768};
    EXPECT_FALSE(spheresNeedStorage(fits, gl33));
    EXPECT_TRUE(spheresNeedStorage(tooMany, small));
    const struct {
        SphereArrayLimits limits;
        const Scene& scene;
        std::string expected;
    } refused[] = {
        {gl33, tooMany,
         "spheres.json: spheres: 1025 spheres, but this GPU's uniform blocks hold at most 1024 "
         "(GL_MAX_UNIFORM_BLOCK_SIZE 16384 bytes, 16 per sphere) and it has no storage blocks "
         "(OpenGL 4.3)"},
        {small, manySpheres(2049),
         "spheres.json: spheres: 2049 spheres, but this GPU's uniform blocks hold at most 1024 "
         "(GL_MAX_UNIFORM_BLOCK_SIZE 16384 bytes, 16 per sphere) and its storage blocks 2048 "
         "(GL_MAX_SHADER_STORAGE_BLOCK_SIZE 32768 bytes)"},
    };
    for (const auto& c : refused) {
        try {
            spheresNeedStorage(c.scene, c.limits);
            ADD_FAILURE() << c.scene.spheres.size() << " spheres were accepted";
        } catch (const Error& e) { EXPECT_EQ(std::string(e.what()), c.expected); }
    }
    ShaderVariant generic;
    EXPECT_EQ(sphereSlots(full(), fits, generic), 4096);  // `raylab shader`: a 64 KB block
    generic.maxBlockBytes = 16384;
    EXPECT_EQ(sphereSlots(full(), fits, generic), 1024);
    generic.sphereStorage = true;
    EXPECT_EQ(sphereSlots(full(), tooMany, generic), 1025);  // storage: the scene's own count
    ShaderVariant specialised;
    specialised.specialized = true;
    EXPECT_EQ(sphereSlots(full(), tooMany, specialised), 1025);
}
