// The reference tracer (reference_tracer.h): the GLSL of solution/ redone in
// double precision, function by function. Each function below names the
// GLSL file it follows.
#include "reference_tracer.h"

#include "reference_intersect.h"
#include "reference_shading.h"
#include "text_format.h"
#include "reference_textures.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>

namespace raylab {

using reference::DRay;
using reference::fresnelConductor;
using reference::fresnelDielectric;
using reference::kNoHit;
using reference::planeUV;
using reference::sphereUV;

ReferenceFeatures ReferenceFeatures::forStage(const StageInfo& stage) {
    ReferenceFeatures f;
    f.shading = stage.has("shading");
    f.shadows = stage.has("shadows");
    f.recursion = stage.has("recursion");
    f.textures = stage.has("textures");
    f.normalMaps = stage.has("normal_maps");
    f.colorModes = stage.has("color_modes");
    return f;
}

PrimaryRay primaryRay(const Camera& camera, int width, int height, int x, int y) {
    // camera.cpp's forward/right/up/focal length, in double.
    const CameraPose& pose = camera.pose();
    const double yaw = glm::radians(double(pose.yawDeg)), pitch = glm::radians(double(pose.pitchDeg));
    const glm::dvec3 forward(std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double focal = 1.0 / std::tan(glm::radians(double(camera.fovYDeg())) * 0.5);
    // canvas.vert's corner ray, interpolated linearly to the pixel centre;
    // y = 0 is the top row of the saved picture (GL's row height - 1).
    const double aspect = double(width) / double(height);
    const double ndcX = 2.0 * (double(x) + 0.5) / double(width) - 1.0;
    const double ndcY = 1.0 - 2.0 * (double(y) + 0.5) / double(height);
    PrimaryRay ray;
    ray.origin = glm::dvec3(pose.position);
    ray.dir = glm::normalize(forward * focal + right * (aspect * ndcX) + up * ndcY);
    return ray;
}

Image referenceImage(const std::vector<ReferenceSample>& samples, int width, int height, long* nonFinite) {
    std::vector<float> rgba(std::size_t(width) * std::size_t(height) * 4, 1.0f);
    for (std::size_t i = 0; i < samples.size() && i < std::size_t(width) * std::size_t(height); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + std::size_t(c)] = float(samples[i].color[c]);
    return imageFromFloats(rgba, width, height, nonFinite);
}

namespace {

// An object's id is kind * stride + index (shader_constants.h).
namespace obj {
using shader::kDisc;
using shader::kPlane;
using shader::kSphere;
using shader::kTorus;
using shader::kTriangle;
constexpr int kStride = shader::kObjectKindStride;
} // namespace obj
using shader::kKindNames;

// trace.glsl: MAX_DEPTH (stack entries and the depth limit) and MAX_RAYS.
using shader::kMaxDepth;
using shader::kMaxRays;

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
    std::frexp(double(float(p)), &exponent);  // |p| = m 2^exponent, m in [0.5, 1): float spacing 2^(exponent - 24)
    return p + std::trunc(256.0 * n) * std::ldexp(1.0, exponent - 24);
}

glm::dvec3 offsetRayOrigin(const glm::dvec3& p, const glm::dvec3& side) {
    return {offsetCoordinate(p.x, side.x), offsetCoordinate(p.y, side.y), offsetCoordinate(p.z, side.z)};
}

struct DMaterial {
    std::string name;
    Material::Type type = Material::Type::Plastic;
    glm::dvec3 ambient{0.0}, diffuse{1.0}, specular{0.0};
    double shininess = 30.0;
    double ior = 1.5;
    glm::dvec3 n{0.0}, k{0.0};
    int texture = -1, normalMap = -1;
};

struct DSphere { glm::dvec3 center; double radius; int material; };
struct DPlane { glm::dvec3 normal; double offset; double tile; int material; };
struct DDisc { glm::dvec3 center, normal; double radius; int material; };
struct DTriangle { glm::dvec3 a, b, c; int material; };
struct DTorus { glm::dvec3 center; double major, minor; glm::dmat3 toLocal; int material; };
struct DLight { glm::dvec3 position, color; };

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

std::string fmt(double v) { return significant(v, 4); }

std::string fmt(const glm::dvec3& v) { return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")"; }

std::string weightText(const glm::dvec3& w) { return fmt(w.x) + "," + fmt(w.y) + "," + fmt(w.z); }

constexpr double kPi = 3.14159265358979;

} // namespace

struct ReferenceTracer::Impl {
    ReferenceFeatures features;
    RenderSettings settings;
    glm::dvec3 background{0.0};
    std::vector<DMaterial> materials;
    std::vector<DLight> lights;
    std::vector<DSphere> spheres;
    std::vector<DPlane> planes;
    std::vector<DDisc> discs;
    std::vector<DTriangle> triangles;
    std::vector<DTorus> tori;
    std::unique_ptr<reference::TextureLayers> textures;
    std::unique_ptr<reference::SkyCube> sky;
    Glow glow;
    glm::dvec3 glowColor{0.0};

