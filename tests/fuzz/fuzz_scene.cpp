// libFuzzer target: raylab::loadScene on arbitrary bytes as a scene file.
//
// The input goes to <scratch>/scene.json (one file per process, rewritten
// each run). loadScene reads that file; texture and sky-box names are
// checked with stat() (is_regular_file) relative to the scene's folder, never
// opened or written; mesh files ("meshes") are regular files of at most
// kMaxMeshFileBytes, opened and parsed read-only. So a name such as
// "../../etc/passwd" or "/dev/zero" is harmless (the first is parsed as an
// OBJ and refused, the second is no regular file). Two small texture files sit next to the scene so
// the success path (materials with textures and normal maps, sky boxes) is reachable too, and a
// small OBJ file (quad.obj) for "meshes" (read by tinyobjloader).
#include "error.h"
#include "fuzz_support.h"
#include "scene.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    static const fuzz::fs::path scene = [] {
        const fuzz::fs::path& dir = fuzz::scratchDir();
        const std::uint8_t png[] = {0x89, 'P', 'N', 'G'};  // contents are never read
        fuzz::writeBytes(dir / "tex.png", png, sizeof png);
        fuzz::writeBytes(dir / "normal.png", png, sizeof png);
        const char quad[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
        fuzz::writeBytes(dir / "quad.obj", reinterpret_cast<const std::uint8_t*>(quad),
                         sizeof quad - 1);
        return dir / "scene.json";
    }();
    fuzz::writeBytes(scene, data, size);
    try {
        Scene s = loadScene(scene);
        // Every index the loader hands out must point into its table.
        auto check = [&](int material) {
            if (material < 0 || std::size_t(material) >= s.materials.size()) __builtin_trap();
        };
        for (const auto& x : s.spheres) check(x.material);
        for (const auto& x : s.planes) check(x.material);
        for (const auto& x : s.discs) check(x.material);
        for (const auto& x : s.triangles) check(x.material);
        for (const auto& x : s.tori) check(x.material);
        for (const auto& x : s.meshes) {
            check(x.material);
            // Every corner index must point into the mesh's vertices.
            for (std::uint32_t i : x.indices)
                if (i >= x.positions.size() || i >= x.normals.size() || i >= x.uvs.size())
                    __builtin_trap();
        }
        for (const auto& m : s.materials)
            if (m.texture >= int(s.textures.size()) || m.normalMap >= int(s.textures.size()))
                __builtin_trap();
        if (s.glow.sphere >= int(s.spheres.size())) __builtin_trap();
    } catch (const Error&) {
        // A message for the user: the expected way to reject bad input.
    }
    return 0;
}
