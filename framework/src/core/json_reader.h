#pragma once
// Reading values out of a JSON file with one-line messages that name the file
// and the JSON path ("assets/scenes/lite.json: spheres[3].radius: expected a
// positive number"). The scene reader and the stage catalogue build on it.
#include "error.h"

#include <nlohmann/json.hpp>

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
    std::string string(const json& v, const std::string& where) const;
    // Fails on a key that is not in KNOWN (or "comment"): a typo such as
    // "tile_szie" must not be dropped silently.
    void allowOnly(const json& obj, const std::string& where,
                   std::initializer_list<const char*> known) const;
    // The list under KEY, or an empty list when the file has none.
    const json& optionalList(const json& doc, const char* key) const;
};

}  // namespace raylab
