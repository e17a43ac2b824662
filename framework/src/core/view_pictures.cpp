#include "view_pictures.h"

#include "error.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace raylab {

namespace {

struct ViewName {
    DebugView view;
    const char* name;
};
constexpr ViewName kViews[] = {{DebugView::Color, "color"},     {DebugView::Depth, "depth"},
                               {DebugView::Normal, "normal"},   {DebugView::Id, "id"},
                               {DebugView::Bounces, "bounces"}, {DebugView::Stack, "stack"}};

int channelsOf(DebugView view) {
    return view == DebugView::Color || view == DebugView::Normal ? 3 : 1;
}

std::string number(double v) { return significant(v, 4); }

std::uint8_t toByte(double v) { return std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

void setPixel(Image& image, std::size_t i, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    image.rgba[4 * i] = r;
    image.rgba[4 * i + 1] = g;
    image.rgba[4 * i + 2] = b;
    image.rgba[4 * i + 3] = 255;
}

// Blue .. cyan .. green .. yellow: far from the overflow red at every point.
void ramp(double s, std::uint8_t rgb[3]) {
    static const double stops[4][3] = {{40, 50, 170}, {0, 170, 200}, {60, 200, 60}, {250, 230, 40}};
    s = std::clamp(s, 0.0, 1.0) * 3.0;
    int i = std::min(2, int(s));
    double f = s - i;
    for (int c = 0; c < 3; ++c)
        rgb[c] = std::uint8_t(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
}

}  // namespace

DebugView parseDebugView(const std::string& name) {
    for (const ViewName& v : kViews)
        if (name == v.name) return v.view;
    throw Error("unknown view '" + name + "' (views: color, depth, normal, id, bounces, stack)");
}

const char* debugViewName(DebugView view) {
    for (const ViewName& v : kViews)
        if (v.view == view) return v.name;
    return "?";
}

bool viewNeedsReference(DebugView view) {
    return view == DebugView::Bounces || view == DebugView::Stack;
}

std::vector<std::string> gpuViewDefines(GpuView view, bool surfaceAt) {
    std::vector<std::string> out = {"RAYLAB_VIEW " + std::to_string(int(view))};
    // surfaceAt() (the outward normal of any kind of object) exists in the
    // stages whose stage.json says "surface_at".
    if (surfaceAt) out.push_back("RAYLAB_VIEW_SURFACE_AT");
    return out;
}

ViewData viewFromGpu(DebugView view, const std::vector<float>& rgba, int width, int height) {
    if (viewNeedsReference(view))
        throw Error(std::string("the ") + debugViewName(view) + " view needs --reference");
    ViewData d;
    d.view = view;
    d.values = FloatImage(width, height, channelsOf(view));
    const std::size_t n = std::size_t(width) * std::size_t(height);
    d.hit.assign(n, 0);
    d.overflow.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = &rgba[4 * i];
        float* out = &d.values.values[i * std::size_t(d.values.channels)];
        d.hit[i] = view == DebugView::Color || p[3] > 0.5f;
        for (int c = 0; c < d.values.channels; ++c) out[c] = p[c];
    }
    return d;
}

void idColor(int id, std::uint8_t rgb[3]) {
    std::uint32_t h = std::uint32_t(id) * 2654435761u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    double hue = double(h % 3600u) / 600.0;  // 0..6
    double sat = 0.55 + 0.35 * double((h >> 12) % 100u) / 100.0;
    double val = 0.75 + 0.25 * double((h >> 20) % 100u) / 100.0;
    int sector = int(hue) % 6;
    double f = hue - std::floor(hue);
    double p = val * (1 - sat), q = val * (1 - sat * f), t = val * (1 - sat * (1 - f));
    double r, g, b;
    switch (sector) {
    case 0: r = val, g = t, b = p; break;
    case 1: r = q, g = val, b = p; break;
    case 2: r = p, g = val, b = t; break;
    case 3: r = p, g = q, b = val; break;
    case 4: r = t, g = p, b = val; break;
    default: r = val, g = p, b = q; break;
    }
    rgb[0] = toByte(r);
    rgb[1] = toByte(g);
    rgb[2] = toByte(b);
}

Image viewToPng(const ViewData& d, std::string* mapping) {
    const int w = d.values.width, h = d.values.height;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    Image image(w, h);
    const std::vector<float>& v = d.values.values;
    std::string what;
    switch (d.view) {
    case DebugView::Color: {
        long nonFinite = 0;
        std::vector<float> rgba(4 * n, 1.0f);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) rgba[4 * i + std::size_t(c)] = v[3 * i + std::size_t(c)];
        image = imageFromFloats(rgba, w, h, &nonFinite);
        what = "colour clamped to 0..1";
        if (nonFinite > 0) what += ", " + std::to_string(nonFinite) + " NaN/Inf pixels magenta";
        break;
    }
    case DebugView::Depth: {
        float lo = INFINITY, hi = -INFINITY;
        for (std::size_t i = 0; i < n; ++i)
            if (d.hit[i] && std::isfinite(v[i])) lo = std::min(lo, v[i]), hi = std::max(hi, v[i]);
        // Near white (255) .. far grey (64); misses black.
        for (std::size_t i = 0; i < n; ++i) {
            if (!d.hit[i] || !std::isfinite(v[i])) continue;
            double s = hi > lo ? double(v[i] - lo) / double(hi - lo) : 0.0;
            auto g = std::uint8_t(std::lround(255.0 - s * (255.0 - 64.0)));
            setPixel(image, i, g, g, g);
        }
        for (std::size_t i = 0; i < n; ++i)
            if (!d.hit[i]) setPixel(image, i, 0, 0, 0);
        what = lo <= hi ? "depth " + number(lo) + ".." + number(hi) +
                              " mapped to white..grey, misses black"
                        : "depth: nothing hit, all black";
        break;
    }
    case DebugView::Normal:
        for (std::size_t i = 0; i < n; ++i) {
            if (!d.hit[i]) setPixel(image, i, 0, 0, 0);
            else
                setPixel(image, i, toByte(0.5 + 0.5 * v[3 * i]), toByte(0.5 + 0.5 * v[3 * i + 1]),
                         toByte(0.5 + 0.5 * v[3 * i + 2]));
        }
        what = "normal -1..1 mapped to 0.5 + 0.5 n (x red, y green, z blue), misses black";
        break;
    case DebugView::Id: {
        std::set<int> ids;
        for (std::size_t i = 0; i < n; ++i) {
            if (!d.hit[i]) {
                setPixel(image, i, 0, 0, 0);
                continue;
            }
            int id = int(std::lround(v[i]));
            ids.insert(id);
            std::uint8_t rgb[3];
            idColor(id, rgb);
            setPixel(image, i, rgb[0], rgb[1], rgb[2]);
        }
        what = "id: " + std::to_string(ids.size()) + " object" + (ids.size() == 1 ? "" : "s");
        if (!ids.empty())
            what += " (ids " + std::to_string(*ids.begin()) + ".." + std::to_string(*ids.rbegin()) +
                    ")";
        what += ", one colour each, misses black";
        break;
    }
    case DebugView::Bounces:
    case DebugView::Stack: {
        float lo = INFINITY, hi = -INFINITY;
        long overflows = 0;
        for (std::size_t i = 0; i < n; ++i) lo = std::min(lo, v[i]), hi = std::max(hi, v[i]);
        for (std::size_t i = 0; i < n; ++i) {
            std::uint8_t rgb[3];
            ramp(hi > lo ? double(v[i] - lo) / double(hi - lo) : 0.0, rgb);
            if (d.overflow[i]) rgb[0] = 255, rgb[1] = 0, rgb[2] = 0, ++overflows;
            setPixel(image, i, rgb[0], rgb[1], rgb[2]);
        }
        what = std::string(d.view == DebugView::Bounces ? "rays per pixel " : "stack depth ") +
               number(lo) + ".." + number(hi) + " mapped to blue..yellow, " +
               std::to_string(overflows) + " stack-overflow pixel" + (overflows == 1 ? "" : "s") +
               " red";
        break;
    }
    }
    if (mapping) *mapping = what;
    return image;
}

std::string pfmDescription(const ViewData& d) {
    switch (d.view) {
    case DebugView::Color: return "linear colour, unclamped";
    case DebugView::Depth: return "hit distance t, 0 for misses";
    case DebugView::Normal: return "unit outward normal xyz, 0 for misses";
    case DebugView::Id: return "object id kind*1048576+index, -1 for misses";
    case DebugView::Bounces: return "rays per pixel";
    case DebugView::Stack: return "most rays waiting on the stack";
    }
    return "";
}

}  // namespace raylab
