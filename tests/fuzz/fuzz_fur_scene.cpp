// libFuzzer target: raylab::loadFurScene on arbitrary bytes as a fur scene
// file. The input goes to <scratch>/fur.json; texture and OBJ names are only
// checked with stat() relative to that folder, never opened (the mesh is
// loaded by the renderer, not by loadFurScene), so any name is harmless.
// Three small texture files sit next to it so the success path is reachable.
#include "error.h"
#include "fur_scene.h"
#include "fuzz_support.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    static const fuzz::fs::path scene = [] {
        const fuzz::fs::path& dir = fuzz::scratchDir();
        const std::uint8_t png[] = {0x89, 'P', 'N', 'G'};  // contents are never read
        for (const char* name : {"c.png", "p.png", "f.png"}) fuzz::writeBytes(dir / name, png, 4);
        return dir / "fur.json";
    }();
    fuzz::writeBytes(scene, data, size);
    try {
        const FurScene s = loadFurScene(scene);
        // What the renderer relies on: a unit light direction, positive
        // scales and lengths, counts within their ranges.
        if (!(std::fabs(glm::length(s.lightDirection) - 1.0f) < 1e-3f)) __builtin_trap();
        for (int i = 0; i < 3; ++i)
            if (!(s.scale[i] > 0.0f)) __builtin_trap();
        if (!(s.fur.length > 0.0f) || s.fur.shells < 1 || s.fur.shells > 256) __builtin_trap();
        if (s.fur.strandSegments < 1 || s.fur.strandSegments > 16) __builtin_trap();
        if (s.mesh.obj.empty() == s.mesh.shape.empty()) __builtin_trap();
    } catch (const Error&) {
        // A message for the user: the expected way to reject bad input.
    }
    return 0;
}
