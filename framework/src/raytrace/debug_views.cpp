#include "debug_views.h"

#include "error.h"
#ifndef RAYLAB_STUDENT_BUILD
#include "reference_tracer.h"
#endif

namespace raylab {

namespace {

#ifndef RAYLAB_STUDENT_BUILD
int channelsOf(DebugView view) {
    return view == DebugView::Color || view == DebugView::Normal ? 3 : 1;
}
#endif

StageInfo withViewDefines(const StageInfo& stage, GpuView view) {
    StageInfo s = stage;
    for (const std::string& d : gpuViewDefines(view, stage.has("surface_at")))
        s.extraDefines.push_back(d);
    return s;
}

}  // namespace

GpuViewRenderer::GpuViewRenderer(GpuView view, const StageInfo& stage, StageSources sources,
                                 Scene scene, int width, int height, ShaderVariant variant)
    : view_(view), stage_(withViewDefines(stage, view)),
      renderer_(stage_, std::move(sources), std::move(scene), width, height, PixelFormat::Rgba32F,
                kViewFragmentEntry, std::move(variant)) {}

std::vector<float> GpuViewRenderer::readFloats() const {
    std::vector<float> rgba = renderer_.target().readFloats();
    const double scale = renderer_.frame().scale;
    if (view_ == GpuView::Depth && scale != 1.0)
        for (std::size_t i = 0; i < rgba.size(); i += 4) rgba[i] = float(double(rgba[i]) / scale);
    return rgba;
}

#ifndef RAYLAB_STUDENT_BUILD  // no reference tracer in a student repository
ViewData viewFromReference(DebugView view, const std::vector<ReferenceSample>& samples, int width,
                           int height) {
    ViewData d;
    d.view = view;
    d.values = FloatImage(width, height, channelsOf(view));
    const std::size_t n = std::size_t(width) * std::size_t(height);
    if (samples.size() != n) throw Error("reference tracer: wrong number of samples");
    d.hit.assign(n, 0);
    d.overflow.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const ReferenceSample& s = samples[i];
        float* out = &d.values.values[i * std::size_t(d.values.channels)];
        d.hit[i] = s.id >= 0;
        d.overflow[i] = s.stackOverflow;
        switch (view) {
        case DebugView::Color:
            for (int c = 0; c < 3; ++c) out[c] = float(s.color[c]);
            break;
        case DebugView::Depth: out[0] = s.id >= 0 ? float(s.depth) : 0.0f; break;
        case DebugView::Normal:
            for (int c = 0; c < 3; ++c) out[c] = s.id >= 0 ? float(s.normal[c]) : 0.0f;
            break;
        case DebugView::Id: out[0] = float(s.id); break;
        case DebugView::Bounces: out[0] = float(s.rays); break;
        case DebugView::Stack: out[0] = float(s.maxStack); break;
        }
    }
    return d;
}
#endif

}  // namespace raylab
