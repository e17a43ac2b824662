// The WebAssembly core writes numbers into baked scenes without
// std::to_chars (its libc++ lacks it for floating point): its replacement
// must write every number exactly as to_chars does, or the page's programs
// would differ from native ones.
#include "text_format.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace raylab {
namespace {

std::string viaToChars(double v) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

TEST(ShortestExact, PortableWritesWhatToCharsWrites) {
    const double fixed[] = {0.0,
                            -0.0,
                            1.0,
                            -1.0,
                            0.1,
                            0.001,
                            1e-4,
                            123456.0,
                            1e20,
                            1e21,
                            1e22,
                            1.5e-7,
                            100000.0,
                            1e15,
                            1e16,
                            1e17,
                            12345678901234567.0,
                            0.3,
                            2.0 / 3.0,
                            5e-324,
                            std::numeric_limits<double>::max(),
                            1.0 / 255.0,
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity()};
    for (double v : fixed) EXPECT_EQ(shortestExactPortable(v), viaToChars(v)) << v;
    // Random doubles of every size, and floats widened (what baked scenes hold).
    std::mt19937_64 rng(7);
    for (int i = 0; i < 200000; ++i) {
        std::uint64_t bits = rng();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) continue;
        const double f =
            double(float(std::ldexp(double(rng() % 2000000) - 1e6, int(rng() % 40) - 30)));
        ASSERT_EQ(shortestExactPortable(v), viaToChars(v)) << v;
        ASSERT_EQ(shortestExactPortable(f), viaToChars(f)) << f;
    }
}

TEST(ShortestExact, NotJustPrintfG) {
    // The control: %g would write these differently ("0.0001", "1.42855e+18").
    EXPECT_EQ(shortestExactPortable(1e-4), "1e-04");
    EXPECT_EQ(shortestExactPortable(1428547813435902208.0), "1428547813435902208");
    EXPECT_EQ(shortestExactPortable(0.001), "0.001");
}

}  // namespace
}  // namespace raylab
