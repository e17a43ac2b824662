#pragma once
// Reading values out of a scene file's JSON (json_reader.h) with messages
// that name the file and the JSON path. Internal to scene*.cpp.
#include "json_reader.h"
#include "scene.h"

#include <string>

namespace raylab {

// The scene's own value kinds on top of JsonReader's.
struct SceneReader : JsonReader {
    std::filesystem::path folder;  // relative paths in the file start here

    float positive(const json& v, const std::string& where) const;
    glm::vec3 vec3(const json& v, const std::string& where) const;
    glm::vec3 direction(const json& v, const std::string& where) const;  // normalised, not zero
    glm::vec3 color(const json& v, const std::string& where) const;
    // A file named relative to the scene's folder, which must exist.
    std::filesystem::path existingFile(const json& v, const std::string& where) const;
};

// The objects: spheres, planes, discs, triangles (and rectangles and boxes,
// made of triangles) and tori. Materials must already be read.
void readShapes(const SceneReader& r, const json& doc, Scene& scene);

}  // namespace raylab
