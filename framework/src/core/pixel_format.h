#pragma once

namespace raylab {

// The pixels of a render target: 8-bit colour, or 32-bit floats where
// grading must see NaN and Inf (which 8-bit colour would hide). The checks'
// targets also keep the TODO marks (gl/framebuffer.h): which pixels reached
// a stub; other targets leave them out, so that the window, `render` and
// `bench` run the program students run.
enum class PixelFormat { Rgba8, Rgba32F, Rgba32FWithTodoMarks };

}  // namespace raylab
