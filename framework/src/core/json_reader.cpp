#include "json_reader.h"

#include <cmath>

namespace raylab {

const json& JsonReader::member(const json& obj, const std::string& where, const char* key) const {
    if (!obj.is_object()) fail(where, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(where, std::string("missing \"") + key + "\"");
    return *it;
}

float JsonReader::number(const json& v, const std::string& where) const {
    if (!v.is_number()) fail(where, "expected a number");
    double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > 1e30) fail(where, "number out of range");
    return float(d);
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

}  // namespace raylab
