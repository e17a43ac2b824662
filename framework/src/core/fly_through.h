#pragma once
// The camera path of the headless demo: a slow turn around the vertical axis
// through the world's origin (where the demo scenes are centred), starting at
// the scene's own camera and always looking the same way relative to the
// scene, while the animation clock runs.
#include "camera.h"

namespace raylab {

struct FlyThrough {
    float degreesPerFrame = 4.0f;
    float secondsPerFrame = 0.1f;

    CameraPose poseAt(const CameraPose& start, int frame) const;
    float timeAt(float startTime, int frame) const {
        return startTime + secondsPerFrame * float(frame);
    }
};

}  // namespace raylab