    std::string objectName(int id) const {
        const int kind = id / obj::kStride, index = id - kind * obj::kStride;
        return std::string(kKindNames[kind]) + " " + std::to_string(index);
    }

    int materialOf(int id) const {
        const int kind = id / obj::kStride, i = id - kind * obj::kStride;
        switch (kind) {
        case obj::kSphere: return spheres[std::size_t(i)].material;
        case obj::kPlane: return planes[std::size_t(i)].material;
        case obj::kDisc: return discs[std::size_t(i)].material;
        case obj::kTriangle: return triangles[std::size_t(i)].material;
        default: return tori[std::size_t(i)].material;
        }
    }

    static void keepNearer(Hit& hit, double t, int kind, int index) {
        if (t != kNoHit && t < hit.t) hit = Hit{t, kind * obj::kStride + index};
    }

    double intersectTorus(const DRay& ray, const DTorus& t) const {
        DRay local{t.toLocal * (ray.origin - t.center), t.toLocal * ray.dir};
        return reference::intersectTorusLocal(local, t.major, t.minor);
    }

    // find_closest.glsl (01: spheres; 05 on: every kind - a scene of an
    // earlier stage has spheres only).
    bool findClosest(const DRay& ray, Hit& hit) const {
        hit = Hit{};
        for (std::size_t i = 0; i < spheres.size(); ++i)
            keepNearer(hit, reference::intersectSphere(ray, spheres[i].center, spheres[i].radius), obj::kSphere, int(i));
        for (std::size_t i = 0; i < planes.size(); ++i)
            keepNearer(hit, reference::intersectPlane(ray, planes[i].normal, planes[i].offset), obj::kPlane, int(i));
        for (std::size_t i = 0; i < discs.size(); ++i)
            keepNearer(hit, reference::intersectDisc(ray, discs[i].center, discs[i].normal, discs[i].radius), obj::kDisc, int(i));
        for (std::size_t i = 0; i < triangles.size(); ++i)
            keepNearer(hit, reference::intersectTriangle(ray, triangles[i].a, triangles[i].b, triangles[i].c), obj::kTriangle, int(i));
        for (std::size_t i = 0; i < tori.size(); ++i) keepNearer(hit, intersectTorus(ray, tori[i]), obj::kTorus, int(i));
        return hit.id >= 0;
    }

    static glm::dvec3 sphereTangent(const glm::dvec3& d) {
        const glm::dvec3 east(d.z, 0.0, -d.x);
        const double len = glm::length(east);
        return len > 1e-6 ? east / len : glm::dvec3(1.0, 0.0, 0.0);
    }

    glm::dvec3 textureLayer(int layer, const glm::dvec2& uv) const {
        return textures ? glm::dvec3(textures->sample(layer, uv)) : glm::dvec3(0.0);
    }

    // 07 normal_map.glsl
    void applyNormalMap(Surface& s, std::ostream* log) const {
        if (!features.normalMaps || !settings.normalMaps || s.material.normalMap < 0) return;
        const glm::dvec3 N = s.normal;
        const glm::dvec3 along = s.tangent - glm::dot(s.tangent, N) * N;
        if (glm::length(along) == 0.0) return;  // no tangent (the GLSL would give NaN; scene files refuse this)
        const glm::dvec3 T = glm::normalize(along);
        const glm::dvec3 B = glm::cross(N, T);
        const glm::dvec3 m = textureLayer(s.material.normalMap, s.uv) * 2.0 - 1.0;
        s.normal = glm::normalize(T * m.x + B * m.y + N * m.z);
        if (log) *log << "  normal map (layer " << s.material.normalMap << "): tangent-space " << fmt(m) << ", normal tilted to " << fmt(s.normal) << "\n";
    }

