#pragma once
// The primary rays of a frame as the GPU computed them (`raylab rays`).
//
// File format (all little-endian):
//   8 bytes   magic "RLRAYS01"
//   uint32    width
//   uint32    height
//   then width * height records, row-major from the TOP row of the picture
//   (record y * width + x is pixel (x, y), y = 0 at the top), each 6 float32:
//   origin x, y, z (the eye, uEye), direction x, y, z (normalize(vsRay) as
//   the fragment shader computed it, unit length).
// Size: 16 + 24 * width * height bytes.
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

inline constexpr char kRayDumpMagic[9] = "RLRAYS01";

struct RayDump {
    int width = 0;
    int height = 0;
    std::vector<float> records;  // width * height * 6: origin xyz, direction xyz

    const float* origin(int x, int y) const {
        return &records[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 6];
    }
    const float* dir(int x, int y) const { return origin(x, y) + 3; }
};

std::string encodeRayDump(const RayDump& dump);
// Throws Error naming WHAT on a bad magic or size.
RayDump decodeRayDump(const std::string& bytes, const std::string& what = "ray dump");

void writeRayDumpAtomic(const RayDump& dump, const std::filesystem::path& file);
RayDump loadRayDump(const std::filesystem::path& file);

}  // namespace raylab
