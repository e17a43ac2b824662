#pragma once
// Run-time switches a frame is drawn with (window keys, command-line flags).
// Shared by the GPU renderer and the CPU reference tracer, so it holds no GL.

#include "shader_constants.h"

namespace raylab {

struct RenderSettings {
    static constexpr int kMaxDepth = shader::kMaxDepth;
    bool shadows = true;       // key 1, --no-shadows
    int maxDepth = kMaxDepth;  // rays per path, 1..8: arrow keys, --depth (from stage 04 on)
    bool glow = true;          // key G, --no-glow (from stage 06 on)
    bool normalMaps = true;    // key N, --no-normal-maps (from stage 07 on)
    int colorMode = 0;         // Up/Down, --color-mode (stage 08): index into kColorModes

    // The fur track.
    static constexpr int kMaxShells = 256;
    int shells = 0;          // keys [ and ], --shells: 0 for the scene's count
    float furLength = 1.0f;  // keys - and =: a factor on the scene's fur length
    bool fins = true;        // key F, --no-fins (from stage f3 on)
    int furTechnique = 0;    // key T, --technique (stage f4): index into kFurTechniques
    int furMesh = 0;         // key M: 0 for the scene's mesh, else procedural shape furMesh - 1
};

// The two ways to draw fur the fur track compares.
inline constexpr const char* kFurTechniques[] = {"shells_and_fins", "fur_shader"};
inline constexpr int kFurTechniqueCount = 2;

// The seed's colour modes: which input channel feeds red, green and blue.
inline constexpr const char* kColorModes[] = {"RGB", "BRB", "BRR", "RBB", "GGR"};
inline constexpr int kColorModeCount = 5;

}  // namespace raylab
