// The rewrite of a geometry shader into a vertex shader (the page's
// geometry shaders, core/geometry_emulation.h), without a GL context: what
// it reads from the layouts, how it rewrites the calls, and the errors it
// gives for what it cannot run, each naming the student's file and line.
// (tests/fur/geometry_emulation_draw_test.cpp draws it against real
// geometry shaders.)
#include "error.h"
#include "geometry_emulation.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace raylab;
using raylab::test::assembledFrom;

namespace {

const ShaderSource kVertex =
    assembledFrom("v.vert", "layout(location = 0) in vec3 aPosition;\n"
                            "out vec3 vPos;\n"
                            "flat out int vFlag;\n"
                            "void main() { vPos = aPosition; vFlag = 1; }\n");

std::string errorOf(const std::string& geometry) {
    try {
        emulateGeometryShader(kVertex, assembledFrom("g.geom", geometry));
    } catch (const Error& e) { return e.what(); }
    return "(no error)";
}

const char* kFins =
    "layout(lines_adjacency) in;\n"
    "layout(triangle_strip, max_vertices = 4) out;\n"
    "in vec3 vPos[];\n"
    "flat in int vFlag[];\n"
    "out vec2 gUv;\n"
    "void corner(vec3 p) { gl_Position = vec4(p, 1.0); gUv = p.xy; EmitVertex(); }\n"
    "int twice() { EmitVertex(); return 2; }\n"
    "void main()\n"
    "{\n"
    "    corner(vPos[1]); corner(vPos[2]);\n"
    "    EndPrimitive();\n"
    "}\n";

}  // namespace

TEST(GeometryEmulation, ReadsTheLayoutsAndTheVertexShadersOutputs) {
    const EmulatedGeometry e = emulateGeometryShader(kVertex, assembledFrom("g.geom", kFins));
    EXPECT_EQ(e.inputName, "lines_adjacency");
    EXPECT_EQ(e.corners, 4);
    EXPECT_EQ(e.output, EmulatedOutput::Triangles);
    EXPECT_EQ(e.maxVertices, 4);
    EXPECT_EQ(e.slots, 2);  // triangles 0-1-2 and 1-2-3 of a strip of 4
    EXPECT_EQ(e.verticesPerSlot, 3);
    EXPECT_EQ(e.captured, (std::vector<std::string>{"vPos", "vFlag"}));
    EXPECT_EQ(e.recordWords, 4);
    EXPECT_EQ(e.attributes, 4);  // 4 corners x 4 words
    // An emission: its strip word, gl_Position and gUv, 7 words in 2 texels;
    // one run of the body keeps all 4 (at most 16 texels a run).
    EXPECT_EQ(e.emissionTexels, 2);
    EXPECT_EQ(e.emissionsPerRun, 4);
    EXPECT_EQ(e.runs, 1);
    EXPECT_EQ(e.emitted.size(), 8u);
}

TEST(GeometryEmulation, RunsTheBodyOnceForAsManyEmissionsAsTransformFeedbackKeeps) {
    // 5 words an emission (strip, gl_Position): 2 texels, 8 a run; 20
    // emissions take 3 runs.
    const EmulatedGeometry e = emulateGeometryShader(
        kVertex,
        assembledFrom("g.geom", "layout(points) in;\n"
                                "layout(line_strip, max_vertices = 20) out;\n"
                                "void main() { gl_Position = vec4(0.0); EmitVertex(); }\n"));
    EXPECT_EQ(e.emissionTexels, 2);
    EXPECT_EQ(e.emissionsPerRun, 8);
    EXPECT_EQ(e.runs, 3);
    EXPECT_EQ(e.emissionsPerPrimitive(), 24);
    EXPECT_EQ(emissionTextureSize(e, 1000).rows, 47);  // 48000 texels
    EXPECT_EQ(emissionTextureSize(e, 1000).layers, 1);
    EXPECT_EQ(emissionTextureSize(e, 100000).rows, 1024);
    EXPECT_EQ(emissionTextureSize(e, 100000).layers, 5);  // 4.8 M texels
}

