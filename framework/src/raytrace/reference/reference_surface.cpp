// The reference tracer's intersections, surfaces, lights, sky, glow and
// colour modes: each function names the GLSL file it follows.
#include "reference_model.h"

#include <algorithm>
#include <cmath>

namespace raylab {

using reference::fresnelConductor;
using reference::fresnelDielectric;
using reference::planeUV;
using reference::sphereUV;

std::string ReferenceTracer::Impl::objectName(int id) const {
    const int kind = id / obj::kStride, index = id - kind * obj::kStride;
    return std::string(kKindNames[kind]) + " " + std::to_string(index);
}

int ReferenceTracer::Impl::materialOf(int id) const {
    const int kind = id / obj::kStride, i = id - kind * obj::kStride;
    switch (kind) {
    case obj::kSphere: return spheres[std::size_t(i)].material;
    case obj::kPlane: return planes[std::size_t(i)].material;
    case obj::kDisc: return discs[std::size_t(i)].material;
    case obj::kTriangle: return triangles[std::size_t(i)].material;
    case obj::kMesh: return meshTriangles[std::size_t(i)].material;
    default: return tori[std::size_t(i)].material;
    }
}

void ReferenceTracer::Impl::keepNearer(Hit& hit, double t, int kind, int index) {
    if (t != kNoHit && t < hit.t) hit = Hit{t, kind * obj::kStride + index};
}

double ReferenceTracer::Impl::intersectTorus(const DRay& ray, const DTorus& t) const {
    DRay local{t.toLocal * (ray.origin - t.center), t.toLocal * ray.dir};
    return reference::intersectTorusLocal(local, t.major, t.minor);
}

// find_closest.glsl (01: spheres; 05 on: every kind - a scene of an
// earlier stage has spheres only).
bool ReferenceTracer::Impl::findClosest(const DRay& ray, Hit& hit) const {
    hit = Hit{};
    for (std::size_t i = 0; i < spheres.size(); ++i)
        keepNearer(hit, reference::intersectSphere(ray, spheres[i].center, spheres[i].radius),
                   obj::kSphere, int(i));
    for (std::size_t i = 0; i < planes.size(); ++i)
        keepNearer(hit, reference::intersectPlane(ray, planes[i].normal, planes[i].offset),
                   obj::kPlane, int(i));
    for (std::size_t i = 0; i < discs.size(); ++i)
        keepNearer(hit,
                   reference::intersectDisc(ray, discs[i].center, discs[i].normal, discs[i].radius),
                   obj::kDisc, int(i));
    for (std::size_t i = 0; i < triangles.size(); ++i)
        keepNearer(
            hit, reference::intersectTriangle(ray, triangles[i].a, triangles[i].b, triangles[i].c),
            obj::kTriangle, int(i));
    for (std::size_t i = 0; i < tori.size(); ++i)
        keepNearer(hit, intersectTorus(ray, tori[i]), obj::kTorus, int(i));
    // Mesh triangles one by one: slow for big meshes, but with nothing
    // (no tree) that could itself be wrong.
    for (std::size_t i = 0; i < meshTriangles.size(); ++i) {
        const DMeshTriangle& m = meshTriangles[i];
        keepNearer(hit, reference::intersectTriangle(ray, m.p[0], m.p[1], m.p[2]), obj::kMesh,
                   int(i));
    }
    return hit.id >= 0;
}

glm::dvec3 ReferenceTracer::Impl::sphereTangent(const glm::dvec3& d) {
    const glm::dvec3 east(d.z, 0.0, -d.x);
    const double len = glm::length(east);
    return len > 1e-6 ? east / len : glm::dvec3(1.0, 0.0, 0.0);
}

glm::dvec3 ReferenceTracer::Impl::textureLayer(int layer, const glm::dvec2& uv) const {
    return textures ? glm::dvec3(textures->sample(layer, uv)) : glm::dvec3(0.0);
}

// 07 normal_map.glsl
void ReferenceTracer::Impl::applyNormalMap(Surface& s, std::ostream* log) const {
    if (!features.normalMaps || !settings.normalMaps || s.material.normalMap < 0) return;
    if (glm::length(s.tangent - glm::dot(s.tangent, s.normal) * s.normal) == 0.0)
        return;  // no tangent (the GLSL would give NaN; scene files refuse this)
    const glm::dvec3 m = textureLayer(s.material.normalMap, s.uv) * 2.0 - 1.0;
    s.normal = reference::applyNormalMap(s.normal, s.tangent, m);
    if (log)
        *log << "  normal map (layer " << s.material.normalMap << "): tangent-space " << fmt(m)
             << ", normal tilted to " << fmt(s.normal) << "\n";
}

// 06 surface_detail.glsl
void ReferenceTracer::Impl::addSurfaceDetail(Surface& s, int kind, int index,
                                             std::ostream* log) const {
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
    applyTexture(s, log);
    applyNormalMap(s, log);
}

void ReferenceTracer::Impl::applyTexture(Surface& s, std::ostream* log) const {
    if (s.material.texture < 0) return;
    const glm::dvec3 picture = textureLayer(s.material.texture, s.uv);
    s.material.ambient *= picture;
    s.material.diffuse *= picture;
    if (log)
        *log << "  texture (layer " << s.material.texture << ") at uv (" << fmt(s.uv.x) << ", "
             << fmt(s.uv.y) << "): " << fmt(picture) << "\n";
}

// scene_meshes.glsl: normals and texture coordinates mixed by the point's
// barycentric weights; a texture, no normal map.
Surface ReferenceTracer::Impl::meshSurface(const glm::dvec3& point, int i,
                                           std::ostream* log) const {
    const DMeshTriangle& m = meshTriangles[std::size_t(i)];
    const glm::dvec3 face = glm::cross(m.p[1] - m.p[0], m.p[2] - m.p[0]);
    const double area2 = glm::dot(face, face);
    const glm::dvec3 w = glm::dvec3(glm::dot(glm::cross(m.p[2] - m.p[1], point - m.p[1]), face),
                                    glm::dot(glm::cross(m.p[0] - m.p[2], point - m.p[2]), face),
                                    glm::dot(glm::cross(m.p[1] - m.p[0], point - m.p[0]), face)) /
                         area2;
    Surface s;
    s.point = point;
    const glm::dvec3 n = w.x * m.n[0] + w.y * m.n[1] + w.z * m.n[2];
    s.normal = glm::dot(n, n) > 1e-12 ? glm::normalize(n) : glm::normalize(face);
    s.uv = w.x * m.uv[0] + w.y * m.uv[1] + w.z * m.uv[2];
    s.material = materials[std::size_t(m.material)];
    applyTexture(s, log);
    return s;
}

// 05 surface_at.glsl (04's for spheres is the same without detail).
Surface ReferenceTracer::Impl::surfaceAt(const DRay& ray, const Hit& hit, std::ostream* log) const {
    Surface s;
    s.point = ray.origin + hit.t * ray.dir;
    const int kind = hit.id / obj::kStride, i = hit.id - kind * obj::kStride;
    if (kind == obj::kMesh) return meshSurface(s.point, i, log);
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
        s.normal = glm::transpose(t.toLocal) *
                   reference::torusNormalLocal(t.toLocal * (s.point - t.center), t.major, t.minor);
    }
    s.material = materials[std::size_t(materialOf(hit.id))];
    addSurfaceDetail(s, kind, i, log);
    return s;
}

