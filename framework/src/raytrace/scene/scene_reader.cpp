#include "scene_reader.h"

#include "paths.h"

namespace raylab {

std::filesystem::path SceneReader::existingFile(const json& v, const std::string& where) const {
    std::filesystem::path p = folder / string(v, where);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
        fail(where, "file " + displayPath(p) + " does not exist");
    return p.lexically_normal();
}

}  // namespace raylab