    // 06 surface_detail.glsl
    void addSurfaceDetail(Surface& s, int kind, int index, std::ostream* log) const {
        if (!features.textures) return;  // stage 05's surface_detail.glsl is empty
        if (kind == obj::kSphere) {
            const glm::dvec3 d = glm::normalize(s.point - spheres[std::size_t(index)].center);
            s.uv = sphereUV(d);
            s.tangent = sphereTangent(d);
        } else if (kind == obj::kPlane) {
            const DPlane& p = planes[std::size_t(index)];
            s.uv = planeUV(s.point, p.normal * p.offset, s.normal, p.tile);
        } else if (kind == obj::kDisc) {
            const DDisc& d = discs[std::size_t(index)];
            s.uv = planeUV(s.point, d.center, s.normal, 2.0 * d.radius) + 0.5;
        }
        if (s.material.texture >= 0) {
            const glm::dvec3 picture = textureLayer(s.material.texture, s.uv);
            s.material.ambient *= picture;
            s.material.diffuse *= picture;
            if (log) *log << "  texture (layer " << s.material.texture << ") at uv (" << fmt(s.uv.x) << ", " << fmt(s.uv.y) << "): " << fmt(picture) << "\n";
        }
        applyNormalMap(s, log);
    }

    // 05 surface_at.glsl (04's for spheres is the same without detail).
    Surface surfaceAt(const DRay& ray, const Hit& hit, std::ostream* log) const {
        Surface s;
        s.point = ray.origin + hit.t * ray.dir;
        const int kind = hit.id / obj::kStride, i = hit.id - kind * obj::kStride;
        if (kind == obj::kSphere) {
            s.normal = glm::normalize(s.point - spheres[std::size_t(i)].center);
        } else if (kind == obj::kPlane) {
            s.normal = planes[std::size_t(i)].normal;
        } else if (kind == obj::kDisc) {
            s.normal = discs[std::size_t(i)].normal;
        } else if (kind == obj::kTriangle) {
            const DTriangle& t = triangles[std::size_t(i)];
            s.normal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
        } else {
            const DTorus& t = tori[std::size_t(i)];
            s.normal = glm::transpose(t.toLocal) * reference::torusNormalLocal(t.toLocal * (s.point - t.center), t.major, t.minor);
        }
        s.material = materials[std::size_t(materialOf(hit.id))];
        addSurfaceDetail(s, kind, i, log);
        return s;
    }

    // 03 light_visibility.glsl (02: always visible).
    bool lightVisible(const glm::dvec3& point, const glm::dvec3& normal, int light, std::ostream* log) const {
        if (!features.shadows || !settings.shadows) return true;
        const glm::dvec3 toLight = lights[std::size_t(light)].position - point;
        const double distanceToLight = glm::length(toLight);
        const glm::dvec3 dir = toLight / distanceToLight;
        const glm::dvec3 side = glm::dot(normal, dir) >= 0.0 ? normal : -normal;
        Hit blocker;
        const bool blocked = findClosest(DRay{offsetRayOrigin(point, side), dir}, blocker) && blocker.t < distanceToLight;
        if (blocked && log)
            *log << "  light " << light << ": in shadow, blocked by " << objectName(blocker.id) << " at t=" << fmt(blocker.t) << " (light at "
                 << fmt(distanceToLight) << ")\n";
        return !blocked;
    }

    // 02 blinn_phong.glsl
    glm::dvec3 blinnPhong(const glm::dvec3& point, const glm::dvec3& normal, const glm::dvec3& toEye, const DMaterial& m,
                          std::ostream* log) const {
        glm::dvec3 color = m.ambient;
        for (std::size_t i = 0; i < lights.size(); ++i) {
            if (!lightVisible(point, normal, int(i), log)) continue;
            const glm::dvec3 toLight = glm::normalize(lights[i].position - point);
            const double lambert = std::max(glm::dot(normal, toLight), 0.0);
            glm::dvec3 diffuse = lights[i].color * m.diffuse * lambert, specular(0.0);
            if (lambert > 0.0) {
                const glm::dvec3 halfway = glm::normalize(toLight + toEye);
                specular = lights[i].color * m.specular * std::pow(std::max(glm::dot(normal, halfway), 0.0), m.shininess);
            }
            color += diffuse + specular;
            if (log) *log << "  light " << i << ": visible, N.L " << fmt(lambert) << ", diffuse " << fmt(diffuse) << ", specular " << fmt(specular) << "\n";
        }
        return color;
    }

