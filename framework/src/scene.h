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

// Blinn-Phong material. Scenes name materials in a table; objects refer to
// them by name.
struct Material {
    // How light leaves the surface besides Blinn-Phong (from stage 04 on).
    enum class Type { Plastic = 0, Mirror = 1, Glass = 2, Metal = 3 };
    std::string name;
    Type type = Type::Plastic;
    float ior = 1.5f;          // glass: index of refraction
    glm::vec3 n{0.0f}, k{0.0f};  // metal: complex index n + ik per RGB channel
    glm::vec3 ambient{0.0f};
    glm::vec3 diffuse{1.0f};   // also the flat colour of stage 01
    glm::vec3 specular{0.0f};
    float shininess = 30.0f;   // the seed's exponent
};

struct PointLight {
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};
};

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    int material = 0;  // index into Scene::materials
    Motion motion;
};

struct Scene {
    std::string file;  // display path, for messages
    glm::vec3 background{0.0f};
    CameraPose camera;
    float fovYDeg = 36.87f;
    std::vector<Material> materials;
    std::vector<PointLight> lights;
    std::vector<Sphere> spheres;
};

// Throws Error "FILE: where: what" for a missing file, a JSON syntax error
// (with line and column), a wrong or missing value, or an unknown material.
// A sphere gives either "material" (a name from "materials") or "color" (a
// flat colour: a material of its own with that diffuse colour).
Scene loadScene(const std::filesystem::path& file);

} // namespace raylab
