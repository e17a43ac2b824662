#pragma once
// Reading values out of a scene file's JSON (json_reader.h) with messages
// that name the file and the JSON path. Internal to scene*.cpp.
#include "json_reader.h"
#include "scene.h"

#include <string>

namespace raylab {

// JsonReader with the scene's folder, for the files a scene names.
struct SceneReader : JsonReader {
    std::filesystem::path folder;  // relative paths in the file start here

    // A file named relative to the scene's folder, which must exist.
    std::filesystem::path existingFile(const json& v, const std::string& where) const;
};

// The objects: spheres, planes, discs, triangles (and rectangles and boxes,
// made of triangles) and tori. Materials must already be read.
void readShapes(const SceneReader& r, const json& doc, Scene& scene);

// An object's "material" (a name from "materials") or "color" (a flat
// colour: a material of its own). Returns the index into scene.materials.
int materialOf(const SceneReader& r, const json& obj, const std::string& where, Scene& scene);

// "meshes": OBJ files placed in the world (scene_meshes.cpp).
void readMeshes(const SceneReader& r, const json& doc, Scene& scene);

}  // namespace raylab
