#include "obj_mesh.h"

#include "error.h"
#include "paths.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>
#include <vector>

namespace raylab {

namespace {

// tinyobjloader reads what is not a number as 0 ("v nan 1 0" is a vertex at
// the origin) and wraps indices beyond an int ("f 99999999999 ..." names
// vertex 1215752191): the numbers are checked here first, with the line.
void checkNumbers(const std::filesystem::path& file, const std::string& name) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    for (long n = 1; std::getline(in, line); ++n) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        const bool coordinates = keyword == "v" || keyword == "vn" || keyword == "vt";
        if (!coordinates && keyword != "f") continue;
        auto fail = [&](const std::string& what) {
            throw Error(name + ":" + std::to_string(n) + ": " + what);
        };
        for (std::string word; words >> word;) {
            if (coordinates) {
                char* end = nullptr;
                errno = 0;
                const double v = std::strtod(word.c_str(), &end);
                if (end == word.c_str() || *end != '\0')
                    fail(keyword + ": '" + word + "' is not a number");
                if (!std::isfinite(v) || errno == ERANGE || std::fabs(v) > 3.0e38)
                    fail(keyword + ": '" + word + "' is not a finite float");
                continue;
            }
            // f: vertex[/texture[/normal]], each a whole number, negative counting back.
            std::istringstream parts(word);
            for (std::string part; std::getline(parts, part, '/');) {
                if (part.empty()) continue;
                char* end = nullptr;
                errno = 0;
                const long long i = std::strtoll(part.c_str(), &end, 10);
                if (end == part.c_str() || *end != '\0')
                    fail("f: '" + word + "' is not an index (v, v/vt, v//vn or v/vt/vn)");
                if (errno == ERANGE || i > 2147483647LL || i < -2147483647LL)
                    fail("f: index " + part + " is out of range");
                if (i == 0) fail("f: index 0 (OBJ counts from 1)");
            }
        }
    }
}

}  // namespace

Mesh loadObjMesh(const std::filesystem::path& file, UvProjection projection) {
    const std::string name = displayPath(file);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw Error(name + ": file does not exist");
    if (!std::filesystem::is_regular_file(file, ec))
        throw Error(name + ": not a regular file (a folder, a device or a pipe)");
    checkNumbers(file, name);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = "";  // no materials: a missing .mtl must not fail the mesh
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        throw Error(name + ": not a readable OBJ file (" +
                    (why.empty() ? std::string("no reason given") : why) + ")");
    }
    // tinyobjloader skips a polygon with a bad index and only warns: a mesh
    // with silent holes would be worse than an error.
    for (const char* dropped : {"invalid vertex index", "Degenerated face"}) {
        const std::string& warning = reader.Warning();
        const std::size_t at = warning.find(dropped);
        if (at == std::string::npos) continue;
        std::size_t start = warning.rfind('\n', at);
        start = start == std::string::npos ? 0 : start + 1;
        std::string line = warning.substr(start, warning.find('\n', at) - start);
        throw Error(name + ": a face was dropped while reading (" + line + ")");
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    for (float v : attrib.vertices)
        if (!std::isfinite(v)) throw Error(name + ": a vertex (v line) is not a finite number");

    // Does every face corner name a normal / a texture coordinate?
    bool allNormals = true, allUvs = true;
    std::size_t corners = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes())
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            ++corners;
            allNormals = allNormals && i.normal_index >= 0;
            allUvs = allUvs && i.texcoord_index >= 0;
        }
    if (corners == 0) throw Error(name + ": the file has no faces (f lines)");

    Mesh mesh;
    mesh.name = name;
    std::map<std::tuple<int, int, int>, std::uint32_t> vertexOf;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f)
            if (shape.mesh.num_face_vertices[f] != 3)
                throw Error(name + ": face " + std::to_string(f + 1) + " of '" + shape.name +
                            "' could not be split into triangles");
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            const int n = allNormals ? i.normal_index : -1, t = allUvs ? i.texcoord_index : -1;
            auto key = std::make_tuple(i.vertex_index, n, t);
            auto it = vertexOf.find(key);
            if (it == vertexOf.end()) {
                if (i.vertex_index < 0)
                    throw Error(name + ": a face's relative vertex index counts back past the "
                                       "first vertex");
                const std::size_t v = std::size_t(i.vertex_index);
                if (3 * v + 2 >= attrib.vertices.size())
                    throw Error(name + ": a face names vertex " + std::to_string(v + 1) +
                                ", which does not exist");
                if (n >= 0 && 3 * std::size_t(n) + 2 >= attrib.normals.size())
                    throw Error(name + ": a face names normal " + std::to_string(n + 1) +
                                ", which does not exist");
                if (t >= 0 && 2 * std::size_t(t) + 1 >= attrib.texcoords.size())
                    throw Error(name + ": a face names texture coordinate " +
                                std::to_string(t + 1) + ", which does not exist");
                it = vertexOf.emplace(key, std::uint32_t(mesh.positions.size())).first;
                mesh.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                            attrib.vertices[3 * v + 2]);
                if (n >= 0)
                    mesh.normals.emplace_back(attrib.normals[3 * std::size_t(n)],
                                              attrib.normals[3 * std::size_t(n) + 1],
                                              attrib.normals[3 * std::size_t(n) + 2]);
                if (t >= 0)
                    mesh.uvs.emplace_back(attrib.texcoords[2 * std::size_t(t)],
                                          attrib.texcoords[2 * std::size_t(t) + 1]);
            }
            mesh.indices.push_back(it->second);
        }
    }
    if (allNormals) {
        // Normals as written may not be unit length; a zero (or non-finite)
        // one is replaced by the smooth normal there, the others are kept.
        std::vector<std::size_t> bad;
        for (std::size_t k = 0; k < mesh.normals.size(); ++k) {
            const float l = glm::length(mesh.normals[k]);
            if (l > 0.0f && std::isfinite(l)) mesh.normals[k] /= l;
            else bad.push_back(k);
        }
        if (!bad.empty()) {
            Mesh smooth = mesh;
            computeSmoothNormals(smooth);
            for (std::size_t k : bad) mesh.normals[k] = smooth.normals[k];
        }
    } else {
        computeSmoothNormals(mesh);
    }
    if (!allUvs) {
        if (projection == UvProjection::Box) computeBoxUvs(mesh);
        else computeSphericalUvs(mesh);
    }
    validateMesh(mesh);
    return mesh;
}

}  // namespace raylab
