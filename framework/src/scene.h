#pragma once
// A scene file (JSON, under assets/scenes/): background, camera, objects.
// Stage 01 uses spheres; later stages add more object kinds.
#include "camera.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// A sinusoidal bob: offset = axis * amplitude * sin(2 pi t / period).
struct Motion {
    glm::vec3 axis{0.0f};
    float amplitude = 0.0f;
    float periodSeconds = 1.0f;
    glm::vec3 offsetAt(float t) const;
};

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    glm::vec3 color{1.0f};
    Motion motion;
};

struct Scene {
    std::string file;  // display path, for messages
    glm::vec3 background{0.0f};
    CameraPose camera;
    float fovYDeg = 36.87f;
    std::vector<Sphere> spheres;
};

// Throws Error "FILE: where: what" for a missing file, a JSON syntax error
// (with line and column) or a wrong or missing value.
Scene loadScene(const std::filesystem::path& file);

} // namespace raylab
