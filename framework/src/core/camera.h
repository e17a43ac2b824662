#pragma once
// The FPS-style camera of the course (after the seed thesis): the view
// direction comes from two angles, the vertical one clamped so the view never
// turns upside down; W/A/S/D move along the view and sideways.
#include <glm/glm.hpp>

namespace raylab {

struct CameraPose {
    glm::dvec3 position{0.0};  // double, like a scene's positions (scene.h)
    float yawDeg = 0.0f;       // 0 looks down -z, 90 looks down +x
    float pitchDeg = 0.0f;     // positive looks up; kept within +-kMaxPitchDeg
};

class Camera {
public:
    // The seed keeps the polar angle within (0.01, 3.14) rad; the same margin
    // from straight up/down as a pitch limit.
    static constexpr float kMaxPitchDeg = 89.4f;

    Camera() = default;
    Camera(const CameraPose& pose, float fovYDeg);

    const CameraPose& pose() const { return pose_; }
    float fovYDeg() const { return fovYDeg_; }

    glm::vec3 forward() const;
    glm::vec3 right() const;  // normalize(cross(forward, world up))
    glm::vec3 up() const;     // cross(right, forward)
    // Distance from the eye to the canvas whose half-height is 1 (the seed uses 3).
    float focalLength() const;

    // Mouse look: degrees added to yaw and pitch; pitch is clamped.
    void turn(float dYawDeg, float dPitchDeg);
    // Moves by (forward, right) amounts in world units.
    void move(float alongForward, float alongRight);

    // The primary ray direction (not normalised) through the centre of pixel
    // (px, py) of a width x height image, row 0 at the top - exactly what the
    // canvas vertex shader's interpolation produces.
    glm::vec3 rayDirection(int px, int py, int width, int height) const;

private:
    CameraPose pose_;
    float fovYDeg_ = 36.87f;  // 2*atan(1/3): the seed's canvas 3 units ahead, half-height 1
};

}  // namespace raylab
