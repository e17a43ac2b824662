#include "scene_reader.h"

#include "paths.h"

#include <cmath>

namespace raylab {

float SceneReader::positive(const json& v, const std::string& where) const {
    float f = number(v, where);
    if (!(f > 0.0f)) fail(where, "expected a positive number");
    return f;
}

glm::vec3 SceneReader::vec3(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() != 3) fail(where, "expected [x, y, z]");
    return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
}

glm::vec3 SceneReader::direction(const json& v, const std::string& where) const {
    glm::vec3 d = vec3(v, where);
    float length = glm::length(d);
    if (!(length > 1e-6f) || !std::isfinite(length))
        fail(where, "expected a direction, not a zero vector");
    return d / length;
}

glm::vec3 SceneReader::color(const json& v, const std::string& where) const {
    glm::vec3 c = vec3(v, where);
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0.0f || c[i] > 1.0f) fail(where, "colour components must lie in [0, 1]");
    return c;
}

std::filesystem::path SceneReader::existingFile(const json& v, const std::string& where) const {
    std::filesystem::path p = folder / string(v, where);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
        fail(where, "file " + displayPath(p) + " does not exist");
    return p.lexically_normal();
}

}  // namespace raylab