    // 04 / 06 sky.glsl
    glm::dvec3 skyColor(const glm::dvec3& dir) const {
        if (!features.textures || !sky) return background;
        return glm::dvec3(sky->sample(dir));
    }

    // GLSL refract(): vec3(0) under total internal reflection.
    static glm::dvec3 refract(const glm::dvec3& I, const glm::dvec3& N, double eta) {
        const double cosI = glm::dot(N, I);
        const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
        if (k < 0.0) return glm::dvec3(0.0);
        return eta * I - (eta * cosI + std::sqrt(k)) * N;
    }

    static glm::dvec3 reflect(const glm::dvec3& I, const glm::dvec3& N) { return I - 2.0 * glm::dot(N, I) * N; }

    // 06 glow.glsl
    glm::dvec3 sunGlow(const DRay& ray, std::ostream* log) const {
        if (glow.sphere < 0) return glm::dvec3(0.0);
        const glm::dvec3 c = spheres[std::size_t(glow.sphere)].center;
        const double r = spheres[std::size_t(glow.sphere)].radius;
        const double tc = glm::dot(c - ray.origin, ray.dir);
        if (tc < 0.0) {
            if (log) *log << "glow: none (the sun is behind the eye)\n";
            return glm::dvec3(0.0);
        }
        Hit blocker;
        if (findClosest(ray, blocker) && blocker.id != obj::kSphere * obj::kStride + glow.sphere && blocker.t < tc) {
            if (log) *log << "glow: none (" << objectName(blocker.id) << " at t=" << fmt(blocker.t) << " is in front of the sun)\n";
            return glm::dvec3(0.0);
        }
        const double dist = glm::length(ray.origin + tc * ray.dir - c);
        const double x = std::max(dist - r, 0.0) / (double(glow.size) * r);
        if (x >= 1.0) {
            if (log) *log << "glow: none (passes " << fmt(dist) << " from the sun's centre, beyond the halo)\n";
            return glm::dvec3(0.0);
        }
        const double fade = 1.0 - x;
        const glm::dvec3 g = glowColor * fade * fade * fade;
        if (log) *log << "glow: adds " << fmt(g) << " (x " << fmt(x) << ")\n";
        return g;
    }

    // 08 color_mode.glsl
    static glm::dvec3 applyColorMode(const glm::dvec3& c, int mode) {
        switch (mode) {
        case 1: return {c.b, c.r, c.b};
        case 2: return {c.b, c.r, c.r};
        case 3: return {c.r, c.b, c.b};
        case 4: return {c.g, c.g, c.r};
        default: return c;
        }
    }

    void recordPrimary(ReferenceSample& sample, const Hit& hit, const glm::dvec3& normal) const {
        sample.depth = hit.t;
        sample.id = hit.id;
        sample.normal = normal;
    }

    // 01 main.frag: the flat colour of the nearest sphere.
    glm::dvec3 traceFlat(const DRay& ray, ReferenceSample& sample, std::ostream* log) const {
        sample.rays = 1;
        Hit hit;
        if (!findClosest(ray, hit)) {
            if (log) *log << "ray 1: misses everything: background " << fmt(background) << "\n";
            return background;
        }
        const glm::dvec3 point = ray.origin + hit.t * ray.dir;
        const int kind = hit.id / obj::kStride, i = hit.id - kind * obj::kStride;
        glm::dvec3 normal = kind == obj::kSphere ? glm::normalize(point - spheres[std::size_t(i)].center) : surfaceAt(ray, hit, nullptr).normal;
        recordPrimary(sample, hit, normal);
        const DMaterial& m = materials[std::size_t(materialOf(hit.id))];
        if (log)
            *log << "ray 1: hits " << objectName(hit.id) << " '" << m.name << "' at t=" << fmt(hit.t) << " point " << fmt(point)
                 << ": flat colour " << fmt(m.diffuse) << "\n";
        return m.diffuse;
    }

