// Headless OpenGL through EGL. Students need not read this file.
#include "error.h"
#include "gl_context.h"
#include "gl_loader.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

namespace raylab {

namespace {

class EglContext : public GlContext {
public:
    EglContext() {
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        EGLint major = 0, minor = 0;
        // Mesa's surfaceless platform needs neither a display nor a GPU.
        if (getPlatformDisplay)
            display_ =
                getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
            // Other drivers (e.g. NVIDIA's) offer a default display instead.
            display_ = eglGetDisplay(EGL_DEFAULT_DISPLAY);
            if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
                throw Error("EGL is not available (no surfaceless or default display)");
        }
        if (!eglBindAPI(EGL_OPENGL_API)) throw Error("EGL cannot bind the desktop OpenGL API");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        // No config and no surface: everything is drawn into framebuffer objects.
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT) {
            eglTerminate(display_);
            throw Error("EGL cannot create an OpenGL 3.3 core context");
        }
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            eglDestroyContext(display_, context_);
            eglTerminate(display_);
            throw Error("EGL cannot make a surfaceless context current");
        }
        loadGlWithGlew();
        requireGl33();
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    std::string backendName() const override { return "egl"; }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace raylab
