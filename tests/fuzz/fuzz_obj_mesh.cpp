// libFuzzer target: raylab::loadObjMesh on arbitrary bytes as an OBJ file,
// then the fin shader's edge adjacency of what it returns. tinyobjloader is
// compiled from Debian's header into this target
// (framework/src/fur/mesh/tiny_obj_loader_impl.cpp), so the fuzzer sees its
// branches too.
#include "adjacency.h"
#include "error.h"
#include "fuzz_support.h"
#include "obj_mesh.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    static const fuzz::fs::path file = fuzz::scratchDir() / "mesh.obj";
    fuzz::writeBytes(file, data, size);
    try {
        const Mesh m = loadObjMesh(file);
        // A mesh the renderer accepts: indices in range, unit or fallback
        // normals, finite everything (validateMesh threw otherwise).
        for (std::uint32_t i : m.indices)
            if (i >= m.vertexCount()) __builtin_trap();
        for (const glm::vec3& n : m.normals)
            if (!(std::fabs(glm::length(n) - 1.0f) < 1e-3f)) __builtin_trap();
        const EdgeAdjacency adj = buildEdgeAdjacency(m);
        for (std::uint32_t i : adj.indices)
            if (i >= m.vertexCount()) __builtin_trap();
        if (adj.indices.size() % 4 != 0) __builtin_trap();
    } catch (const Error&) {
        // A message for the user: the expected way to reject bad input.
    }
    return 0;
}