// 03 light_visibility.glsl (02: always visible).
bool ReferenceTracer::Impl::lightVisible(const glm::dvec3& point, const glm::dvec3& normal,
                                         int light, std::ostream* log) const {
    if (!features.shadows || !settings.shadows) return true;
    const glm::dvec3 toLight = lights[std::size_t(light)].position - point;
    const double distanceToLight = glm::length(toLight);
    const glm::dvec3 dir = toLight / distanceToLight;
    // 08's light_visibility.glsl casts no ray toward a light behind the
    // surface (it adds nothing either way); so the ray export holds only the
    // shadow rays the GPU casts. The picture is the same in every stage.
    if (glm::dot(normal, dir) <= 0.0) {
        // Said so for every stage: stages 03-07 do cast that shadow ray,
        // whose answer changes nothing.
        if (log) *log << "  light " << light << ": behind the surface, adds no light\n";
        return false;
    }
    const glm::dvec3 side = glm::dot(normal, dir) >= 0.0 ? normal : -normal;
    Hit blocker;
    const DRay shadowRay{offsetRayOrigin(point, side), dir};
    const bool blocked = findClosest(shadowRay, blocker) && blocker.t < distanceToLight;
    recordRay(TracedRay::Kind::Shadow, shadowRay, distanceToLight, blocker, blocked);
    if (blocked && log)
        *log << "  light " << light << ": in shadow, blocked by " << objectName(blocker.id)
             << " at t=" << fmt(blocker.t) << " (light at " << fmt(distanceToLight) << ")\n";
    return !blocked;
}

