#include "cli_parse.h"

#include "error.h"

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <vector>

namespace raylab {

Size parseSize(const std::string& text) {
    static const std::regex re(R"(^(\d{1,6})[xX](\d{1,6})$)");
    std::smatch m;
    if (!std::regex_match(text, m, re))
        throw Error("--size '" + text + "': expected WIDTHxHEIGHT, e.g. 800x600");
    Size s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.width < 1 || s.height < 1 || s.width > kMaxSide || s.height > kMaxSide)
        throw Error("--size '" + text + "': each side must be between 1 and " +
                    std::to_string(kMaxSide));
    return s;
}

CameraPose parseCamera(const std::string& text) {
    const std::string usage =
        "--camera '" + text + "': expected x,y,z,yaw,pitch (numbers; angles in degrees)";
    std::vector<double> v;  // the position in double, like a scene file's
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        char* end = nullptr;
        const double f = std::strtod(part.c_str(), &end);
        if (part.empty() || end == part.c_str() || *end != '\0' || !std::isfinite(f) ||
            std::fabs(f) > 1e7)
            throw Error(usage);
        v.push_back(f);
    }
    if (v.size() != 5 || (!text.empty() && text.back() == ',')) throw Error(usage);
    if (std::fabs(v[4]) > Camera::kMaxPitchDeg)
        throw Error("--camera '" + text + "': pitch must lie within +-" +
                    std::to_string(int(Camera::kMaxPitchDeg)) + " degrees");
    return CameraPose{{v[0], v[1], v[2]}, float(v[3]), float(v[4])};
}

double parseSceneScale(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v >= kMinSceneScale && v <= kMaxSceneScale))
        throw Error("--scene-scale '" + text + "': expected a factor between 1e-6 and 1e8");
    return v;
}

glm::dvec3 parseSceneOffset(const std::string& text) {
    const std::string usage =
        "--scene-offset '" + text + "': expected x,y,z (numbers within +-1e8)";
    std::vector<double> v;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        char* end = nullptr;
        const double d = std::strtod(part.c_str(), &end);
        if (part.empty() || end == part.c_str() || *end != '\0' || !(std::fabs(d) <= 1e8))
            throw Error(usage);
        v.push_back(d);
    }
    if (v.size() != 3 || text.back() == ',') throw Error(usage);
    return {v[0], v[1], v[2]};
}

}  // namespace raylab
