#pragma once
// An 8-bit RGBA image with rows stored top to bottom, and PNG I/O through
// SDL2_image (png_file.cpp). Writes are atomic: a failed or interrupted write never leaves a
// partial file under the requested name.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace raylab {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {}
    const std::uint8_t* pixel(int x, int y) const {
        return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    }
    std::uint8_t* pixel(int x, int y) {
        return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    }
};

Image loadPng(const std::filesystem::path& file);

// RGBA floats (top row first) to 8 bits: clamp to [0, 1], scale, round. NaN
// or Inf pixels become magenta and are counted in *NONFINITE. Checks and
// grading read frames this way, so that a NaN is seen, not turned black.
Image imageFromFloats(const std::vector<float>& rgba, int width, int height, long* nonFinite);

// SRC scaled to W x H bilinearly, pixel centres onto pixel centres, clamped
// at the borders, rounded to 8 bits. (Texture layers of different sizes are
// brought to one size this way; the reference tracer must get the same bytes.)
Image resampledBilinear(const Image& src, int w, int h);

// Writes FILE.tmp-PID next to FILE, then renames it over FILE.
void writePngAtomic(const Image& image, const std::filesystem::path& file);

}  // namespace raylab
