// The reference tracer's scene in double precision, where secondary rays
// start, and the text of its log (reference_model.h).
#include "reference_model.h"

#include "gpu_values.h"
#include "text_format.h"

#include <cmath>

namespace raylab {

namespace refmodel {

// Where a secondary ray (shadow, reflected, refracted) starts: the hit point
// moved off the surface toward SIDE (the normal on the side the ray leaves
// from), exactly as framework/shaders/ray_offset.glsl's offsetRayOrigin()
// moves it on the GPU: each coordinate by trunc(256 n) steps of the float
// spacing at that coordinate, or by n / 65536 where |coordinate| < 1/32.
// In double precision no offset is needed against acne (T_MIN already
// rejects self-hits); it is mirrored because where the ray starts is part of
// the model: through glass, a refracted ray started 1e-3 (the stages' old
// fixed offset) instead of ~3e-5 inside the surface lands visibly elsewhere
// (measured: 0.1-0.6% of the pixels of the glass views of stages 04-05).
// This is the one place the reference decides the offset.
double offsetCoordinate(double p, double n) {
    if (std::fabs(p) < 1.0 / 32.0) return p + n / 65536.0;
    int exponent = 0;
    std::frexp(double(float(p)),
               &exponent);  // |p| = m 2^exponent, m in [0.5, 1): float spacing 2^(exponent - 24)
    return p + std::trunc(256.0 * n) * std::ldexp(1.0, exponent - 24);
}

glm::dvec3 offsetRayOrigin(const glm::dvec3& p, const glm::dvec3& side) {
    return {offsetCoordinate(p.x, side.x), offsetCoordinate(p.y, side.y),
            offsetCoordinate(p.z, side.z)};
}

std::vector<TracedRay>*& tracedRays() {
    thread_local std::vector<TracedRay>* rays = nullptr;
    return rays;
}

void recordRay(TracedRay::Kind kind, const DRay& ray, double tMax, const Hit& hit, bool found) {
    std::vector<TracedRay>* rays = tracedRays();
    if (!rays) return;
    TracedRay r;
    r.origin = glm::vec3(ray.origin);
    r.dir = glm::vec3(ray.dir);
    r.tMax = float(tMax);
    r.kind = kind;
    r.hitId = found ? hit.id : -1;
    r.hitT = found ? float(hit.t) : 0.0f;
    rays->push_back(r);
}

std::string fmt(double v) { return significant(v, 4); }

std::string fmt(const glm::dvec3& v) {
    return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")";
}

std::string weightText(const glm::dvec3& w) { return fmt(w.x) + "," + fmt(w.y) + "," + fmt(w.z); }

}  // namespace refmodel

ReferenceTracer::ReferenceTracer(const Scene& input, const ReferenceFeatures& features,
                                 float timeSeconds, const RenderSettings& settings)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.frame = sceneFrame(input);
    const Scene scene = transformScene(input, m.frame);
    m.features = features;
    m.settings = settings;
    m.background = glm::dvec3(scene.background);
    for (const Material& mat : scene.materials) {
        DMaterial d;
        d.name = mat.name;
        d.type = mat.type;
        d.ambient = glm::dvec3(mat.ambient);
        d.diffuse = glm::dvec3(mat.diffuse);
        d.specular = glm::dvec3(mat.specular);
        d.shininess = mat.shininess;
        d.ior = mat.ior;
        d.n = glm::dvec3(mat.n);
        d.k = glm::dvec3(mat.k);
        d.texture = features.textures ? mat.texture : -1;
        d.normalMap = features.textures ? mat.normalMap : -1;
        m.materials.push_back(d);
    }
    // The scene's doubles, framed like the GPU's (in double), then each
    // position and length as the GPU receives it (gpu_values.h: rounded once
    // to float) and carried on in double: the reference traces the geometry
    // the GPU is given, so the two differ only by how they compute with it.
    auto at = [](const glm::dvec3& p) { return glm::dvec3(gpuPoint(p)); };
    auto length = [](double l) { return double(float(l)); };
    for (const PointLight& l : scene.lights)
        m.lights.push_back({at(l.position), glm::dvec3(l.color)});
    for (const Sphere& s : scene.spheres) {
        const glm::vec4 c = gpuSphere(s, timeSeconds);  // at TIMESECONDS, as sphere_blocks.cpp
        m.spheres.push_back({glm::dvec3(glm::vec3(c)), double(c.w), s.material});
    }
    for (const Plane& p : scene.planes)
        m.planes.push_back(
            {glm::dvec3(p.normal), double(gpuPlane(p).w), length(p.tileSize), p.material});
    for (const Disc& d : scene.discs)
        m.discs.push_back({at(d.center), glm::dvec3(d.normal), length(d.radius), d.material});
    for (const Triangle& t : scene.triangles)
        m.triangles.push_back(
            {at(t.vertices[0]), at(t.vertices[1]), at(t.vertices[2]), t.material});
    for (const Torus& t : scene.tori)
        m.tori.push_back(
            {at(t.center), length(t.majorRadius), length(t.minorRadius),
             reference::torusToLocal(glm::normalize(glm::dvec3(t.axisAt(timeSeconds)))),
             t.material});
    for (const MeshObject& o : scene.meshes)
        for (std::size_t t = 0; t < o.triangleCount(); ++t) {
            DMeshTriangle d{};
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t v = o.indices[3 * t + k];
                d.p[k] = at(o.positions[v]);
                d.n[k] = glm::dvec3(o.normals[v]);
                d.uv[k] = glm::dvec2(o.uvs[v]);
            }
            d.material = o.material;
            m.meshTriangles.push_back(d);
        }
    m.glow = scene.glow;
    m.glowColor = glm::dvec3(scene.glow.color);
    if (features.textures) {
        if (!scene.textures.empty())
            m.textures = std::make_unique<reference::TextureLayers>(scene.textures);
        if (scene.skyBox) m.sky = std::make_unique<reference::SkyCube>(*scene.skyBox);
    }
}

}  // namespace raylab
