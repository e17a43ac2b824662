#include "gl_loader.h"

#include "error.h"
#include "gl.h"

#include <cstdio>

namespace raylab {

namespace {

// Every GLEW-loaded function the framework calls. GL 1.1 functions (glClear,
// glDrawArrays, glReadPixels, ...) are linked symbols, not GLEW pointers.
// Adding a GL call to the framework? Add it here, or the OSMesa backend stops
// with "missing OpenGL function" (tests/backend_test covers this).
// clang-format off
#define RAYLAB_GLEW_FUNCTIONS(X) \
    X(ActiveTexture) X(AttachShader) X(BindBuffer) X(BindFramebuffer) X(BindVertexArray)           \
    X(BlitFramebuffer) X(BufferData) X(CheckFramebufferStatus) X(ClientWaitSync)                   \
    X(CompileShader) X(CreateProgram) X(CreateShader) X(DeleteBuffers) X(DeleteFramebuffers)       \
    X(DeleteProgram) X(DeleteShader) X(DeleteSync) X(DeleteVertexArrays) X(DetachShader)           \
    X(EnableVertexAttribArray) X(FenceSync) X(FramebufferTexture2D) X(GenBuffers)                  \
    X(GenFramebuffers) X(GenVertexArrays) X(GenerateMipmap) X(GetProgramInfoLog) X(GetProgramiv)   \
    X(GetShaderInfoLog) X(GetShaderiv) X(GetUniformLocation) X(LinkProgram) X(ShaderSource)        \
    X(Uniform1f) X(Uniform1i) X(Uniform2f) X(Uniform3f) X(Uniform3fv) X(Uniform4fv)                \
    X(Uniform1fv) X(Uniform1iv) X(UniformMatrix3fv) X(UniformMatrix4fv) X(UseProgram)              \
    X(VertexAttribPointer) X(TexImage3D) X(TexSubImage3D) X(TexBuffer)                            \
    X(GenRenderbuffers) X(BindRenderbuffer) X(RenderbufferStorage) X(FramebufferRenderbuffer)      \
    X(DeleteRenderbuffers) X(GenQueries) X(BeginQuery) X(EndQuery)                                \
    X(GetQueryObjectui64v) X(DeleteQueries) X(DrawBuffers) X(ClearBufferfv)                       \
    X(BufferSubData) X(BindBufferBase) X(GetUniformBlockIndex) X(UniformBlockBinding)             \
    X(GetIntegeri_v)
// Functions of later versions, used only where the context offers them
// (GL 4.3 storage buffers: sphere_blocks.cpp); loaded when present, never required.
#define RAYLAB_GLEW_OPTIONAL_FUNCTIONS(X) X(GetProgramResourceIndex) X(ShaderStorageBlockBinding)
// clang-format on

bool allLoaded(std::string* missing) {
#define RAYLAB_CHECK(name)                                                                         \
    if (!__glew##name) {                                                                           \
        *missing = "gl" #name;                                                                     \
        return false;                                                                              \
    }
    RAYLAB_GLEW_FUNCTIONS(RAYLAB_CHECK)
#undef RAYLAB_CHECK
    return true;
}

}  // namespace

void loadGlWithGlew() {
    glewExperimental = GL_TRUE;
    GLenum status = glewInit();
    std::string missing;
    if (!allLoaded(&missing)) {
        throw Error(std::string("cannot load OpenGL functions (glewInit: ") +
                    reinterpret_cast<const char*>(glewGetErrorString(status)) +
                    ", first missing: " + missing + ")");
    }
    // glewInit's probing may leave an error behind; start clean.
    while (glGetError() != GL_NO_ERROR) {}
}

void loadGlFrom(GetProcFn getProc) {
#define RAYLAB_LOAD(name)                                                                          \
    __glew##name = reinterpret_cast<decltype(__glew##name)>(getProc("gl" #name));
    RAYLAB_GLEW_FUNCTIONS(RAYLAB_LOAD)
    RAYLAB_GLEW_OPTIONAL_FUNCTIONS(RAYLAB_LOAD)
#undef RAYLAB_LOAD
    std::string missing;
    if (!allLoaded(&missing))
        throw Error("missing OpenGL function " + missing + " in this context");
}

void requireGl33() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 33)
        throw Error("OpenGL 3.3 is required, this context offers " + std::to_string(major) + "." +
                    std::to_string(minor));
}

std::string glDescription() {
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return "OpenGL " + str(GL_VERSION) + " on " + str(GL_RENDERER);
}

}  // namespace raylab
