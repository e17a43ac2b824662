// The camera maths: basis, pitch clamping, and the ray through a pixel centre.
#include "camera.h"

#include <glm/gtc/epsilon.hpp>
#include <gtest/gtest.h>

using raylab::Camera;
using raylab::CameraPose;

namespace {
void expectNear(glm::vec3 actual, glm::vec3 expected, const char* what) {
    EXPECT_TRUE(glm::all(glm::epsilonEqual(actual, expected, 1e-5f)))
        << what << ": expected (" << expected.x << ", " << expected.y << ", " << expected.z
        << "), actual (" << actual.x << ", " << actual.y << ", " << actual.z << ")";
}
}  // namespace

TEST(Camera, DefaultLooksDownNegativeZWithYUp) {
    Camera cam(CameraPose{}, 40.0f);
    expectNear(cam.forward(), {0, 0, -1}, "forward");
    expectNear(cam.right(), {1, 0, 0}, "right");
    expectNear(cam.up(), {0, 1, 0}, "up");
}

TEST(Camera, BasisIsOrthonormalForManyAngles) {
    for (float yaw = -360.0f; yaw <= 360.0f; yaw += 37.0f)
        for (float pitch = -89.0f; pitch <= 89.0f; pitch += 17.8f) {
            Camera cam(CameraPose{{1, 2, 3}, yaw, pitch}, 40.0f);
            glm::vec3 f = cam.forward(), r = cam.right(), u = cam.up();
            EXPECT_NEAR(glm::length(f), 1.0f, 1e-5f) << "yaw " << yaw << " pitch " << pitch;
            EXPECT_NEAR(glm::length(r), 1.0f, 1e-5f) << "yaw " << yaw << " pitch " << pitch;
            EXPECT_NEAR(glm::length(u), 1.0f, 1e-5f) << "yaw " << yaw << " pitch " << pitch;
            EXPECT_NEAR(glm::dot(f, r), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(f, u), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(r, u), 0.0f, 1e-5f);
            EXPECT_GT(u.y, 0.0f) << "the image's up must never point down (view flipped)";
        }
}

TEST(Camera, PitchIsClampedSoTheViewNeverFlips) {
    Camera cam(CameraPose{}, 40.0f);
    cam.turn(0.0f, 500.0f);
    EXPECT_FLOAT_EQ(cam.pose().pitchDeg, Camera::kMaxPitchDeg);
    EXPECT_GT(cam.up().y, 0.0f);
    EXPECT_FALSE(glm::any(glm::isnan(cam.right())))
        << "right must stay defined looking (almost) straight up";
    cam.turn(0.0f, -1000.0f);
    EXPECT_FLOAT_EQ(cam.pose().pitchDeg, -Camera::kMaxPitchDeg);
    Camera constructed(CameraPose{{0, 0, 0}, 0.0f, 120.0f}, 40.0f);
    EXPECT_FLOAT_EQ(constructed.pose().pitchDeg, Camera::kMaxPitchDeg);
}

TEST(Camera, FocalLengthGivesTheFieldOfView) {
    // The seed's canvas: 3 units ahead, half-height 1 -> fov = 2 atan(1/3).
    Camera seed(CameraPose{}, 2.0f * glm::degrees(std::atan(1.0f / 3.0f)));
    EXPECT_NEAR(seed.focalLength(), 3.0f, 1e-4f);
}

TEST(Camera, RayThroughCentrePixelIsTheViewDirection) {
    Camera cam(CameraPose{{0, 1, 5}, 30.0f, -10.0f}, 40.0f);
    glm::vec3 d =
        cam.rayDirection(50, 25, 101, 51);  // odd sizes: pixel (50, 25) is the exact centre
    expectNear(glm::normalize(d), cam.forward(), "centre ray");
}

TEST(Camera, RayThroughCornerPixelCentre) {
    Camera cam(CameraPose{}, 90.0f);  // focal length 1
    // 4x2 image, aspect 2: pixel (0, 0) is top left, its centre at NDC (-0.75, 0.5).
    expectNear(cam.rayDirection(0, 0, 4, 2), {2.0f * -0.75f, 0.5f, -1.0f}, "top-left ray");
    expectNear(cam.rayDirection(3, 1, 4, 2), {2.0f * 0.75f, -0.5f, -1.0f}, "bottom-right ray");
}

TEST(Camera, MoveFollowsForwardAndRight) {
    Camera cam(CameraPose{{0, 0, 0}, 90.0f, 0.0f}, 40.0f);  // looking down +x
    cam.move(2.0f, 1.0f);
    expectNear(glm::vec3(cam.pose().position), {2.0f, 0.0f, 1.0f}, "position");
}
