#pragma once
// Reading values out of a JSON file with one-line messages that name the file
// and the JSON path ("assets/scenes/lite.json: spheres[3].radius: expected a
// positive number"). The scene reader and the stage catalogue build on it.
#include "camera.h"
#include "error.h"

#include <glm/glm.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <initializer_list>
#include <string>

namespace raylab {

using nlohmann::json;

struct JsonReader {
    std::string file;  // as shown in messages

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(file + ": " + where + ": " + what);
    }
    // OBJ[KEY]; WHERE is OBJ's own path ("camera": 'camera: missing "yaw"').
    const json& member(const json& obj, const std::string& where, const char* key) const;
    // A finite number within +-1e30, as a float.
    float number(const json& v, const std::string& where) const;
    // The same number in double precision: a scene's positions and lengths
    // (1e6 + 0.35 is no float).
    double real(const json& v, const std::string& where) const;
    std::string string(const json& v, const std::string& where) const;
    // Fails on a key that is not in KNOWN (or "comment"): a typo such as
    // "tile_szie" must not be dropped silently.
    void allowOnly(const json& obj, const std::string& where,
                   std::initializer_list<const char*> known) const;
    // The list under KEY, or an empty list when the file has none.
    const json& optionalList(const json& doc, const char* key) const;

    float positive(const json& v, const std::string& where) const;
    glm::vec3 vec3(const json& v, const std::string& where) const;
    // Double precision: a length (positive, at least 1e-30) and a position.
    double length(const json& v, const std::string& where) const;
    glm::dvec3 point(const json& v, const std::string& where) const;
    glm::vec3 direction(const json& v, const std::string& where) const;  // normalised, not zero
    glm::vec3 color(const json& v, const std::string& where) const;      // components in [0, 1]
};

// The JSON document in FILE (SHOWN in messages). Throws Error with one line:
// "SHOWN: cannot read the file", "SHOWN: line 3, column 7: JSON syntax error",
// "SHOWN: JSON number out of range (larger than a double can hold)".
json parseJsonFile(const std::filesystem::path& file, const std::string& shown);

// The "camera" block every scene file has, whatever its track:
// {"position": [x, y, z], "yaw": deg, "pitch": deg, "fov_y": deg (optional)}.
struct SceneCamera {
    CameraPose pose;
    float fovYDeg = 36.87f;  // Camera's default: the seed's canvas
};
SceneCamera readSceneCamera(const JsonReader& r, const json& doc);

// Only the camera block of the scene file FILE (any track's): what grading
// needs to move a view's camera. Throws Error naming the file.
SceneCamera loadSceneCamera(const std::filesystem::path& file);

}  // namespace raylab
