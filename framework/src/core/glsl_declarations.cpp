#include "glsl_declarations.h"

#include "error.h"

#include <map>
#include <set>

namespace raylab {

std::vector<GlslStatement> fileScopeStatements(const std::vector<GlslToken>& t) {
    std::vector<GlslStatement> out;
    int depth = 0;
    std::size_t begin = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const std::string& s = t[i].text;
        if (s == "{") ++depth;
        else if (s == "}" && --depth == 0) out.push_back({begin, i + 1}), begin = i + 1;
        else if (s == ";" && depth == 0) out.push_back({begin, i + 1}), begin = i + 1;
    }
    return out;
}

namespace {

const std::set<std::string> kQualifiers = {"flat",      "smooth", "noperspective", "centroid",
                                           "invariant", "highp",  "mediump",       "lowp"};

}  // namespace

std::size_t skipLayout(const std::vector<GlslToken>& t, std::size_t i, std::size_t end,
                       std::vector<std::string>* words) {
    if (i >= end || t[i].text != "layout" || i + 1 >= end || t[i + 1].text != "(") return i;
    std::size_t j = i + 2;
    for (; j < end && t[j].text != ")"; ++j)
        if (words) words->push_back(t[j].text);
    return j + 1;
}

bool parseVaryings(const std::vector<GlslToken>& t, const GlslStatement& s,
                   const std::string& storage, std::vector<GlslVarying>& out,
                   const ShaderSource& source) {
    std::size_t i = skipLayout(t, s.begin, s.end);
    bool hasStorage = false;
    while (i < s.end && (kQualifiers.count(t[i].text) || t[i].text == storage)) {
        hasStorage = hasStorage || t[i].text == storage;
        ++i;
    }
    if (!hasStorage || i + 1 >= s.end || t[i].text == ";") return false;
    const GlslToken& type = t[i++];
    if (t[i].text == "{") {
        const SourceLine w = source.where(type.line);
        throw Error(w.file + ":" + std::to_string(w.line) + ": an interface block (" + type.text +
                    " { ... }) cannot be passed between the page's emulated shader stages; "
                    "declare its members one by one");
    }
    while (i < s.end) {
        GlslVarying v{type.text, t[i].text, false, t[i].line};
        ++i;
        if (i < s.end && t[i].text == "[") {
            v.array = true;
            while (i < s.end && t[i].text != "]") ++i;
            ++i;
        }
        out.push_back(v);
        if (i < s.end && t[i].text == ",") ++i;
        else break;
    }
    return true;
}

BasicType basicType(const std::string& type) {
    static const std::map<std::string, BasicType> kTypes = {
        {"float", {1, 'f'}}, {"vec2", {2, 'f'}},  {"vec3", {3, 'f'}},  {"vec4", {4, 'f'}},
        {"int", {1, 'i'}},   {"ivec2", {2, 'i'}}, {"ivec3", {3, 'i'}}, {"ivec4", {4, 'i'}},
        {"uint", {1, 'u'}},  {"uvec2", {2, 'u'}}, {"uvec3", {3, 'u'}}, {"uvec4", {4, 'u'}},
    };
    const auto it = kTypes.find(type);
    return it == kTypes.end() ? BasicType{} : it->second;
}

}  // namespace raylab
