#include "fly_through.h"

#include <cmath>

namespace raylab {

CameraPose FlyThrough::poseAt(const CameraPose& start, int frame) const {
    // Turning the position by the same angle as the yaw keeps the view
    // pointed at the same part of the scene (Camera: yaw 0 looks along -z,
    // positive yaw turns toward +x).
    float angleDeg = degreesPerFrame * float(frame);
    float a = angleDeg * 3.14159265f / 180.0f;
    CameraPose pose = start;
    pose.position.x = start.position.x * std::cos(a) - start.position.z * std::sin(a);
    pose.position.z = start.position.x * std::sin(a) + start.position.z * std::cos(a);
    pose.yawDeg = start.yawDeg + angleDeg;
    return pose;
}

}  // namespace raylab
