// The objects of a scene file. Rectangles and boxes are written as such in
// the file (easier to get right by hand) and become triangles here.
#include "scene_reader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace raylab {

// "material": a name from "materials", or "color": a flat colour (a material
// of its own with that diffuse colour).
int materialOf(const SceneReader& r, const json& obj, const std::string& where, Scene& scene) {
    if (obj.is_object() && obj.contains("material")) {
        if (!obj["material"].is_string())
            r.fail(where + ".material", "expected the name of a material");
        std::string name = obj["material"].get<std::string>();
        auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                               [&](const Material& m) { return m.name == name; });
        if (it == scene.materials.end())
            r.fail(where + ".material", "unknown material \"" + name + "\"");
        return int(it - scene.materials.begin());
    }
    Material flat;
    flat.name = where;
    flat.diffuse = r.color(r.member(obj, where, "color"), where + ".color");
    scene.materials.push_back(flat);
    return int(scene.materials.size()) - 1;
}

namespace {

std::string item(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
}

void readSpheres(const SceneReader& r, const json& doc, Scene& scene) {
    const json& spheres = r.member(doc, "scene", "spheres");
    if (!spheres.is_array()) r.fail("spheres", "expected a list");
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        std::string where = item("spheres", i);
        const json& s = spheres[i];
        r.allowOnly(s, where, {"center", "radius", "material", "color", "motion"});
        Sphere sphere;
        sphere.center = r.point(r.member(s, where, "center"), where + ".center");
        sphere.radius = r.length(r.member(s, where, "radius"), where + ".radius");
        sphere.material = materialOf(r, s, where, scene);
        if (s.contains("motion")) {
            const json& m = s["motion"];
            std::string mw = where + ".motion";
            r.allowOnly(m, mw, {"axis", "amplitude", "period"});
            sphere.motion.axis = r.vec3(r.member(m, mw, "axis"), mw + ".axis");
            sphere.motion.amplitude = r.real(r.member(m, mw, "amplitude"), mw + ".amplitude");
            sphere.motion.periodSeconds = r.positive(r.member(m, mw, "period"), mw + ".period");
        }
        scene.spheres.push_back(sphere);
    }
}

void readPlanes(const SceneReader& r, const json& doc, Scene& scene) {
    const json& planes = r.optionalList(doc, "planes");
    for (std::size_t i = 0; i < planes.size(); ++i) {
        std::string where = item("planes", i);
        r.allowOnly(planes[i], where, {"point", "normal", "tile_size", "material", "color"});
        Plane p;
        p.point = r.point(r.member(planes[i], where, "point"), where + ".point");
        p.normal = r.direction(r.member(planes[i], where, "normal"), where + ".normal");
        if (planes[i].contains("tile_size"))
            p.tileSize = r.length(planes[i]["tile_size"], where + ".tile_size");
        p.material = materialOf(r, planes[i], where, scene);
        scene.planes.push_back(p);
    }
}

void readDiscs(const SceneReader& r, const json& doc, Scene& scene) {
    const json& discs = r.optionalList(doc, "discs");
    for (std::size_t i = 0; i < discs.size(); ++i) {
        std::string where = item("discs", i);
        r.allowOnly(discs[i], where, {"center", "normal", "radius", "material", "color"});
        Disc d;
        d.center = r.point(r.member(discs[i], where, "center"), where + ".center");
        d.normal = r.direction(r.member(discs[i], where, "normal"), where + ".normal");
        d.radius = r.length(r.member(discs[i], where, "radius"), where + ".radius");
        d.material = materialOf(r, discs[i], where, scene);
        scene.discs.push_back(d);
    }
}

void addTriangle(const SceneReader& r, const std::string& where, Scene& scene, glm::dvec3 a,
                 glm::dvec3 b, glm::dvec3 c, int material) {
    if (!(glm::length(glm::cross(b - a, c - a)) > 1e-8))
        r.fail(where, "degenerate: the corners lie on one line");
    scene.triangles.push_back(Triangle{{a, b, c}, material});
}

void readTriangles(const SceneReader& r, const json& doc, Scene& scene) {
    const json& triangles = r.optionalList(doc, "triangles");
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        std::string where = item("triangles", i);
        r.allowOnly(triangles[i], where, {"vertices", "material", "color"});
        const json& v = r.member(triangles[i], where, "vertices");
        if (!v.is_array() || v.size() != 3)
            r.fail(where + ".vertices", "expected three [x, y, z] corners");
        int material = materialOf(r, triangles[i], where, scene);
        // One by one: a bad corner is reported in order, whatever the
        // compiler's order of evaluating arguments.
        const glm::dvec3 a = r.point(v[0], where + ".vertices[0]");
        const glm::dvec3 b = r.point(v[1], where + ".vertices[1]");
        const glm::dvec3 c = r.point(v[2], where + ".vertices[2]");
        addTriangle(r, where, scene, a, b, c, material);
    }
}

// corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v: its
// front (normal) is cross(edge_u, edge_v).
void readRectangles(const SceneReader& r, const json& doc, Scene& scene) {
    const json& rects = r.optionalList(doc, "rectangles");
    for (std::size_t i = 0; i < rects.size(); ++i) {
        std::string where = item("rectangles", i);
        r.allowOnly(rects[i], where, {"corner", "edge_u", "edge_v", "material", "color"});
        const glm::dvec3 p = r.point(r.member(rects[i], where, "corner"), where + ".corner");
        const glm::dvec3 u = r.point(r.member(rects[i], where, "edge_u"), where + ".edge_u");
        const glm::dvec3 v = r.point(r.member(rects[i], where, "edge_v"), where + ".edge_v");
        int material = materialOf(r, rects[i], where, scene);
        addTriangle(r, where, scene, p, p + u, p + u + v, material);
        addTriangle(r, where, scene, p, p + u + v, p + v, material);
    }
}