    // 04 trace.glsl (02/03 main.frag: the same with no secondary rays and
    // the background as sky).
    glm::dvec3 trace(const DRay& primary, ReferenceSample& sample, std::ostream* log) const {
        PendingRay stack[kMaxDepth];
        int stackSize = 0;
        glm::dvec3 color(0.0);
        PendingRay current{primary, glm::dvec3(1.0), 1, 1};
        int numbered = 1;
        const int maxDepth = features.recursion ? settings.maxDepth : 1;

        for (int n = 0; n < kMaxRays; ++n) {
            ++sample.rays;
            bool pathGoesOn = false;
            Hit hit;
            if (log) *log << "ray " << current.number << " (depth " << current.depth << ", weight " << weightText(current.weight) << "): ";
            if (!findClosest(current.ray, hit)) {
                const glm::dvec3 skyRgb = skyColor(current.ray.dir);
                color += current.weight * skyRgb;
                if (log) *log << "misses everything\n  miss: " << (features.textures && sky ? "sky " : "background ") << fmt(skyRgb)
                              << ", adds colour " << fmt(current.weight * skyRgb) << "\n";
            } else {
                std::ostringstream detail;  // texture and normal map lines, after the hit's line
                Surface s = surfaceAt(current.ray, hit, log ? &detail : nullptr);
                const glm::dvec3 point = s.point;
                // 02/03 main.frag flip the normal when dot > 0; trace.glsl
                // keeps it only when dot < 0 (they differ only at dot == 0).
                const double facing = glm::dot(current.ray.dir, s.normal);
                const bool entering = features.recursion ? facing < 0.0 : !(facing > 0.0);
                const glm::dvec3 normal = entering ? s.normal : -s.normal;
                if (n == 0) recordPrimary(sample, hit, s.normal);
                if (log) {
                    const DMaterial& m = materials[std::size_t(materialOf(hit.id))];
                    *log << "hits " << objectName(hit.id) << " '" << m.name << "' at t=" << fmt(hit.t) << " point " << fmt(point)
                         << " normal " << fmt(s.normal) << (entering ? " entering" : " leaving") << "\n"
                         << detail.str();
                }
                const DMaterial& m = s.material;
                const glm::dvec3 local = blinnPhong(point, normal, -current.ray.dir, m, log);
                color += current.weight * local;
                if (log) *log << "  adds colour " << fmt(current.weight * local) << " (Blinn-Phong " << fmt(local) << ")\n";

                if (m.type != Material::Type::Plastic && current.depth < maxDepth) {
                    const double cosIncident = -glm::dot(current.ray.dir, normal);
                    glm::dvec3 reflectance;
                    std::string what;
                    if (m.type == Material::Type::Mirror) {
                        reflectance = m.specular;
                        if (log) what = "  mirror: reflectance " + fmt(reflectance);
                    } else if (m.type == Material::Type::Metal) {
                        reflectance = fresnelConductor(cosIncident, m.n, m.k);
                        if (log) what = "  metal: F=" + fmt(reflectance) + " (cos " + fmt(cosIncident) + ")";
                    } else {
                        const double eta = entering ? 1.0 / m.ior : m.ior;
                        const glm::dvec3 refracted = refract(current.ray.dir, normal, eta);
                        double F = 1.0;  // total internal reflection
                        if (refracted != glm::dvec3(0.0)) {
                            const double cosTransmitted = -glm::dot(refracted, normal);
                            const double cosOutside = entering ? cosIncident : cosTransmitted;
                            F = fresnelDielectric(cosOutside, m.ior);
                            if (log) what = "  glass: F=" + fmt(F) + " (cos " + fmt(cosOutside) + ")";
                            if (stackSize < kMaxDepth) {
                                stack[stackSize] = PendingRay{DRay{offsetRayOrigin(point, -normal), refracted}, current.weight * (1.0 - F),
                                                              current.depth + 1, ++numbered};
                                ++stackSize;
                                sample.maxStack = std::max(sample.maxStack, stackSize);
                                if (log) what += ", pushes refracted ray " + std::to_string(numbered) + " (weight " + weightText(current.weight * (1.0 - F)) + ")";
                            } else {
                                sample.stackOverflow = true;
                                if (log) what += ", stack full (" + std::to_string(kMaxDepth) + "): refracted ray dropped";
                            }
                        } else if (log) {
                            what = "  glass: total internal reflection (F=1)";
                        }
                        reflectance = glm::dvec3(F);
                    }
                    current = PendingRay{DRay{offsetRayOrigin(point, normal), reflect(current.ray.dir, normal)}, current.weight * reflectance,
                                         current.depth + 1, ++numbered};
                    pathGoesOn = true;
                    if (log) *log << what << ", follows reflected ray " << current.number << " (weight " << weightText(current.weight) << ")\n";
                } else if (log) {
                    if (m.type == Material::Type::Plastic)
                        *log << "  plastic: the path ends\n";
                    else if (!features.recursion)
                        *log << "  no reflected or refracted rays before stage 04: the path ends\n";
                    else
                        *log << "  depth limit " << maxDepth << " reached: the path ends\n";
                }
            }
            if (!pathGoesOn) {
                if (stackSize == 0) break;
                --stackSize;
                current = stack[stackSize];
                if (log) *log << "pop ray " << current.number << "\n";
            }
        }
        return color;
    }

