#pragma once
// What the page's bindings share: typed-array copies and sources as JSON.
// Students need not read this file.
#include "shader_source.h"

#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include <vector>

namespace raylab {

// A copy (wasm memory may move when it grows) as a new JavaScript TYPE array.
template <typename T>
emscripten::val typedArray(const char* type, const std::vector<T>& values) {
    return emscripten::val::global(type).new_(
        emscripten::typed_memory_view(values.size(), values.data()));
}

// {"text": ..., "origin": [[file, line], ...]}: what mapCompilerLog needs back.
inline nlohmann::json sourceJson(const ShaderSource& s) {
    nlohmann::json origin = nlohmann::json::array();
    for (const SourceLine& l : s.origin) origin.push_back({l.file, l.line});
    return {{"text", s.text}, {"origin", origin}};
}

}  // namespace raylab
