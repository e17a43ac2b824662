// Embree 3 casting a frame's rays (embree_caster.h). Spheres and triangles
// are Embree's own primitives; planes, discs and tori are user geometry
// whose intersection is the reference tracer's (double precision, the GLSL's
// rules), so Embree and the reference answer the same question.
#include "embree_caster.h"

#include "error.h"
#include "gpu_values.h"
#include "reference_intersect.h"
#include "shader_constants.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>

#ifdef RAYLAB_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace raylab {

double agreementWithReference(const std::vector<TracedRay>& rays, const EmbreeAnswers& answers) {
    if (rays.empty() || answers.ids.size() != rays.size()) return 0.0;
    std::size_t same = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (rays[i].kind == TracedRay::Kind::Shadow)
            same += (rays[i].hitId >= 0) == (answers.ids[i] >= 0);
        else same += rays[i].hitId == answers.ids[i];
    }
    return double(same) / double(rays.size());
}

#ifdef RAYLAB_HAVE_EMBREE

namespace {

using reference::DRay;
using reference::kNoHit;

// How far an infinite plane reaches in the BVH: far beyond any demo scene
// (a box around a plane must be finite).
constexpr double kPlaneReach = 1e4;

struct PlaneShape {
    glm::dvec3 normal;
    double offset;
    double hit(const DRay& r) const { return reference::intersectPlane(r, normal, offset); }
    RTCBounds bounds() const {
        // A slab along the normal's largest axis, kPlaneReach wide in the others.
        int d = 0;
        for (int i = 1; i < 3; ++i)
            if (std::fabs(normal[i]) > std::fabs(normal[d])) d = i;
        double lo[3], hi[3];
        double spread = 0.0;
        for (int i = 0; i < 3; ++i) {
            lo[i] = -kPlaneReach, hi[i] = kPlaneReach;
            if (i != d) spread += kPlaneReach * std::fabs(normal[i]);
        }
        const double mid = offset / normal[d], half = spread / std::fabs(normal[d]) + 1e-3;
        lo[d] = mid - half, hi[d] = mid + half;
        return RTCBounds{float(lo[0]), float(lo[1]), float(lo[2]), 0.0f,
                         float(hi[0]), float(hi[1]), float(hi[2]), 0.0f};
    }
};

struct DiscShape {
    glm::dvec3 center, normal;
    double radius;
    double hit(const DRay& r) const { return reference::intersectDisc(r, center, normal, radius); }
    RTCBounds bounds() const {
        const glm::dvec3 lo = center - radius - 1e-4, hi = center + radius + 1e-4;
        return RTCBounds{float(lo.x), float(lo.y), float(lo.z), 0.0f,
                         float(hi.x), float(hi.y), float(hi.z), 0.0f};
    }
};

struct TorusShape {
    glm::dvec3 center;
    double major, minor;
    glm::dmat3 toLocal;
    double hit(const DRay& r) const {
        return reference::intersectTorusLocal(
            DRay{toLocal * (r.origin - center), glm::normalize(toLocal * r.dir)}, major, minor);
    }
    RTCBounds bounds() const {
        const double reach = major + minor + 1e-4;
        const glm::dvec3 lo = center - reach, hi = center + reach;
        return RTCBounds{float(lo.x), float(lo.y), float(lo.z), 0.0f,
                         float(hi.x), float(hi.y), float(hi.z), 0.0f};
    }
};

DRay toDRay(const RTCRay& r) {
    return DRay{glm::dvec3(r.org_x, r.org_y, r.org_z),
                glm::normalize(glm::dvec3(r.dir_x, r.dir_y, r.dir_z))};
}

template <class Shape>
void boundsOf(const RTCBoundsFunctionArguments* a) {
    const auto& shapes = *static_cast<const std::vector<Shape>*>(a->geometryUserPtr);
    *a->bounds_o = shapes[a->primID].bounds();
}

// Only rtcIntersect1 / rtcOccluded1 are used, so N is 1 and the SOA ray
// packet of the callback is laid out as a single RTCRayHit / RTCRay.
template <class Shape>
void intersectOf(const RTCIntersectFunctionNArguments* a) {
    if (a->N != 1 || !a->valid[0]) return;
    const auto& shapes = *static_cast<const std::vector<Shape>*>(a->geometryUserPtr);
    RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(a->rayhit);
    const double t = shapes[a->primID].hit(toDRay(rh->ray));
    if (t == kNoHit || t < rh->ray.tnear || t > rh->ray.tfar) return;
    rh->ray.tfar = float(t);
    rh->hit.Ng_x = rh->hit.Ng_y = rh->hit.Ng_z = 0.0f;
    rh->hit.u = rh->hit.v = 0.0f;
    rh->hit.primID = a->primID;
    rh->hit.geomID = a->geomID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

template <class Shape>
void occludedOf(const RTCOccludedFunctionNArguments* a) {
    if (a->N != 1 || !a->valid[0]) return;
    const auto& shapes = *static_cast<const std::vector<Shape>*>(a->geometryUserPtr);
    RTCRay* ray = reinterpret_cast<RTCRay*>(a->ray);
    const double t = shapes[a->primID].hit(toDRay(*ray));
    if (t != kNoHit && t >= ray->tnear && t <= ray->tfar)
        ray->tfar = -std::numeric_limits<float>::infinity();  // Embree's "occluded"
}

RTCRay rayOf(const TracedRay& r) {
    RTCRay ray;
    ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
    ray.dir_x = r.dir.x, ray.dir_y = r.dir.y, ray.dir_z = r.dir.z;
    ray.tnear = float(shader::kTMin);  // hits at t <= T_MIN do not count, as in the GLSL
    ray.tfar = r.tMax;
    ray.time = 0.0f;
    ray.mask = 0xffffffffu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

void recordError(void* userPtr, RTCError, const char* message) {
    *static_cast<std::string*>(userPtr) = message ? message : "unknown error";
}

}  // namespace

struct EmbreeCaster::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string lastError;
    std::vector<int> kindOfGeometry;  // geomID -> object kind (shader_constants.h)
    std::vector<PlaneShape> planes;
    std::vector<DiscShape> discs;
    std::vector<TorusShape> tori;
    double buildMs = 0.0;

    template <class Shape>
    void addUser(std::vector<Shape>& shapes, int kind) {
        if (shapes.empty()) return;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, unsigned(shapes.size()));
        rtcSetGeometryUserData(g, &shapes);
        rtcSetGeometryBoundsFunction(g, boundsOf<Shape>, nullptr);
        rtcSetGeometryIntersectFunction(g, intersectOf<Shape>);
        rtcSetGeometryOccludedFunction(g, occludedOf<Shape>);
        attach(g, kind);
    }
    void attach(RTCGeometry g, int kind) {
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        if (kindOfGeometry.size() <= id) kindOfGeometry.resize(id + 1, -1);
        kindOfGeometry[id] = kind;
    }
    void check(const char* what) const {
        if (!lastError.empty()) throw Error(std::string("Embree: ") + what + ": " + lastError);
    }
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

bool embreeBuilt() { return true; }
std::string embreeVersion() { return RTC_VERSION_STRING; }

EmbreeCaster::EmbreeCaster(const Scene& s) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.device = rtcNewDevice(nullptr);
    if (!m.device) throw Error("Embree: cannot create a device");
    rtcSetDeviceErrorFunction(m.device, recordError, &m.lastError);
    const auto start = std::chrono::steady_clock::now();
    m.scene = rtcNewScene(m.device);
    if (!s.spheres.empty()) {
        RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), s.spheres.size()));
        for (std::size_t i = 0; i < s.spheres.size(); ++i) {
            const glm::vec4 c = gpuSphere(s.spheres[i], 0.0f);
            v[4 * i] = c.x, v[4 * i + 1] = c.y, v[4 * i + 2] = c.z;
            v[4 * i + 3] = c.w;
        }
        m.attach(g, shader::kSphere);
    }
    if (!s.triangles.empty()) {
        RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              3 * s.triangles.size()));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), s.triangles.size()));
        for (std::size_t i = 0; i < s.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = gpuPoint(s.triangles[i].vertices[std::size_t(k)]);
                v[9 * i + 3 * std::size_t(k)] = p.x;
                v[9 * i + 3 * std::size_t(k) + 1] = p.y;
                v[9 * i + 3 * std::size_t(k) + 2] = p.z;
                idx[3 * i + std::size_t(k)] = unsigned(3 * i + std::size_t(k));
            }
        m.attach(g, shader::kTriangle);
    }
    std::size_t meshTriangles = 0, meshCorners = 0;
    for (const MeshObject& mesh : s.meshes) {
        meshTriangles += mesh.triangleCount();
        meshCorners += mesh.positions.size();
    }
    if (meshTriangles > 0) {
        // Every mesh's triangles in one geometry, in the order the GLSL and
        // the reference number them (primID = the triangle's index).
        RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), meshCorners));
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), meshTriangles));
        std::size_t corner = 0, index = 0;
        for (const MeshObject& mesh : s.meshes) {
            for (const glm::dvec3& d : mesh.positions) {
                const glm::vec3 p = gpuPoint(d);
                v[3 * corner] = p.x, v[3 * corner + 1] = p.y, v[3 * corner + 2] = p.z;
                ++corner;
            }
            const std::size_t base = corner - mesh.positions.size();
            for (std::uint32_t i : mesh.indices) idx[index++] = unsigned(base + i);
        }
        m.attach(g, shader::kMesh);
    }
    for (const Plane& p : s.planes) {
        m.planes.push_back({glm::dvec3(p.normal), double(gpuPlane(p).w)});
    }
    for (const Disc& d : s.discs) {
        const glm::vec4 g = gpuDisc(d);
        m.discs.push_back({glm::dvec3(glm::vec3(g)), glm::dvec3(d.normal), double(g.w)});
    }
    for (const Torus& t : s.tori)
        m.tori.push_back({glm::dvec3(gpuPoint(t.center)), double(float(t.majorRadius)),
                          double(float(t.minorRadius)),
                          reference::torusToLocal(glm::normalize(glm::dvec3(t.axisAt(0.0f))))});
    m.addUser(m.planes, shader::kPlane);
    m.addUser(m.discs, shader::kDisc);
    m.addUser(m.tori, shader::kTorus);
    rtcCommitScene(m.scene);
    m.buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    m.check("building the scene");
}