    ReferenceSample traceSample(const DRay& ray, std::ostream* log) const {
        ReferenceSample sample;
        glm::dvec3 color = features.shading ? trace(ray, sample, log) : traceFlat(ray, sample, log);
        if (features.textures && settings.glow) color += sunGlow(ray, log);
        if (features.colorModes && settings.colorMode > 0 && settings.colorMode < kColorModeCount) {
            const glm::dvec3 shown = applyColorMode(color, settings.colorMode);
            if (log) *log << "colour mode " << kColorModes[settings.colorMode] << ": " << fmt(color) << " -> " << fmt(shown) << "\n";
            color = shown;
        }
        sample.color = color;
        return sample;
    }
};

ReferenceTracer::ReferenceTracer(const Scene& scene, const ReferenceFeatures& features, float timeSeconds, const RenderSettings& settings)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
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
    for (const PointLight& l : scene.lights) m.lights.push_back({glm::dvec3(l.position), glm::dvec3(l.color)});
    // Positions at TIMESECONDS exactly as stage_renderer.cpp computes them
    // (in float, as the GPU receives them), then carried on in double.
    for (const Sphere& s : scene.spheres) m.spheres.push_back({glm::dvec3(s.center + s.motion.offsetAt(timeSeconds)), double(s.radius), s.material});
    for (const Plane& p : scene.planes) {
        const glm::dvec3 n(p.normal);
        m.planes.push_back({n, glm::dot(n, glm::dvec3(p.point)), double(p.tileSize), p.material});
    }
    for (const Disc& d : scene.discs) m.discs.push_back({glm::dvec3(d.center), glm::dvec3(d.normal), double(d.radius), d.material});
    for (const Triangle& t : scene.triangles)
        m.triangles.push_back({glm::dvec3(t.vertices[0]), glm::dvec3(t.vertices[1]), glm::dvec3(t.vertices[2]), t.material});
    for (const Torus& t : scene.tori)
        m.tori.push_back({glm::dvec3(t.center), double(t.majorRadius), double(t.minorRadius),
                          reference::torusToLocal(glm::normalize(glm::dvec3(t.axisAt(timeSeconds)))), t.material});
    m.glow = scene.glow;
    m.glowColor = glm::dvec3(scene.glow.color);
    if (features.textures) {
        if (!scene.textures.empty()) m.textures = std::make_unique<reference::TextureLayers>(scene.textures);
        if (scene.skyBox) m.sky = std::make_unique<reference::SkyCube>(*scene.skyBox);
    }
}

ReferenceTracer::~ReferenceTracer() = default;

ReferenceSample ReferenceTracer::trace(const PrimaryRay& ray, std::ostream* log) const {
    return impl_->traceSample(DRay{ray.origin, glm::normalize(ray.dir)}, log);
}

std::vector<ReferenceSample> ReferenceTracer::traceImage(const Camera& camera, int width, int height) const {
    std::vector<ReferenceSample> samples(std::size_t(width) * std::size_t(height));
    std::atomic<int> nextRow{0};
    auto work = [&] {
        for (int y = nextRow++; y < height; y = nextRow++)
            for (int x = 0; x < width; ++x) samples[std::size_t(y) * std::size_t(width) + std::size_t(x)] = trace(primaryRay(camera, width, height, x, y));
    };
    const int threads = std::max(1, std::min(int(std::thread::hardware_concurrency()), height));
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return samples;
}

} // namespace raylab
