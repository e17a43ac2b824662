#pragma once
// Parsing of the command line's value formats, with one-line errors.
#include "camera.h"

#include <string>

namespace raylab {

struct Size {
    int width = 0;
    int height = 0;
};

// "WxH", each side 1..kMaxSide. Throws Error("--size '...': ...").
Size parseSize(const std::string& text);
inline constexpr int kMaxSide = 8192;

// "x,y,z,yaw,pitch" (degrees; pitch within +-Camera::kMaxPitchDeg).
CameraPose parseCamera(const std::string& text);

// --scene-scale: a factor within [kMinSceneScale, kMaxSceneScale] (beyond,
// float itself runs out: 1e-30 squared is 0).
inline constexpr double kMinSceneScale = 1e-6, kMaxSceneScale = 1e8;
double parseSceneScale(const std::string& text);
// --scene-offset: "x,y,z", each within +-1e8.
glm::dvec3 parseSceneOffset(const std::string& text);

}  // namespace raylab
