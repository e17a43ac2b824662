#include "ray_dump.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace raylab {

namespace {

constexpr std::size_t kHeaderBytes = 16;

void putU32(std::string& out, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out[at + std::size_t(i)] = char((v >> (8 * i)) & 0xffu);
}

std::uint32_t getU32(const std::string& in, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
        v |= std::uint32_t(static_cast<unsigned char>(in[at + std::size_t(i)])) << (8 * i);
    return v;
}

std::uint32_t floatBits(float f) {
    std::uint32_t b = 0;
    std::memcpy(&b, &f, 4);
    return b;
}

float bitsFloat(std::uint32_t b) {
    float f = 0.0f;
    std::memcpy(&f, &b, 4);
    return f;
}

}  // namespace

std::string encodeRayDump(const RayDump& dump) {
    const std::size_t n = std::size_t(dump.width) * std::size_t(dump.height) * 6;
    if (dump.width <= 0 || dump.height <= 0 || dump.records.size() != n)
        throw Error("ray dump: the records do not match the size");
    std::string out(kHeaderBytes + n * 4, '\0');
    std::memcpy(out.data(), kRayDumpMagic, 8);
    putU32(out, 8, std::uint32_t(dump.width));
    putU32(out, 12, std::uint32_t(dump.height));
    for (std::size_t i = 0; i < n; ++i)
        putU32(out, kHeaderBytes + 4 * i, floatBits(dump.records[i]));
    return out;
}

RayDump decodeRayDump(const std::string& bytes, const std::string& what) {
    if (bytes.size() < kHeaderBytes || bytes.compare(0, 8, kRayDumpMagic) != 0)
        throw Error(what + ": not a ray dump (it must start with " + kRayDumpMagic + ")");
    RayDump dump;
    std::uint32_t w = getU32(bytes, 8), h = getU32(bytes, 12);
    if (w == 0 || h == 0 || w > 65536 || h > 65536) throw Error(what + ": bad size in the header");
    dump.width = int(w);
    dump.height = int(h);
    const std::size_t n = std::size_t(w) * std::size_t(h) * 6;
    if (bytes.size() != kHeaderBytes + n * 4)
        throw Error(what + ": " + std::to_string(bytes.size()) + " bytes, expected " +
                    std::to_string(kHeaderBytes + n * 4));
    dump.records.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        dump.records[i] = bitsFloat(getU32(bytes, kHeaderBytes + 4 * i));
    return dump;
}

void writeRayDumpAtomic(const RayDump& dump, const std::filesystem::path& file) {
    writeTextFileAtomic(file, encodeRayDump(dump));
}

RayDump loadRayDump(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read " + displayPath(file));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return decodeRayDump(bytes.str(), displayPath(file));
}

}  // namespace raylab
