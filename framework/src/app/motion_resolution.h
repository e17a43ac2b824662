#pragma once
// Fewer pixels while the camera moves. On a CPU renderer (llvmpipe) a full
// frame of the demo takes a few hundred milliseconds, so the view would lag
// far behind the keys and the mouse. While the camera moves the window
// therefore draws every frame at 1/d of its width and height (d^2 times
// fewer rays) and scales it up; once the camera has been still for a moment
// it draws the full frame again. d follows the measured frame time so that
// a moving frame takes about the target time, whatever the scene, stage or
// machine. Key R switches it off and on. (Students need not read this file.)
namespace raylab {

class MotionResolution {
public:
    static constexpr double kTargetMs = 50.0;       // 20 frames per second while moving
    static constexpr double kSettleSeconds = 0.25;  // still this long: full resolution again
    static constexpr int kMaxDivisor = 8;

    explicit MotionResolution(bool enabled = true) : enabled_(enabled) {}

    // Once per frame, before it is drawn: how long the previous frame took
    // (drawn at the divisor then in force) and whether the camera moved since.
    void update(double previousFrameMs, bool cameraMoved);

    // 1: full resolution; d: 1/d of the width and height.
    int divisor() const { return divisor_; }
    bool enabled() const { return enabled_; }
    void setEnabled(bool on);

private:
    bool enabled_;
    int divisor_ = 1;
    int previousDivisor_ = 1;   // the divisor the previous frame was drawn at
    double fullFrameMs_ = 0.0;  // the last full-resolution frame's time, 0 before one
    double stillSeconds_ = kSettleSeconds;
};

// A size divided by D, at least one pixel.
int reducedSize(int size, int divisor);

}  // namespace raylab
