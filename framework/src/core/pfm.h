#pragma once
// Portable Float Map (PFM) images: raw 32-bit floats, for the debug views
// (`raylab render --view depth --out d.pfm`) where 8-bit PNG would round the
// values away.
//
// The format: a text header "PF\n" (3 channels, RGB) or "Pf\n" (1 channel,
// grey), then "WIDTH HEIGHT\n", then the scale "-1.0\n" (a negative scale
// means little-endian floats; its size is 1), then WIDTH*HEIGHT pixels of
// 1 or 3 floats with the rows stored BOTTOM TO TOP. In memory (FloatImage)
// rows are top to bottom, like Image.
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct FloatImage {
    int width = 0;
    int height = 0;
    int channels = 1;           // 1 (Pf) or 3 (PF)
    std::vector<float> values;  // width * height * channels, top row first

    FloatImage() = default;
    FloatImage(int w, int h, int c)
        : width(w), height(h), channels(c),
          values(std::size_t(w) * std::size_t(h) * std::size_t(c), 0.0f) {}
    float* at(int x, int y) {
        return &values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) *
                       std::size_t(channels)];
    }
    const float* at(int x, int y) const {
        return &values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) *
                       std::size_t(channels)];
    }
};

// The bytes of a PFM file (little-endian, scale -1.0).
std::string encodePfm(const FloatImage& image);
// Parses a PFM file's bytes (either byte order). Throws Error naming WHAT.
FloatImage decodePfm(const std::string& bytes, const std::string& what = "PFM data");

// Atomic write (FILE.tmp-PID, then rename); throws Error.
void writePfmAtomic(const FloatImage& image, const std::filesystem::path& file);
FloatImage loadPfm(const std::filesystem::path& file);

}  // namespace raylab
