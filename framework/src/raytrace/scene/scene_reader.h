#pragma once
// Reading values out of a scene file's JSON with messages that name the file
// and the JSON path ("assets/scenes/lite.json: spheres[3].radius: expected a
// positive number"). Internal to scene*.cpp.
#include "error.h"
#include "scene.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>

namespace raylab {

using nlohmann::json;

struct SceneReader {
    const std::string& file;
    std::filesystem::path folder;  // relative paths in the file start here

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(file + ": " + where + ": " + what);
    }
    const json& member(const json& obj, const std::string& where, const char* key) const;
    float number(const json& v, const std::string& where) const;
    float positive(const json& v, const std::string& where) const;
    glm::vec3 vec3(const json& v, const std::string& where) const;
    glm::vec3 direction(const json& v, const std::string& where) const;  // normalised, not zero
    glm::vec3 color(const json& v, const std::string& where) const;
    std::string string(const json& v, const std::string& where) const;
    // A file named relative to the scene's folder, which must exist.
    std::filesystem::path existingFile(const json& v, const std::string& where) const;
    // Fails on a key that is not in KNOWN (or "comment"): a typo such as
    // "tile_szie" must not be dropped silently.
    void allowOnly(const json& obj, const std::string& where,
                   std::initializer_list<const char*> known) const;
    // The list under KEY, or an empty list when the file has none.
    const json& optionalList(const json& doc, const char* key) const;
};

// The objects: spheres, planes, discs, triangles (and rectangles and boxes,
// made of triangles) and tori. Materials must already be read.
void readShapes(const SceneReader& r, const json& doc, Scene& scene);

}  // namespace raylab
