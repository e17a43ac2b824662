#include "image.h"

#include <algorithm>
#include <cmath>

namespace raylab {

Image imageFromFloats(const std::vector<float>& rgba, int width, int height, long* nonFinite) {
    Image image(width, height);
    long bad = 0;
    for (std::size_t p = 0; p < std::size_t(width) * std::size_t(height); ++p) {
        const float* in = &rgba[p * 4];
        std::uint8_t* out = &image.rgba[p * 4];
        bool finite = std::isfinite(in[0]) && std::isfinite(in[1]) && std::isfinite(in[2]);
        if (!finite) ++bad;
        for (int c = 0; c < 3; ++c)
            out[c] = finite ? std::uint8_t(std::lround(std::clamp(in[c], 0.0f, 1.0f) * 255.0f))
                            : std::uint8_t(c == 1 ? 0 : 255);
        out[3] = 255;
    }
    if (nonFinite) *nonFinite = bad;
    return image;
}

Image resampledBilinear(const Image& src, int w, int h) {
    if (src.width == w && src.height == h) return src;
    Image out(w, h);
    for (int y = 0; y < h; ++y) {
        float sy = std::clamp((float(y) + 0.5f) * float(src.height) / float(h) - 0.5f, 0.0f,
                              float(src.height - 1));
        int y0 = int(sy), y1 = std::min(y0 + 1, src.height - 1);
        float fy = sy - float(y0);
        for (int x = 0; x < w; ++x) {
            float sx = std::clamp((float(x) + 0.5f) * float(src.width) / float(w) - 0.5f, 0.0f,
                                  float(src.width - 1));
            int x0 = int(sx), x1 = std::min(x0 + 1, src.width - 1);
            float fx = sx - float(x0);
            for (int c = 0; c < 4; ++c) {
                float top =
                    float(src.pixel(x0, y0)[c]) * (1 - fx) + float(src.pixel(x1, y0)[c]) * fx;
                float bottom =
                    float(src.pixel(x0, y1)[c]) * (1 - fx) + float(src.pixel(x1, y1)[c]) * fx;
                out.pixel(x, y)[c] = std::uint8_t(std::lround(top * (1 - fy) + bottom * fy));
            }
        }
    }
    return out;
}

}  // namespace raylab
