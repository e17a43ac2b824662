#pragma once
// A scene file (JSON, under assets/scenes/): background, camera, materials,
// lights and objects. Positions and lengths are held in double precision, as
// the file gives them: a scene 1e6 from the origin keeps its centimetres. The
// renderers move it next to the origin in double (sceneFrame) before anything
// becomes a float for the GPU. Stage 01 uses spheres; stage 05 adds planes, discs,
// triangles (also as rectangles and boxes) and tori; stage 06 textures and a
// sky box. The format is documented in assets/scenes/README.md.
#include "camera.h"
#include "mesh.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

// A sinusoidal bob: offset = axis * amplitude * sin(2 pi t / period).
struct Motion {
    glm::vec3 axis{0.0f};
    double amplitude = 0.0;
    float periodSeconds = 1.0f;
    glm::dvec3 offsetAt(float t) const;
};

// Blinn-Phong material. Scenes name materials in a table; objects refer to
// them by name.
struct Material {
    // How light leaves the surface besides Blinn-Phong (from stage 04 on).
    enum class Type { Plastic = 0, Mirror = 1, Glass = 2, Metal = 3 };
    std::string name;
    Type type = Type::Plastic;
    float ior = 1.5f;            // glass: index of refraction
    glm::vec3 n{0.0f}, k{0.0f};  // metal: complex index n + ik per RGB channel
    glm::vec3 ambient{0.0f};
    glm::vec3 diffuse{1.0f};  // also the flat colour of stage 01
    glm::vec3 specular{0.0f};
    float shininess = 30.0f;  // the seed's exponent
    int texture = -1;         // layer in Scene::textures multiplying ambient and diffuse, -1: none
    int normalMap = -1;       // layer in Scene::textures, -1: none (stage 07)
};

struct PointLight {
    glm::dvec3 position{0.0};
    glm::vec3 color{1.0f};
};

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 1.0;
    int material = 0;  // index into Scene::materials
    Motion motion;
};

// An infinite plane through `point`; textures repeat every `tileSize` units.
struct Plane {
    glm::dvec3 point{0.0};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit
    double tileSize = 1.0;
    int material = 0;
};

struct Disc {
    glm::dvec3 center{0.0};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit
    double radius = 1.0;
    int material = 0;
};

// Counter-clockwise seen from the side the normal points to. Rectangles and
// boxes in the file become triangles.
struct Triangle {
    std::array<glm::dvec3, 3> vertices{};
    int material = 0;
};

// A ring around `axis` through `center`: distance `majorRadius` from the
// centre to the middle of the tube, tube radius `minorRadius`. With a spin,
// the torus turns about `spinAxis` once every `spinPeriod` seconds.
struct Torus {
    glm::dvec3 center{0.0};
    glm::vec3 axis{0.0f, 1.0f, 0.0f};  // unit
    double majorRadius = 1.0;
    double minorRadius = 0.25;
    glm::vec3 spinAxis{0.0f, 1.0f, 0.0f};
    float spinPeriod = 0.0f;  // 0: no spin
    int material = 0;
    glm::vec3 axisAt(float t) const;
};

// World-to-local rotation of a torus whose axis is AXIS: the axis becomes +z
// (the shaders' uTorusToLocal).
glm::mat3 torusToLocal(glm::vec3 axis);

// A triangle mesh from an OBJ file (stage 08), placed in the world: its
// positions scaled by `scale` and moved by `translate` when read (in double,
// like every position of a scene), so `positions` are world coordinates
// (normals unchanged: the scale is uniform). Its vertex normals and texture
// coordinates are interpolated across each triangle; one material for the
// whole mesh.
struct MeshObject {
    std::filesystem::path file;
    std::vector<glm::dvec3> positions;
    std::vector<glm::vec3> normals;      // unit, one per position
    std::vector<glm::vec2> uvs;          // one per position
    std::vector<std::uint32_t> indices;  // three per triangle
    int material = 0;
    std::size_t triangleCount() const { return indices.size() / 3; }
    // Corner K (0-2) of triangle T.
    const glm::dvec3& corner(std::size_t t, std::size_t k) const {
        return positions[indices[3 * t + k]];
    }
};

// A halo drawn around a sphere (the "sun"), key G.
struct Glow {
    int sphere = -1;  // -1: none
    glm::vec3 color{1.0f, 0.8f, 0.5f};
    float size = 4.0f;  // how far the halo reaches, in sphere radii
};

struct Scene {
    std::string file;  // display path, for messages
    glm::vec3 background{0.0f};
    CameraPose camera;
    float fovYDeg = 36.87f;
    std::vector<Material> materials;
    std::vector<PointLight> lights;
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Disc> discs;
    std::vector<Triangle> triangles;
    std::vector<Torus> tori;
    std::vector<MeshObject> meshes;
    std::vector<std::filesystem::path> textures;  // image files, one texture layer each
    std::optional<std::array<std::filesystem::path, 6>> skyBox;  // faces +x, -x, +y, -y, +z, -z
    Glow glow;
};

// Throws Error "FILE: where: what" for a missing file, a JSON syntax error
// (with line and column), a wrong or missing value, an unknown material or a
// texture file that does not exist. Texture paths are relative to the scene
// file's folder.
// A sphere gives either "material" (a name from "materials") or "color" (a
// flat colour: a material of its own with that diffuse colour).
Scene loadScene(const std::filesystem::path& file);

// MESH (as read from FILE, in its own coordinates) placed in the world:
// positions scaled by SCALE and moved by TRANSLATE, in double.
MeshObject placeMesh(std::filesystem::path file, Mesh mesh, double scale,
                     const glm::dvec3& translate, int material);

// The triangles of all meshes together (KIND_MESH indices run through the
// meshes in order).
std::size_t meshTriangleCount(const Scene& scene);

// The meshes' triangles as the shaders read them (scene_meshes.glsl): six
// RGBA texels per triangle, its corners (position, u) then their (normal,
// v); and per triangle its mesh's material. At least one entry each (an
// empty buffer texture is not allowed everywhere).
std::vector<float> meshCornerTexels(const Scene& scene);
std::vector<int> meshTriangleMaterials(const Scene& scene);

}  // namespace raylab
