#include "json_reader.h"

#include "paths.h"

#include <cmath>
#include <fstream>
#include <iterator>

namespace raylab {

const json& JsonReader::member(const json& obj, const std::string& where, const char* key) const {
    if (!obj.is_object()) fail(where, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(where, std::string("missing \"") + key + "\"");
    return *it;
}

float JsonReader::number(const json& v, const std::string& where) const {
    return float(real(v, where));
}

double JsonReader::real(const json& v, const std::string& where) const {
    if (!v.is_number()) fail(where, "expected a number");
    double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > 1e30) fail(where, "number out of range");
    return d;
}

std::string JsonReader::string(const json& v, const std::string& where) const {
    if (!v.is_string()) fail(where, "expected a string");
    return v.get<std::string>();
}

void JsonReader::allowOnly(const json& obj, const std::string& where,
                           std::initializer_list<const char*> known) const {
    if (!obj.is_object()) return;  // member() says "expected an object" where it matters
    for (const auto& [key, value] : obj.items()) {
        if (key == "comment") continue;
        bool ok = false;
        std::string list;
        for (const char* k : known) {
            ok |= key == k;
            list += (list.empty() ? "" : ", ") + std::string(k);
        }
        if (!ok)
            fail(where.empty() ? key : where + "." + key, "unknown key (known here: " + list + ")");
    }
}

const json& JsonReader::optionalList(const json& doc, const char* key) const {
    static const json empty = json::array();
    if (!doc.contains(key)) return empty;
    const json& list = doc[key];
    if (!list.is_array()) fail(key, "expected a list");
    return list;
}

float JsonReader::positive(const json& v, const std::string& where) const {
    float f = number(v, where);
    if (!(f > 0.0f)) fail(where, "expected a positive number");
    return f;
}

glm::vec3 JsonReader::vec3(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() != 3) fail(where, "expected [x, y, z]");
    return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
}

double JsonReader::length(const json& v, const std::string& where) const {
    const double d = real(v, where);
    if (!(d > 0.0)) fail(where, "expected a positive number");
    // Positions and lengths meet floats on the GPU; a length no float holds
    // would vanish there.
    if (d < 1e-30) fail(where, "number out of range");
    return d;
}

glm::dvec3 JsonReader::point(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() != 3) fail(where, "expected [x, y, z]");
    return {real(v[0], where + "[0]"), real(v[1], where + "[1]"), real(v[2], where + "[2]")};
}

glm::vec3 JsonReader::direction(const json& v, const std::string& where) const {
    glm::vec3 d = vec3(v, where);
    float length = glm::length(d);
    if (!(length > 1e-6f) || !std::isfinite(length))
        fail(where, "expected a direction, not a zero vector");
    return d / length;
}

glm::vec3 JsonReader::color(const json& v, const std::string& where) const {
    glm::vec3 c = vec3(v, where);
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0.0f || c[i] > 1.0f) fail(where, "colour components must lie in [0, 1]");
    return c;
}

SceneCamera readSceneCamera(const JsonReader& r, const json& doc) {
    SceneCamera c;
    const json& cam = r.member(doc, "scene", "camera");
    r.allowOnly(cam, "camera", {"position", "yaw", "pitch", "fov_y"});
    c.pose.position = r.point(r.member(cam, "camera", "position"), "camera.position");
    c.pose.yawDeg = r.number(r.member(cam, "camera", "yaw"), "camera.yaw");
    c.pose.pitchDeg = r.number(r.member(cam, "camera", "pitch"), "camera.pitch");
    if (cam.contains("fov_y")) {
        c.fovYDeg = r.positive(cam["fov_y"], "camera.fov_y");
        if (c.fovYDeg >= 170.0f) r.fail("camera.fov_y", "must be below 170 degrees");
    }
    return c;
}

namespace {
std::string lineColumn(const std::string& text, std::size_t byte) {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}
}  // namespace

json parseJsonFile(const std::filesystem::path& file, const std::string& shown) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(shown + ": cannot read the file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        throw Error(shown + ": " + lineColumn(text, e.byte > 0 ? e.byte - 1 : 0) +
                    ": JSON syntax error");
    } catch (const json::out_of_range&) {
        // nlohmann::json reports a number too large for a double ("1e500") as
        // out_of_range (406), not parse_error: without this it escaped as a
        // non-Error exception (found by tests/fuzz/fuzz_scene).
        throw Error(shown + ": JSON number out of range (larger than a double can hold)");
    } catch (const json::exception& e) { throw Error(shown + ": not valid JSON: " + e.what()); }
}

SceneCamera loadSceneCamera(const std::filesystem::path& file) {
    JsonReader r{displayPath(file)};
    const json doc = parseJsonFile(file, r.file);
    if (!doc.is_object()) r.fail("scene", "expected an object");
    return readSceneCamera(r, doc);
}

}  // namespace raylab
