#include "gpu_trace.h"

#include "error.h"
#include "gl.h"
#include "stage_renderer.h"
#include "trace_recording.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

namespace {

// The most rays a report lists (a path of depth 8 with shadow rays stays far below).
constexpr int kMaxRecords = 1024;
constexpr int kAttachments = 4;

// A one-row target of COLUMNS pixels, four RGBA32F attachments.
class RecordTarget {
public:
    explicit RecordTarget(int columns) {
        glGenFramebuffers(1, &fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glGenTextures(kAttachments, textures_);
        GLenum buffers[kAttachments];
        for (int a = 0; a < kAttachments; ++a) {
            glBindTexture(GL_TEXTURE_2D, textures_[a]);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, columns, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + a), GL_TEXTURE_2D,
                                   textures_[a], 0);
            buffers[a] = GLenum(GL_COLOR_ATTACHMENT0 + a);
        }
        glDrawBuffers(kAttachments, buffers);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw Error("this GL cannot draw into four float targets (framebuffer status " +
                        std::to_string(status) + ")");
    }
    ~RecordTarget() {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteTextures(kAttachments, textures_);
    }
    RecordTarget(const RecordTarget&) = delete;
    RecordTarget& operator=(const RecordTarget&) = delete;

    GLuint id() const { return fbo_; }
    // Attachment A's first COLUMNS pixels, RGBA floats.
    std::vector<float> read(int a, int columns) const {
        std::vector<float> out(std::size_t(columns) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + a));
        glReadPixels(0, 0, columns, 1, GL_RGBA, GL_FLOAT, out.data());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return out;
    }

private:
    GLuint fbo_ = 0;
    GLuint textures_[kAttachments] = {};
};

}  // namespace

std::string traceShaderPath(const StageInfo& stage, const StageSources& sources, const Scene& scene,
                            const Camera& camera, float timeSeconds, const RenderSettings& settings,
                            int width, int height, int x, int y) {
    StageRenderer renderer(stage, sources, scene, width, height);
    std::vector<TraceCallSite> sites;
    renderer.setFragmentRewrite([&](const ShaderSource& fragment) {
        TraceRecording r = recordTrace(fragment);
        sites = std::move(r.sites);
        return r.fragment;
    });
    RecordTarget target(kMaxRecords + 1);
    // Record K lands on column K: the pixel's row counted from the bottom.
    const int row = height - 1 - y;
    glEnable(GL_SCISSOR_TEST);
    auto draw = [&](int k) {
        glScissor(k, 0, 1, 1);
        renderer.renderAt(target.id(), k - x, -row, k, camera, timeSeconds, settings);
    };
    draw(0);
    const std::vector<float> summary = target.read(0, 1);
    const int calls = std::clamp(int(std::lround(summary[3])), 0, kMaxRecords);
    for (int k = 1; k <= calls; ++k) draw(k);
    glDisable(GL_SCISSOR_TEST);
    std::vector<std::vector<float>> columns;
    for (int a = 0; a < kAttachments; ++a) columns.push_back(target.read(a, calls + 1));
    std::vector<float> records(std::size_t(calls) * 16);
    for (int k = 0; k < calls; ++k)
        for (int a = 0; a < kAttachments; ++a)
            std::copy_n(columns[std::size_t(a)].begin() + 4 * (k + 1), 4,
                        records.begin() + 16 * k + 4 * a);
    return formatTracedPath(sites, summary, records, renderer.frame().scale,
                            renderer.frame().offset);
}

}  // namespace raylab