EmbreeCaster::~EmbreeCaster() = default;

double EmbreeCaster::buildMs() const { return impl_->buildMs; }

double EmbreeCaster::cast(const std::vector<TracedRay>& rays, int threads,
                          EmbreeAnswers* answers) const {
    const Impl& m = *impl_;
    if (answers) {
        answers->ids.assign(rays.size(), -1);
        answers->t.assign(rays.size(), 0.0f);
    }
    // Blocks of consecutive rays (neighbouring pixels: coherent) handed out
    // to the threads as they come free.
    constexpr std::size_t kBlock = 1024;
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::size_t b = next.fetch_add(kBlock); b < rays.size(); b = next.fetch_add(kBlock)) {
            const std::size_t end = std::min(rays.size(), b + kBlock);
            for (std::size_t i = b; i < end; ++i) {
                const TracedRay& r = rays[i];
                if (r.kind == TracedRay::Kind::Shadow) {
                    RTCRay ray = rayOf(r);
                    rtcOccluded1(m.scene, &context, &ray);
                    if (answers) answers->ids[i] = ray.tfar < 0.0f ? 0 : -1;
                } else {
                    RTCRayHit rh;
                    rh.ray = rayOf(r);
                    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                    rtcIntersect1(m.scene, &context, &rh);
                    if (answers && rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                        answers->ids[i] =
                            m.kindOfGeometry[rh.hit.geomID] * shader::kObjectKindStride +
                            int(rh.hit.primID);
                        answers->t[i] = rh.ray.tfar;
                    }
                }
            }
        }
    };
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int i = 1; i < std::max(1, threads); ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

#else  // no Embree in this build

struct EmbreeCaster::Impl {};

bool embreeBuilt() { return false; }
std::string embreeVersion() { return ""; }

EmbreeCaster::EmbreeCaster(const Scene&) {
    throw Error("Embree not built (install libembree-dev and run cmake again)");
}
EmbreeCaster::~EmbreeCaster() = default;
double EmbreeCaster::buildMs() const { return 0.0; }
double EmbreeCaster::cast(const std::vector<TracedRay>&, int, EmbreeAnswers*) const { return 0.0; }

#endif

}  // namespace raylab
