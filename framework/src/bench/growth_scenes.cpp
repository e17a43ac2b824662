#include "growth_scenes.h"

#include "mesh_shapes.h"

#include <algorithm>
#include <cmath>

namespace raylab {

Scene growthBaseScene(const std::string& name) {
    Scene s;
    s.file = name;
    s.background = glm::vec3(0.62f, 0.76f, 0.93f);
    s.camera.position = glm::dvec3(0.0, 0.4, 3.6);
    s.camera.pitchDeg = -6.0f;
    s.fovYDeg = 45.0f;
    Material clay;
    clay.name = "clay";
    clay.ambient = glm::vec3(0.08f, 0.04f, 0.02f);
    clay.diffuse = glm::vec3(0.78f, 0.40f, 0.22f);
    clay.specular = glm::vec3(0.4f);
    s.materials.push_back(clay);
    Material floor;
    floor.name = "floor";
    floor.ambient = glm::vec3(0.06f);
    floor.diffuse = glm::vec3(0.55f, 0.52f, 0.45f);
    s.materials.push_back(floor);
    s.lights.push_back({glm::dvec3(-4.0, 6.0, 5.0), glm::vec3(0.9f)});
    Plane p;
    p.point = glm::dvec3(0.0, -1.05, 0.0);
    p.material = 1;
    s.planes.push_back(p);
    return s;
}

Scene growthMeshScene(long wanted) {
    int detail = std::max(2, int((1.0 + std::sqrt(1.0 + double(wanted))) / 2.0));
    while (detail > 2 && 4L * detail * detail - 4L * detail > wanted) --detail;
    Mesh mesh = makeShape("sphere", detail);
    Scene s = growthBaseScene("growth: sphere mesh, " + std::to_string(mesh.triangleCount()) +
                              " triangles");
    s.meshes.push_back(placeMesh("sphere", std::move(mesh), 1.0, glm::dvec3(0.0), 0));
    return s;
}

Scene growthSphereScene(int n) {
    Scene s = growthBaseScene("growth: " + std::to_string(n) + " spheres");
    const int side = int(std::ceil(std::cbrt(double(n))));
    const float cell = 2.0f / float(side);
    unsigned state = 12345u;
    auto jitter = [&] {
        state = state * 1664525u + 1013904223u;
        return (float(state >> 8) / float(1u << 24) - 0.5f) * 0.3f * cell;
    };
    for (int i = 0; i < n; ++i) {
        glm::vec3 c(float(i % side), float((i / side) % side), float(i / (side * side)));
        Sphere sphere;
        sphere.center = -1.0f + (c + 0.5f) * cell + glm::vec3(jitter(), jitter(), jitter());
        sphere.radius = 0.3f * cell;
        s.spheres.push_back(sphere);
    }
    return s;
}

}  // namespace raylab