TEST(GeometryEmulation, TheDrawDeclaresTheOutputsAsWritten) {
    const EmulatedGeometry e = emulateGeometryShader(kVertex, assembledFrom("g.geom", kFins));
    const std::string& t = e.draw.text;
    EXPECT_NE(t.find("\nout vec2 gUv;\n"), std::string::npos) << t;
    EXPECT_NE(t.find("flat out int raylab_kept;"), std::string::npos) << t;
    // Its line names the student's: a mismatch with the fragment shader is theirs.
    std::istringstream in(t);
    int line = 0, found = 0;
    for (std::string l; std::getline(in, l);)
        if (++line, l == "out vec2 gUv;") {
            found = line;
            EXPECT_EQ(e.draw.where(line).file, "g.geom");
            EXPECT_EQ(e.draw.where(line).line, 5);
        }
    EXPECT_GT(found, 0);
    // In the expand it is a plain variable the body writes.
    EXPECT_NE(e.expand.text.find("vec2 gUv;"), std::string::npos);
    EXPECT_EQ(e.expand.text.find("out vec2 gUv"), std::string::npos);
}

TEST(GeometryEmulation, RewritesTheCallsAndKeepsEveryLine) {
    const EmulatedGeometry e = emulateGeometryShader(kVertex, assembledFrom("g.geom", kFins));
    const std::string& t = e.expand.text;
    // In a void function the body stops once its emissions are kept; in
    // another one the call stays a call.
    EXPECT_NE(t.find("{ if (raylab_emitVertex()) return; }"), std::string::npos) << t;
    EXPECT_NE(t.find("int twice() { raylab_emitVertex(); return 2; }"), std::string::npos) << t;
    EXPECT_NE(t.find("raylab_endPrimitive();"), std::string::npos);
    EXPECT_NE(t.find("void raylab_geometryMain()"), std::string::npos);
    EXPECT_NE(t.find("vec3 vPos[RAYLAB_CORNERS];"), std::string::npos);
    // Every line of g.geom is still there, at its own origin.
    std::istringstream in(t);
    int line = 0, fromGeom = 0;
    for (std::string l; std::getline(in, l);) {
        const SourceLine w = e.expand.where(++line);
        if (w.file != "g.geom") continue;
        ++fromGeom;
        if (w.line == 8) { EXPECT_EQ(l, "void raylab_geometryMain()"); }
    }
    EXPECT_EQ(fromGeom, 12);
}

TEST(GeometryEmulation, ReadsMaxVerticesThroughMacrosAndSkipsInactiveCode) {
    const EmulatedGeometry e = emulateGeometryShader(
        kVertex,
        assembledFrom("g.geom",
                      "#define SEGMENTS 7\n"
                      "#define MAX_V (SEGMENTS)\n"
                      "layout(triangles) in;\n"
                      "layout(line_strip, max_vertices = MAX_V) out;\n"
                      "in vec3 vPos[];\n"
                      "#ifdef NOT_DEFINED\n"
                      "out mat3 gNever;\n"
                      "#endif\n"
                      "void main() { gl_Position = vec4(vPos[0], 1.0); EmitVertex(); }\n"));
    EXPECT_EQ(e.maxVertices, 7);
    EXPECT_EQ(e.output, EmulatedOutput::Lines);
    EXPECT_EQ(e.slots, 6);
    EXPECT_EQ(e.verticesPerPrimitive(), 12);
}

TEST(GeometryEmulation, NamesTheFileAndLineOfWhatItCannotRun) {
    const std::string head = "layout(triangles) in;\nlayout(points, max_vertices = 1) out;\n";
    EXPECT_EQ(errorOf(head + "in vec3 vNormal[];\nvoid main() {}\n"),
              "g.geom:3: the input vNormal is not an output of the vertex shader");
    EXPECT_EQ(errorOf(head + "flat in float vFlag[];\nvoid main() {}\n"),
              "g.geom:3: the input vFlag is float, the vertex shader's output int");
    EXPECT_EQ(errorOf(head + "in VS { vec3 p; } vs[];\nvoid main() {}\n"),
              "g.geom:3: an interface block (VS { ... }) cannot be passed between the page's "
              "emulated shader stages; declare its members one by one");
    EXPECT_EQ(errorOf(head + "void main()\n{\n    int i = gl_InvocationID;\n}\n"),
              "g.geom:5: gl_InvocationID is not available where geometry shaders are emulated "
              "(the page: WebGL 2 has none); raylab run and check run it natively");
    EXPECT_EQ(errorOf(head + "out mat3 gBasis;\nvoid main() {}\n"),
              "g.geom:3: the output gBasis (mat3) cannot be emulated: use float, int or uint "
              "scalars and vectors");
    EXPECT_EQ(errorOf("layout(triangles) in;\nlayout(points, max_vertices = N) out;\n"),
              "g.geom:2: max_vertices = N is not a whole number the page can read");
    EXPECT_EQ(errorOf("void main() {}\n"),
              "g.geom: the geometry shader declares no input primitive (layout(triangles) in;)");
}
