// The reference tracer (reference_tracer.h): the GLSL of solution/ redone in
// double precision, function by function. Each function below names the
// GLSL file it follows.
#include "reference_tracer.h"

#include "reference_model.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>

namespace raylab {

using reference::fresnelConductor;
using reference::fresnelDielectric;

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
    const double yaw = glm::radians(double(pose.yawDeg)),
                 pitch = glm::radians(double(pose.pitchDeg));
    const glm::dvec3 forward(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                             -std::cos(yaw) * std::cos(pitch));
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

Image referenceImage(const std::vector<ReferenceSample>& samples, int width, int height,
                     long* nonFinite) {
    std::vector<float> rgba(std::size_t(width) * std::size_t(height) * 4, 1.0f);
    for (std::size_t i = 0; i < samples.size() && i < std::size_t(width) * std::size_t(height); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + std::size_t(c)] = float(samples[i].color[c]);
    return imageFromFloats(rgba, width, height, nonFinite);
}

void ReferenceTracer::Impl::recordPrimary(ReferenceSample& sample, const Hit& hit,
                                          const glm::dvec3& normal) const {
    sample.depth = hit.t;
    sample.id = hit.id;
    sample.normal = normal;
}

// 01 main.frag: the flat colour of the nearest sphere.
glm::dvec3 ReferenceTracer::Impl::traceFlat(const DRay& ray, ReferenceSample& sample,
                                            std::ostream* log) const {
    sample.rays = 1;
    Hit hit;
    if (!findClosest(ray, hit)) {
        if (log) *log << "ray 1: misses everything: background " << fmt(background) << "\n";
        return background;
    }
    const glm::dvec3 point = ray.origin + hit.t * ray.dir;
    const int kind = hit.id / obj::kStride, i = hit.id - kind * obj::kStride;
    glm::dvec3 normal = kind == obj::kSphere
                            ? glm::normalize(point - spheres[std::size_t(i)].center)
                            : surfaceAt(ray, hit, nullptr).normal;
    recordPrimary(sample, hit, normal);
    const DMaterial& m = materials[std::size_t(materialOf(hit.id))];
    if (log)
        *log << "ray 1: hits " << objectName(hit.id) << " '" << m.name << "' at t=" << fmt(hit.t)
             << " point " << fmt(point) << ": flat colour " << fmt(m.diffuse) << "\n";
    return m.diffuse;
}

// 04 trace.glsl (02/03 main.frag: the same with no secondary rays and
// the background as sky).
glm::dvec3 ReferenceTracer::Impl::trace(const DRay& primary, ReferenceSample& sample,
                                        std::ostream* log) const {
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
        if (log)
            *log << "ray " << current.number << " (depth " << current.depth << ", weight "
                 << weightText(current.weight) << "): ";
        const bool found = findClosest(current.ray, hit);
        recordRay(n == 0 ? TracedRay::Kind::Primary : TracedRay::Kind::Secondary, current.ray, 1e30,
                  hit, found);
        if (!found) {
            const glm::dvec3 skyRgb = skyColor(current.ray.dir);
            color += current.weight * skyRgb;
            if (log)
                *log << "misses everything\n  miss: "
                     << (features.textures && sky ? "sky " : "background ") << fmt(skyRgb)
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
                *log << "hits " << objectName(hit.id) << " '" << m.name << "' at t=" << fmt(hit.t)
                     << " point " << fmt(point) << " normal " << fmt(s.normal)
                     << (entering ? " entering" : " leaving") << "\n"
                     << detail.str();
            }
            const DMaterial& m = s.material;
            const glm::dvec3 local = blinnPhong(point, normal, -current.ray.dir, m, log);
            color += current.weight * local;
            if (log)
                *log << "  adds colour " << fmt(current.weight * local) << " (Blinn-Phong "
                     << fmt(local) << ")\n";

            if (m.type != Material::Type::Plastic && current.depth < maxDepth) {
                const double cosIncident = -glm::dot(current.ray.dir, normal);
                glm::dvec3 reflectance;
                std::string what;
                if (m.type == Material::Type::Mirror) {
                    reflectance = m.specular;
                    if (log) what = "  mirror: reflectance " + fmt(reflectance);
                } else if (m.type == Material::Type::Metal) {
                    reflectance = fresnelConductor(cosIncident, m.n, m.k);
                    if (log)
                        what = "  metal: F=" + fmt(reflectance) + " (cos " + fmt(cosIncident) + ")";
                } else {
                    const glm::dvec4 glass =
                        reference::refractGlass(current.ray.dir, normal, entering, m.ior);
                    const glm::dvec3 refracted(glass);
                    const double F = glass.w;  // 1 under total internal reflection
                    if (refracted != glm::dvec3(0.0)) {
                        const double cosOutside =
                            entering ? cosIncident : -glm::dot(refracted, normal);
                        if (log) what = "  glass: F=" + fmt(F) + " (cos " + fmt(cosOutside) + ")";
                        const glm::dvec3 refractedWeight = current.weight * (1.0 - F);
                        if (!weightCounts(refractedWeight)) {
                            if (log) what += ", refracted ray too faint: not traced";
                        } else if (stackSize < kMaxDepth) {
                            stack[stackSize] = PendingRay{
                                DRay{offsetRayOrigin(point, -normal), refracted},
                                current.weight * (1.0 - F), current.depth + 1, ++numbered};
                            ++stackSize;
                            sample.maxStack = std::max(sample.maxStack, stackSize);
                            if (log)
                                what += ", pushes refracted ray " + std::to_string(numbered) +
                                        " (weight " + weightText(current.weight * (1.0 - F)) + ")";
                        } else {
                            sample.stackOverflow = true;
                            if (log)
                                what += ", stack full (" + std::to_string(kMaxDepth) +
                                        "): refracted ray dropped";
                        }
                    } else if (log) {
                        what = "  glass: total internal reflection (F=1)";
                    }
                    reflectance = glm::dvec3(F);
                }
                if (!weightCounts(current.weight * reflectance)) {
                    if (log) *log << what << ", reflected ray too faint: the path ends\n";
                } else {
                    current = PendingRay{
                        DRay{offsetRayOrigin(point, normal), reflect(current.ray.dir, normal)},
                        current.weight * reflectance, current.depth + 1, ++numbered};
                    pathGoesOn = true;
                    if (log)
                        *log << what << ", follows reflected ray " << current.number << " (weight "
                             << weightText(current.weight) << ")\n";
                }
            } else if (log) {
                if (m.type == Material::Type::Plastic) *log << "  plastic: the path ends\n";
                else if (!features.recursion)
                    *log << "  no reflected or refracted rays before stage 04: the path ends\n";
                else *log << "  depth limit " << maxDepth << " reached: the path ends\n";
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

ReferenceSample ReferenceTracer::Impl::traceSample(const DRay& ray, std::ostream* log) const {
    ReferenceSample sample;
    glm::dvec3 color = features.shading ? trace(ray, sample, log) : traceFlat(ray, sample, log);
    if (features.textures && settings.glow) color += sunGlow(ray, log);
    if (features.colorModes && settings.colorMode > 0 && settings.colorMode < kColorModeCount) {
        const glm::dvec3 shown = applyColorMode(color, settings.colorMode);
        if (log)
            *log << "colour mode " << kColorModes[settings.colorMode] << ": " << fmt(color)
                 << " -> " << fmt(shown) << "\n";
        color = shown;
    }
    sample.color = color;
    return sample;
}
ReferenceTracer::~ReferenceTracer() = default;

void ReferenceTracer::setWeightCut(double cut) { impl_->weightCut = cut; }

void ReferenceTracer::setGlowSharesPrimaryHit(bool shared) { impl_->glowSharesPrimaryHit = shared; }

// The weight-cut variant's test (its weightCounts()); always true without a cut.
bool ReferenceTracer::Impl::weightCounts(const glm::dvec3& weight) const {
    return weightCut <= 0.0 || std::max({weight.r, weight.g, weight.b}) >= double(float(weightCut));
}

ReferenceSample ReferenceTracer::trace(const PrimaryRay& ray, std::ostream* log) const {
    // Into the frame the scene is traced in, and the depth back out of it.
    const SceneTransform& frame = impl_->frame;
    ReferenceSample sample = impl_->traceSample(
        DRay{ray.origin * frame.scale + frame.offset, glm::normalize(ray.dir)}, log);
    sample.depth /= frame.scale;
    return sample;
}

std::vector<ReferenceSample> ReferenceTracer::traceImage(const Camera& camera, int width,
                                                         int height,
                                                         std::vector<TracedRay>* rays) const {
    std::vector<ReferenceSample> samples(std::size_t(width) * std::size_t(height));
    // One list per row, joined in row order at the end: the export does not
    // depend on which thread traced which row.
    std::vector<std::vector<TracedRay>> rowRays(rays ? std::size_t(height) : 0);
    std::atomic<int> nextRow{0};
    auto work = [&] {
        for (int y = nextRow++; y < height; y = nextRow++) {
            tracedRays() = rays ? &rowRays[std::size_t(y)] : nullptr;
            for (int x = 0; x < width; ++x)
                samples[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                    trace(primaryRay(camera, width, height, x, y));
        }
        tracedRays() = nullptr;
    };
    const int threads = std::max(1, std::min(int(std::thread::hardware_concurrency()), height));
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (rays) {
        rays->clear();
        for (const std::vector<TracedRay>& row : rowRays)
            rays->insert(rays->end(), row.begin(), row.end());
    }
    return samples;
}

}  // namespace raylab
