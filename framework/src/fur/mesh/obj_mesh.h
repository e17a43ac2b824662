#pragma once
// Triangle meshes from Wavefront OBJ files, read by Debian's tinyobjloader.
#include "mesh.h"

#include <filesystem>

namespace raylab {

// Every object and group of FILE as one mesh; polygons are triangulated, and
// one vertex is made per distinct (position, normal, texture coordinate)
// triple. Missing normals are computed (smooth, area-weighted) and missing
// texture coordinates by PROJECTION (mesh.h says how each does); a file that mixes faces with
// and without them gets them computed for every face. Materials are ignored.
// Throws Error("FILE: cause") for a missing or malformed file or one without
// triangles.
Mesh loadObjMesh(const std::filesystem::path& file, UvProjection projection = UvProjection::Sphere);

}  // namespace raylab
