#pragma once
// A fur scene (assets/scenes/fur/*.json): one mesh with a transform, a
// directional light, the camera, and the fur's parameters and textures.
// The format is in assets/scenes/README.md, "Fur scenes".
#include "camera.h"
#include "mesh.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>

namespace raylab {

struct FurMeshSpec {
    std::string shape;  // "sphere", "torus", "cube" (mesh_shapes.h); empty when obj is set
    int detail = 16;
    std::filesystem::path obj;  // an OBJ file (obj_mesh.h)
    // An OBJ model is moved and scaled into the box from -1 to 1 (its
    // bounding box centred on the origin, its longest side 2 units), the
    // size of the built-in shapes the scenes' cameras and fur lengths are
    // made for: models come in any units (a bunny 10 units tall, a teapot
    // 32 wide). "fit": false keeps the file's own coordinates.
    bool fit = true;
    // Texture coordinates of an OBJ model without any ("uvs": "sphere" or
    // "box"; mesh.h says what each does well and badly).
    UvProjection uvs = UvProjection::Sphere;
};

// Where an OBJ model ended up: its bounds as the file gives them and, when
// fitted, the scale and the centre applied (p -> (p - centre) * scale).
struct MeshPlacement {
    bool fromObj = false;
    bool fitted = false;
    glm::vec3 lo{0.0f}, hi{0.0f};
    glm::vec3 centre{0.0f};
    float scale = 1.0f;
    std::size_t triangles = 0;
};

// One line for the user about an OBJ model (empty for a built-in shape):
// "mesh FILE: N triangles, bounds (x, y, z) .. (x, y, z); fitted: ...".
std::string describePlacement(const MeshPlacement& placement, const std::string& file);

struct FurParameters {
    float length = 0.2f;           // world units at scale 1 (along the normal)
    int shells = 30;               // layers drawn, the skin included
    float patternScale = 8.0f;     // pattern tiles per unit of texture coordinate
    float shadowIntensity = 0.6f;  // darkening at the root: 1 - intensity * (1 - layer)
    std::filesystem::path colorMap, pattern, finMap;
    // The fur shader (stage f4): strands bend along gravity by up to this
    // share of their length, per unit area there are `strandDensity` roots,
    // and each strand has `strandSegments` line segments.
    float gravity = 0.3f;
    float strandDensity = 600.0f;
    int strandSegments = 4;
};

struct FurScene {
    std::string file;  // as shown in messages
    glm::vec3 background{0.1f};
    CameraPose camera;
    float fovYDeg = 45.0f;
    FurMeshSpec mesh;
    // Model transform: scale, then rotate about z, then x, then y (degrees;
    // y last, so that `spin`, degrees per second added to y, turns the model
    // about the world's vertical), then translate.
    glm::vec3 translate{0.0f}, rotateDeg{0.0f}, scale{1.0f};
    float spinDegPerSecond = 0.0f;
    glm::vec3 lightDirection{0.0f, 1.0f, 0.0f};  // toward the light, unit length
    glm::vec3 lightColor{1.0f}, ambient{0.15f};
    FurParameters fur;

    // The model matrix at TIME seconds.
    glm::mat4 modelMatrix(float timeSeconds) const;
};

// Throws Error("FILE: where: what") with the file and JSON path.
FurScene loadFurScene(const std::filesystem::path& file);

// The mesh a fur scene names (procedural or OBJ, fitted unless it says
// "fit": false), checked; PLACEMENT (optional) says where an OBJ model went.
// Throws Error.
Mesh loadFurMesh(const FurScene& scene, MeshPlacement* placement = nullptr);

}  // namespace raylab
