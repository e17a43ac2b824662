// Mesa's softpipe (label softpipe): the two softpipe bugs behind what the
// label leaves out or works around, each as the smallest program that shows
// it (docs/bench/README.md, "On Mesa's softpipe"). Under GALLIUM_DRIVER=
// softpipe each test pins the bug as measured with Mesa 22.3: a Mesa that
// fixes it fails here and says what can change. Under any other driver it
// expects what the GL specification says (ctest runs it on llvmpipe too:
// the control that the programs themselves are right).
#include "canvas.h"
#include "framebuffer.h"
#include "gl.h"
#include "shader_program.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <string>

using namespace raylab;
using raylab::test::assembledFrom;
using raylab::test::ensureGlContext;

namespace {

std::string renderer() {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return r ? r : "";
}

bool onSoftpipe() { return renderer() == "softpipe"; }

const char* kCanvasVertex = "layout(location = 0) in vec2 aCorner;\n"
                            "void main() { gl_Position = vec4(aCorner, 0.0, 1.0); }\n";

// Each pixel writes its own slot of a local array at a run-time index and
// reads two slots back: pixel 0 writes slot 1, pixel 1 slot 2. GLSL defines
// this for any index inside the array. trace.glsl's stack push (stage 04 on)
// and the BVH walk's (stage 08) have this form.
const char* kStoreAtRunTimeIndex =
    "out vec4 result;\n"
    "void main()\n"
    "{\n"
    "    int i = 1 + int(gl_FragCoord.x);  // pixel x writes slot x + 1\n"
    "    vec4 slots[4] = vec4[4](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));\n"
    "    slots[i] = vec4(1.0);\n"
    "    result = vec4(slots[1].x, slots[2].x, 0.0, 1.0);\n"
    "}\n";

}  // namespace

TEST(SoftpipeQuirks, AStoreAtARunTimeIndexTakesOnePixelsIndexForItsQuad) {
    ensureGlContext();
    ShaderProgram program(assembledFrom("canvas.vert", kCanvasVertex),
                          assembledFrom("store.frag", kStoreAtRunTimeIndex));
    Framebuffer target(2, 1, PixelFormat::Rgba32F);  // two pixels of one 2x2 quad
    Canvas canvas;
    target.bind();
    program.use();
    canvas.draw();
    const std::vector<float> px = target.readFloats();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const float pixel0Slot1 = px[0], pixel1Slot1 = px[4], pixel1Slot2 = px[5];
    EXPECT_EQ(pixel0Slot1, 1.0f) << renderer();
    if (onSoftpipe()) {
        // Pixel 1's write lands in slot 1, pixel 0's index: tgsi_exec's
        // store_dest takes the address register's first channel for all four.
        EXPECT_TRUE(pixel1Slot1 == 1.0f && pixel1Slot2 == 0.0f)
            << "softpipe now stores at each pixel's own index (pixel 1: slot 1 = " << pixel1Slot1
            << ", slot 2 = " << pixel1Slot2
            << "): stage 04's glass views and trace, stage 05's glass views and stage 08's "
               "views can join the label (tests/CMakeLists.txt, softpipe_check_*)";
    } else {
        EXPECT_EQ(pixel1Slot1, 0.0f) << renderer();
        EXPECT_EQ(pixel1Slot2, 1.0f) << renderer();
    }
}

namespace {

// A geometry shader that turns each point into one triangle; COUNTED draws
// four points with rasterisation discarded and returns GL_PRIMITIVES_GENERATED,
// with transform feedback active (into a buffer too small for all of it)
// or not.
GLuint64 primitivesGenerated(bool transformFeedback) {
    ShaderProgram program(
        assembledFrom("point.vert", "void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n"),
        assembledFrom("triangle.geom", "layout(points) in;\n"
                                       "layout(triangle_strip, max_vertices = 3) out;\n"
                                       "void main()\n"
                                       "{\n"
                                       "    for (int k = 0; k < 3; ++k) {\n"
                                       "        gl_Position = gl_in[0].gl_Position;\n"
                                       "        EmitVertex();\n"
                                       "    }\n"
                                       "}\n"),
        assembledFrom("white.frag", "out vec4 color;\nvoid main() { color = vec4(1.0); }\n"),
        {"gl_Position"});
    Framebuffer target(4, 4);
    target.bind();
    GLuint vao = 0, buffer = 0, query = 0;
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &buffer);
    glGenQueries(1, &query);
    glBindVertexArray(vao);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffer);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, 3 * 4 * sizeof(float), nullptr, GL_STREAM_READ);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    program.use();
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    if (transformFeedback) glBeginTransformFeedback(GL_TRIANGLES);
    glDrawArrays(GL_POINTS, 0, 4);
    if (transformFeedback) glEndTransformFeedback();
    glEndQuery(GL_PRIMITIVES_GENERATED);
    glDisable(GL_RASTERIZER_DISCARD);
    GLuint64 generated = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &generated);
    glDeleteQueries(1, &query);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glDeleteBuffers(1, &buffer);
    glDeleteVertexArrays(1, &vao);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return generated;
}

}  // namespace

TEST(SoftpipeQuirks, PrimitivesGeneratedCountsOnlyWhileTransformFeedbackIsActive) {
    ensureGlContext();
    GLint bits = 0;
    glGetQueryiv(GL_PRIMITIVES_GENERATED, GL_QUERY_COUNTER_BITS, &bits);
    EXPECT_GT(bits, 0) << renderer() << " says it has no primitives-generated counter";
    // With transform feedback active every driver counts, softpipe too: how
    // FurRenderer::countPrimitives counts fins and strands.
    EXPECT_EQ(primitivesGenerated(true), 4u) << renderer();
    const GLuint64 without = primitivesGenerated(false);
    if (onSoftpipe()) {
        EXPECT_EQ(without, 0u)
            << "softpipe now counts generated primitives without transform feedback too: "
               "the fin count need not run it (framework/src/fur/fur_renderer.cpp, "
               "countPrimitives)";
    } else {
        EXPECT_EQ(without, 4u) << renderer();
    }
}