// An axis-aligned box turned by rotation_y degrees about its vertical axis:
// 12 triangles, every face counter-clockwise seen from outside.
void readBoxes(const SceneReader& r, const json& doc, Scene& scene) {
    const json& boxes = r.optionalList(doc, "boxes");
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        std::string where = item("boxes", i);
        r.allowOnly(boxes[i], where, {"center", "size", "rotation_y", "material", "color"});
        const glm::dvec3 center = r.point(r.member(boxes[i], where, "center"), where + ".center");
        const glm::dvec3 size = r.point(r.member(boxes[i], where, "size"), where + ".size");
        for (int c = 0; c < 3; ++c)
            if (!(size[c] > 0.0)) r.fail(where + ".size", "every side must be positive");
        float turn = boxes[i].contains("rotation_y")
                         ? r.number(boxes[i]["rotation_y"], where + ".rotation_y")
                         : 0.0f;
        int material = materialOf(r, boxes[i], where, scene);
        // In double: the float sinf/cosf of C libraries differ in the last
        // bit, double sin/cos practically never do, so the corners (which
        // the specialised shader prints) are the same everywhere, the web
        // build's included.
        const glm::dmat4 rotation =
            glm::rotate(glm::dmat4(1.0), glm::radians(double(turn)), glm::dvec3(0, 1, 0));
        auto corner = [&](int x, int y, int z) {
            const glm::dvec3 local = (glm::dvec3(x, y, z) - 0.5) * size;
            return center + glm::dvec3(rotation * glm::dvec4(local, 1.0));
        };
        // Each face: the axis it is normal to, and which side.
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = 0; side < 2; ++side) {
                int u = (axis + 1) % 3, v = (axis + 2) % 3;
                if (side == 0) std::swap(u, v);  // keeps the face counter-clockwise from outside
                auto at = [&](int du, int dv) {
                    int c[3];
                    c[axis] = side;
                    c[u] = du;
                    c[v] = dv;
                    return corner(c[0], c[1], c[2]);
                };
                addTriangle(r, where, scene, at(0, 0), at(1, 0), at(1, 1), material);
                addTriangle(r, where, scene, at(0, 0), at(1, 1), at(0, 1), material);
            }
        }
    }
}

void readTori(const SceneReader& r, const json& doc, Scene& scene) {
    const json& tori = r.optionalList(doc, "tori");
    for (std::size_t i = 0; i < tori.size(); ++i) {
        std::string where = item("tori", i);
        const json& t = tori[i];
        r.allowOnly(
            t, where,
            {"center", "axis", "major_radius", "minor_radius", "spin", "material", "color"});
        Torus torus;
        torus.center = r.point(r.member(t, where, "center"), where + ".center");
        torus.axis = r.direction(r.member(t, where, "axis"), where + ".axis");
        torus.majorRadius = r.length(r.member(t, where, "major_radius"), where + ".major_radius");
        torus.minorRadius = r.length(r.member(t, where, "minor_radius"), where + ".minor_radius");
        if (torus.minorRadius >= torus.majorRadius)
            r.fail(where, "minor_radius must be smaller than major_radius");
        if (t.contains("spin")) {
            std::string sw = where + ".spin";
            r.allowOnly(t["spin"], sw, {"axis", "period"});
            torus.spinAxis = r.direction(r.member(t["spin"], sw, "axis"), sw + ".axis");
            torus.spinPeriod = r.positive(r.member(t["spin"], sw, "period"), sw + ".period");
        }
        torus.material = materialOf(r, t, where, scene);
        scene.tori.push_back(torus);
    }
}

}  // namespace

glm::vec3 Torus::axisAt(float t) const {
    if (spinPeriod <= 0.0f) return axis;
    float angle = 6.28318530718f * std::fmod(t / spinPeriod, 1.0f);
    return glm::normalize(
        glm::vec3(glm::rotate(glm::mat4(1.0f), angle, spinAxis) * glm::vec4(axis, 0.0f)));
}

// Texture coordinates exist on spheres, planes and discs; a tangent (for
// normal maps) on spheres only. Anything else would render flat or black.
void checkTexturesFit(const SceneReader& r, const Scene& scene) {
    auto check = [&](const char* list, std::size_t i, int material, bool uv, bool tangent) {
        const Material& m = scene.materials[std::size_t(material)];
        std::string where = item(list, i) + ".material";
        if (m.texture >= 0 && !uv)
            r.fail(where, "material \"" + m.name + "\" has a texture, but " + list +
                              " have no texture coordinates (spheres, planes and discs do)");
        if (m.normalMap >= 0 && !tangent)
            r.fail(where, "material \"" + m.name +
                              "\" has a normal map, but only spheres take normal maps");
    };
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        check("planes", i, scene.planes[i].material, true, false);
    for (std::size_t i = 0; i < scene.discs.size(); ++i)
        check("discs", i, scene.discs[i].material, true, false);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
        check("triangles", i, scene.triangles[i].material, false, false);
    for (std::size_t i = 0; i < scene.tori.size(); ++i)
        check("tori", i, scene.tori[i].material, false, false);
}

void readShapes(const SceneReader& r, const json& doc, Scene& scene) {
    readSpheres(r, doc, scene);
    readPlanes(r, doc, scene);
    readDiscs(r, doc, scene);
    readTriangles(r, doc, scene);
    readRectangles(r, doc, scene);
    readBoxes(r, doc, scene);
    readTori(r, doc, scene);
    readMeshes(r, doc, scene);
    checkTexturesFit(r, scene);
}

}  // namespace raylab
