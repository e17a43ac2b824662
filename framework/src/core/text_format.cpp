#include "text_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace raylab {

std::string significant(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

std::string fixedPoint(double v, int decimals) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string trimmedFixed(double v, int decimals) {
    std::string s = fixedPoint(v, decimals);
    if (s.find('.') == std::string::npos) return s;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

std::string shortestExactPortable(double v) {
    if (!std::isfinite(v) || v == 0.0) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%g", v);  // inf, -inf, nan, 0, -0 as to_chars writes them
        return buf;
    }
    // The fewest significant digits that read back as V.
    char sci[64];
    int digits = 1;
    for (; digits < 17; ++digits) {
        std::snprintf(sci, sizeof sci, "%.*e", digits - 1, v);
        if (std::strtod(sci, nullptr) == v) break;
    }
    std::snprintf(sci, sizeof sci, "%.*e", digits - 1, v);
    // sci is [-]d[.ddd]e(+|-)xx: its digits and exponent, written out in full.
    const std::string s = sci;
    const bool negative = s[0] == '-';
    const std::size_t e = s.find('e');
    std::string mantissa;
    for (std::size_t i = negative ? 1 : 0; i < e; ++i)
        if (s[i] != '.') mantissa += s[i];
    const int exponent = std::atoi(s.c_str() + e + 1);
    std::string fixed;
    if (exponent >= 0) {
        const std::size_t whole = std::size_t(exponent) + 1;
        if (mantissa.size() <= whole) {
            // A whole number: to_chars writes its exact digits (as %.0f does),
            // not the shortest ones padded with zeros.
            char exact[400];
            std::snprintf(exact, sizeof exact, "%.0f", std::fabs(v));
            fixed = exact;
        } else {
            fixed = mantissa.substr(0, whole) + "." + mantissa.substr(whole);
        }
    } else {
        fixed = "0." + std::string(std::size_t(-exponent - 1), '0') + mantissa;
    }
    if (negative) fixed = "-" + fixed;
    // The shorter of the two; fixed on a tie.
    return fixed.size() <= s.size() ? fixed : s;
}

std::string shortestExact(double v) {
#ifdef __EMSCRIPTEN__
    // emscripten's libc++ has no floating-point to_chars.
    return shortestExactPortable(v);
#else
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
#endif
}

std::string durationText(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
    char buf[64];
    if (seconds < 60) {
        std::snprintf(buf, sizeof buf, "%.1f s", seconds);
    } else if (seconds < 3600) {
        const long s = std::lround(seconds);
        std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
    } else {
        const long m = std::lround(seconds / 60);
        std::snprintf(buf, sizeof buf, "%ld h %02ld min", m / 60, m % 60);
    }
    return buf;
}

}  // namespace raylab
