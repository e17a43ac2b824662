#pragma once
// The inside of the reference tracer (reference_tracer.h), shared by its
// files: the scene in double precision, the ray and hit records, and
// ReferenceTracer::Impl, whose functions each follow one GLSL file:
// reference_surface.cpp (intersections, surfaces, lights, sky, glow, colour
// modes), reference_tracer.cpp (the paths: flat, stack-based recursion) and
// reference_model.cpp (the scene converted, offsets, log text).
// Not for use outside this folder.
#include "reference_intersect.h"
#include "reference_rays.h"
#include "reference_shading.h"
#include "reference_textures.h"
#include "reference_tracer.h"
#include "scene_transform.h"
#include "shader_constants.h"

#include <glm/glm.hpp>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace raylab {

using reference::DRay;
using reference::kNoHit;

namespace refmodel {

// An object's id is kind * stride + index (shader_constants.h).
namespace obj {
using shader::kDisc;
using shader::kMesh;
using shader::kPlane;
using shader::kSphere;
using shader::kTorus;
using shader::kTriangle;
constexpr int kStride = shader::kObjectKindStride;
}  // namespace obj
using shader::kKindNames;

// trace.glsl: MAX_DEPTH (stack entries and the depth limit) and MAX_RAYS.
using shader::kMaxDepth;
using shader::kMaxRays;

struct DMaterial {
    std::string name;
    Material::Type type = Material::Type::Plastic;
    glm::dvec3 ambient{0.0}, diffuse{1.0}, specular{0.0};
    double shininess = 30.0;
    double ior = 1.5;
    glm::dvec3 n{0.0}, k{0.0};
    int texture = -1, normalMap = -1;
};

struct DSphere {
    glm::dvec3 center;
    double radius;
    int material;
};
struct DPlane {
    glm::dvec3 normal;
    double offset;
    double tile;
    int material;
};
struct DDisc {
    glm::dvec3 center, normal;
    double radius;
    int material;
};
struct DTriangle {
    glm::dvec3 a, b, c;
    int material;
};
// One triangle of a mesh (scene_meshes.glsl): corners, their normals and
// texture coordinates.
struct DMeshTriangle {
    glm::dvec3 p[3], n[3];
    glm::dvec2 uv[3];
    int material;
};
struct DTorus {
    glm::dvec3 center;
    double major, minor;
    glm::dmat3 toLocal;
    int material;
};
struct DLight {
    glm::dvec3 position, color;
};

struct Hit {
    double t = 1e30;  // T_FAR
    int id = -1;
};

// surface.glsl
struct Surface {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};  // unit, outward
    DMaterial material;
    glm::dvec2 uv{0.0};
    glm::dvec3 tangent{0.0};
};

// trace.glsl's PendingRay, numbered for the log.
struct PendingRay {
    DRay ray;
    glm::dvec3 weight{1.0};
    int depth = 1;
    int number = 1;
};

// Where a secondary ray starts (see reference_model.cpp).
glm::dvec3 offsetRayOrigin(const glm::dvec3& p, const glm::dvec3& side);

// While traceImage exports a frame's rays (reference_rays.h): where this
// thread appends the rays it casts; null otherwise. Per thread, because the
// tracer's functions are const and run on every core at once.
std::vector<TracedRay>*& tracedRays();

// Appends RAY (cast by this thread) with the answer HIT to tracedRays(),
// when a frame's rays are being exported.
void recordRay(TracedRay::Kind kind, const DRay& ray, double tMax, const Hit& hit, bool found);

// Log text: 4 significant digits.
std::string fmt(double v);
std::string fmt(const glm::dvec3& v);
std::string weightText(const glm::dvec3& w);

}  // namespace refmodel

using namespace refmodel;

struct ReferenceTracer::Impl {
    // The scene is traced in the GPU's frame (sceneFrame): the same T_MIN
    // and ray offsets then mean the same share of the scene.
    SceneTransform frame;
    ReferenceFeatures features;
    RenderSettings settings;
    double weightCut = 0.0;             // setWeightCut
    bool glowSharesPrimaryHit = false;  // setGlowSharesPrimaryHit
    glm::dvec3 background{0.0};
    std::vector<DMaterial> materials;
    std::vector<DLight> lights;
    std::vector<DSphere> spheres;
    std::vector<DPlane> planes;
    std::vector<DDisc> discs;
    std::vector<DTriangle> triangles;
    std::vector<DTorus> tori;
    std::vector<DMeshTriangle> meshTriangles;  // every mesh's, in one list (KIND_MESH)
    std::unique_ptr<reference::TextureLayers> textures;
    std::unique_ptr<reference::SkyCube> sky;
    Glow glow;
    glm::dvec3 glowColor{0.0};

    std::string objectName(int id) const;
    int materialOf(int id) const;
    static void keepNearer(Hit& hit, double t, int kind, int index);
    double intersectTorus(const DRay& ray, const DTorus& t) const;
    // find_closest.glsl (01: spheres; 05 on: every kind - a scene of an
    // earlier stage has spheres only).
    bool findClosest(const DRay& ray, Hit& hit) const;
    static glm::dvec3 sphereTangent(const glm::dvec3& d);
    glm::dvec3 textureLayer(int layer, const glm::dvec2& uv) const;
    // The material's texture at s.uv scales its ambient and diffuse colours
    // (06 surface_detail.glsl, scene_meshes.glsl).
    void applyTexture(Surface& s, std::ostream* log) const;
    // 07 normal_map.glsl
    void applyNormalMap(Surface& s, std::ostream* log) const;
    // 06 surface_detail.glsl
    void addSurfaceDetail(Surface& s, int kind, int index, std::ostream* log) const;
    // 05 surface_at.glsl (04's for spheres is the same without detail).
    Surface surfaceAt(const DRay& ray, const Hit& hit, std::ostream* log) const;
    // scene_meshes.glsl meshSurface (stage 08 scenes with meshes).
    Surface meshSurface(const glm::dvec3& point, int i, std::ostream* log) const;
    // 03 light_visibility.glsl (02: always visible).
    bool lightVisible(const glm::dvec3& point, const glm::dvec3& normal, int light,
                      std::ostream* log) const;
    // 02 blinn_phong.glsl
    glm::dvec3 blinnPhong(const glm::dvec3& point, const glm::dvec3& normal,
                          const glm::dvec3& toEye, const DMaterial& m, std::ostream* log) const;
    // 04 / 06 sky.glsl
    glm::dvec3 skyColor(const glm::dvec3& dir) const;
    // GLSL refract(): vec3(0) under total internal reflection.
    static glm::dvec3 refract(const glm::dvec3& I, const glm::dvec3& N, double eta);
    static glm::dvec3 reflect(const glm::dvec3& I, const glm::dvec3& N);
    // 06 glow.glsl
    glm::dvec3 sunGlow(const DRay& ray, std::ostream* log) const;
    // 08 color_mode.glsl
    static glm::dvec3 applyColorMode(const glm::dvec3& c, int mode);
    void recordPrimary(ReferenceSample& sample, const Hit& hit, const glm::dvec3& normal) const;
    // 01 main.frag: the flat colour of the nearest sphere.
    glm::dvec3 traceFlat(const DRay& ray, ReferenceSample& sample, std::ostream* log) const;
    // 04 trace.glsl (02/03 main.frag: the same with no secondary rays and
    // the background as sky).
    glm::dvec3 trace(const DRay& primary, ReferenceSample& sample, std::ostream* log) const;
    ReferenceSample traceSample(const DRay& ray, std::ostream* log) const;
    bool weightCounts(const glm::dvec3& weight) const;
};

}  // namespace raylab
