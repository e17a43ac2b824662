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
    std::vector<float> v;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        char* end = nullptr;
        float f = std::strtof(part.c_str(), &end);
        if (part.empty() || end == part.c_str() || *end != '\0' || !std::isfinite(f) ||
            std::fabs(f) > 1e7f)
            throw Error(usage);
        v.push_back(f);
    }
    if (v.size() != 5 || (!text.empty() && text.back() == ',')) throw Error(usage);
    if (std::fabs(v[4]) > Camera::kMaxPitchDeg)
        throw Error("--camera '" + text + "': pitch must lie within +-" +
                    std::to_string(int(Camera::kMaxPitchDeg)) + " degrees");
    return CameraPose{{v[0], v[1], v[2]}, v[3], v[4]};
}

}  // namespace raylab
