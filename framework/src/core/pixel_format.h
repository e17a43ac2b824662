#pragma once

namespace raylab {

// The pixels of a render target: 8-bit colour, or 32-bit floats where
// grading must see NaN and Inf (which 8-bit colour would hide).
enum class PixelFormat { Rgba8, Rgba32F };

}  // namespace raylab
