// The trace build (core/trace_recording.h) without a GL context: every call
// of findClosest() is recorded with its function, file and line; the guided
// lab's path state is passed where the calling function keeps it; main() is
// renamed and wrapped; errors for a program it cannot record.
#include "error.h"
#include "trace_recording.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace raylab;
using raylab::test::assembledFrom;

namespace {

const char* kProgram =
    "struct Ray { vec3 origin; vec3 dir; };\n"
    "struct Hit { float t; int id; };\n"
    "struct PendingRay { Ray ray; vec3 weight; int depth; };\n"
    "layout(location = 0) out vec4 fragColor;\n"
    "int solve(vec4 a, out vec4 roots) { roots = a; return 0; }\n"
    "bool findClosest(Ray ray, out Hit hit)\n"
    "{\n"
    "    hit = Hit(1.0, 0); return true;\n"
    "}\n"
    "bool lightVisible(vec3 p) { Hit h; return !findClosest(Ray(p, vec3(0, 1, 0)), h); }\n"
    "vec3 trace(Ray primary)\n"
    "{\n"
    "    int stackSize = 0; PendingRay current = PendingRay(primary, vec3(1.0), current.depth); "
    "Hit hit;\n"
    "    if (findClosest(current.ray, hit)) return current.weight * (lightVisible(vec3(0.0)) ? 1.0 "
    ": 0.0);\n"
    "    return vec3(0.0);\n"
    "}\n"
    "void main()\n"
    "{\n"
    "    fragColor = vec4(trace(Ray(vec3(0.0), vec3(0.0, 0.0, -1.0))), 1.0);\n"
    "}\n";

std::string traceErrorOf(const std::string& text) {
    try {
        recordTrace(assembledFrom("m.frag", text));
    } catch (const Error& e) { return e.what(); }
    return "(no error)";
}

}  // namespace

TEST(TraceRecording, RecordsEveryCallWithItsSite) {
    const TraceRecording r = recordTrace(assembledFrom("m.frag", kProgram));
    ASSERT_EQ(r.sites.size(), 2u);
    EXPECT_EQ(r.sites[0].function, "lightVisible");
    EXPECT_EQ(r.sites[0].where.file, "m.frag");
    EXPECT_EQ(r.sites[0].where.line, 10);
    EXPECT_EQ(r.sites[1].function, "trace");
    EXPECT_EQ(r.sites[1].where.line, 14);
    const std::string& t = r.fragment.text;
    // The guided lab's path state where trace() keeps it; none elsewhere.
    EXPECT_NE(t.find("raylab_traceFindClosest(current.ray, hit, 1, current.weight, "
                     "float(stackSize), float(current.depth))"),
              std::string::npos)
        << t;
    EXPECT_NE(
        t.find("raylab_traceFindClosest(Ray(p, vec3(0, 1, 0)), h, 0, vec3(-1.0), -1.0, -1.0)"),
        std::string::npos);
    // main() renamed and wrapped; the colour output is fragColor, not the
    // `out vec4` parameter of solve().
    EXPECT_NE(t.find("void raylab_stageMain()"), std::string::npos);
    EXPECT_NE(t.find("fragColor = vec4(fragColor.rgb, float(raylab_traceCalls));"),
              std::string::npos);
    EXPECT_EQ(t.find("roots = vec4(roots.rgb"), std::string::npos);
    // The recorder follows findClosest's definition; the student's lines keep their origin.
    EXPECT_LT(t.find("bool findClosest("), t.find("bool raylab_traceFindClosest("));
    std::istringstream in(t);
    int line = 0, found = 0;
    for (std::string l; std::getline(in, l);) {
        ++line;
        if (l.rfind("vec3 trace(Ray primary)", 0) != 0) continue;
        ++found;
        EXPECT_EQ(r.fragment.where(line).file, "m.frag");
        EXPECT_EQ(r.fragment.where(line).line, 11);
    }
    EXPECT_EQ(found, 1);
}

TEST(TraceRecording, NamesWhatItCannotRecord) {
    EXPECT_EQ(traceErrorOf("void main() {}\n"),
              "the program defines no findClosest() whose calls to record");
    EXPECT_EQ(
        traceErrorOf("struct Ray { vec3 o; }; struct Hit { float t; };\n"
                     "bool findClosest(Ray r, out Hit h) { return false; }\nvoid main() {}\n"),
        "the program calls findClosest() nowhere: no path to record");
}
