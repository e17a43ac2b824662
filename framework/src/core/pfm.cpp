#include "pfm.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace raylab {

namespace {

bool hostIsLittleEndian() {
    const std::uint32_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

std::uint32_t byteSwap(std::uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

}  // namespace

std::string encodePfm(const FloatImage& image) {
    if (image.channels != 1 && image.channels != 3)
        throw Error("a PFM image has 1 or 3 channels, not " + std::to_string(image.channels));
    if (image.values.size() !=
        std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
        throw Error("PFM image: the values do not match the size");
    std::string out = std::string(image.channels == 3 ? "PF" : "Pf") + "\n" +
                      std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    const std::size_t header = out.size();
    const std::size_t row = std::size_t(image.width) * std::size_t(image.channels);
    out.resize(header + row * std::size_t(image.height) * sizeof(float));
    const bool swap = !hostIsLittleEndian();
    char* p = out.data() + header;
    for (int y = image.height - 1; y >= 0; --y) {  // bottom row first
        const float* src = &image.values[std::size_t(y) * row];
        for (std::size_t i = 0; i < row; ++i, p += 4) {
            std::uint32_t bits = 0;
            std::memcpy(&bits, &src[i], 4);
            if (swap) bits = byteSwap(bits);
            std::memcpy(p, &bits, 4);
        }
    }
    return out;
}

FloatImage decodePfm(const std::string& bytes, const std::string& what) {
    // The header: three whitespace-separated tokens after the magic, the
    // last one followed by exactly one whitespace character.
    std::size_t pos = 0;
    auto token = [&]() {
        while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
        std::size_t start = pos;
        while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
        return bytes.substr(start, pos - start);
    };
    std::string magic = token();
    if (magic != "PF" && magic != "Pf")
        throw Error(what + ": not a PFM file (it must start with PF or Pf)");
    int channels = magic == "PF" ? 3 : 1;
    int width = 0, height = 0;
    double scale = 0.0;
    try {
        width = std::stoi(token());
        height = std::stoi(token());
        scale = std::stod(token());
    } catch (const std::exception&) { throw Error(what + ": bad PFM header"); }
    if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || scale == 0.0)
        throw Error(what + ": bad PFM header");
    ++pos;  // the single whitespace after the scale
    const std::size_t count = std::size_t(width) * std::size_t(height) * std::size_t(channels);
    if (bytes.size() < pos || bytes.size() - pos != count * sizeof(float))
        throw Error(what + ": PFM data is " +
                    std::to_string(bytes.size() < pos ? 0 : bytes.size() - pos) +
                    " bytes, expected " + std::to_string(count * sizeof(float)));
    const bool fileLittle = scale < 0.0;
    const bool swap = fileLittle != hostIsLittleEndian();
    FloatImage image(width, height, channels);
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    const char* p = bytes.data() + pos;
    for (int y = height - 1; y >= 0; --y) {
        float* dst = &image.values[std::size_t(y) * row];
        for (std::size_t i = 0; i < row; ++i, p += 4) {
            std::uint32_t bits = 0;
            std::memcpy(&bits, p, 4);
            if (swap) bits = byteSwap(bits);
            std::memcpy(&dst[i], &bits, 4);
        }
    }
    return image;
}

void writePfmAtomic(const FloatImage& image, const std::filesystem::path& file) {
    writeTextFileAtomic(file, encodePfm(image));
}

FloatImage loadPfm(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read " + displayPath(file));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return decodePfm(bytes.str(), displayPath(file));
}

}  // namespace raylab
