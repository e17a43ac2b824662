#include "camera.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {
constexpr glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};
}

Camera::Camera(const CameraPose& pose, float fovYDeg) : pose_(pose), fovYDeg_(fovYDeg) {
    pose_.pitchDeg = std::clamp(pose_.pitchDeg, -kMaxPitchDeg, kMaxPitchDeg);
}

glm::vec3 Camera::forward() const {
    float yaw = glm::radians(pose_.yawDeg), pitch = glm::radians(pose_.pitchDeg);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), kWorldUp)); }

glm::vec3 Camera::up() const { return glm::cross(right(), forward()); }

float Camera::focalLength() const { return 1.0f / std::tan(glm::radians(fovYDeg_) * 0.5f); }

void Camera::turn(float dYawDeg, float dPitchDeg) {
    pose_.yawDeg = std::fmod(pose_.yawDeg + dYawDeg, 360.0f);
    pose_.pitchDeg = std::clamp(pose_.pitchDeg + dPitchDeg, -kMaxPitchDeg, kMaxPitchDeg);
}

void Camera::move(float alongForward, float alongRight) {
    pose_.position += forward() * alongForward + right() * alongRight;
}

glm::vec3 Camera::rayDirection(int px, int py, int width, int height) const {
    float aspect = float(width) / float(height);
    float x = (float(px) + 0.5f) / float(width) * 2.0f - 1.0f;
    float y = 1.0f - (float(py) + 0.5f) / float(height) * 2.0f;
    return forward() * focalLength() + right() * (aspect * x) + up() * y;
}

}  // namespace raylab
