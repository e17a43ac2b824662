#pragma once
// What every track's renderer does the same way: it draws each frame into
// an off-screen framebuffer, which the window copies to the screen and the
// headless commands read back.
#include "framebuffer.h"
#include "track_renderer.h"

#include <memory>

namespace raylab {

class TargetRenderer : public TrackRenderer {
public:
    Image read() const override { return target_->read(); }
    std::vector<float> readFloats() const override { return target_->readFloats(); }
    long todoPixels() const override { return target_->countTodoMarks(); }
    int width() const override { return target_->width(); }
    int height() const override { return target_->height(); }
    void blitToScreen(int screenWidth, int screenHeight) const override {
        target_->blitToScreen(screenWidth, screenHeight);
    }
    void resize(int width, int height, PixelFormat format = PixelFormat::Rgba8) override {
        target_ = std::make_unique<Framebuffer>(width, height, format);
    }
    const Framebuffer& target() const { return *target_; }

protected:
    TargetRenderer(int width, int height, PixelFormat format)
        : target_(std::make_unique<Framebuffer>(width, height, format)) {}

    std::unique_ptr<Framebuffer> target_;
};

}  // namespace raylab