// 02 blinn_phong.glsl
glm::dvec3 ReferenceTracer::Impl::blinnPhong(const glm::dvec3& point, const glm::dvec3& normal,
                                             const glm::dvec3& toEye, const DMaterial& m,
                                             std::ostream* log) const {
    glm::dvec3 color = m.ambient;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (!lightVisible(point, normal, int(i), log)) continue;
        const glm::dvec3 toLight = glm::normalize(lights[i].position - point);
        const reference::LightTerms terms = reference::blinnPhongLight(
            normal, toEye, toLight, lights[i].color, m.diffuse, m.specular, m.shininess);
        const double lambert = terms.lambert;
        const glm::dvec3 diffuse = terms.diffuse, specular = terms.specular;
        color += diffuse + specular;
        if (log)
            *log << "  light " << i << ": visible, N.L " << fmt(lambert) << ", diffuse "
                 << fmt(diffuse) << ", specular " << fmt(specular) << "\n";
    }
    return color;
}

// 04 / 06 sky.glsl
glm::dvec3 ReferenceTracer::Impl::skyColor(const glm::dvec3& dir) const {
    if (!features.textures || !sky) return background;
    return glm::dvec3(sky->sample(dir));
}

// GLSL refract(): vec3(0) under total internal reflection.
glm::dvec3 ReferenceTracer::Impl::refract(const glm::dvec3& I, const glm::dvec3& N, double eta) {
    return reference::refract(I, N, eta);
}

glm::dvec3 ReferenceTracer::Impl::reflect(const glm::dvec3& I, const glm::dvec3& N) {
    return I - 2.0 * glm::dot(N, I) * N;
}

// 06 glow.glsl
glm::dvec3 ReferenceTracer::Impl::sunGlow(const DRay& ray, std::ostream* log) const {
    if (glow.sphere < 0) return glm::dvec3(0.0);
    const glm::dvec3 c = spheres[std::size_t(glow.sphere)].center;
    const double r = spheres[std::size_t(glow.sphere)].radius;
    const double tc = glm::dot(c - ray.origin, ray.dir);
    if (tc < 0.0) {
        if (log) *log << "glow: none (the sun is behind the eye)\n";
        return glm::dvec3(0.0);
    }
    // The halo test before the blocker ray, as glow.glsl (the same answer;
    // the ray export then holds only the glow rays the GPU casts).
    const double dist = glm::length(ray.origin + tc * ray.dir - c);
    const double x = std::max(dist - r, 0.0) / (double(glow.size) * r);
    if (x >= 1.0) {
        if (log)
            *log << "glow: none (passes " << fmt(dist)
                 << " from the sun's centre, beyond the halo)\n";
        return glm::dvec3(0.0);
    }
    Hit blocker;
    const bool found = findClosest(ray, blocker);
    if (!glowSharesPrimaryHit) recordRay(TracedRay::Kind::Glow, ray, 1e30, blocker, found);
    if (found && blocker.id != obj::kSphere * obj::kStride + glow.sphere && blocker.t < tc) {
        if (log)
            *log << "glow: none (" << objectName(blocker.id) << " at t=" << fmt(blocker.t)
                 << " is in front of the sun)\n";
        return glm::dvec3(0.0);
    }
    const double fade = 1.0 - x;
    const glm::dvec3 g = glowColor * fade * fade * fade;
    if (log) *log << "glow: adds " << fmt(g) << " (x " << fmt(x) << ")\n";
    return g;
}

// 08 color_mode.glsl
glm::dvec3 ReferenceTracer::Impl::applyColorMode(const glm::dvec3& c, int mode) {
    return reference::applyColorMode(c, mode);
}
}  // namespace raylab
