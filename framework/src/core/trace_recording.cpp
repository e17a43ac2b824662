#include "trace_recording.h"

#include "error.h"
#include "glsl_scan.h"

#include <algorithm>

namespace raylab {

namespace {

struct Edit {
    std::size_t pos = 0, length = 0;
    std::string text;
};

bool hasSequence(const std::vector<GlslToken>& t, std::size_t from, std::size_t to,
                 std::initializer_list<const char*> words) {
    for (std::size_t i = from; i + words.size() <= to; ++i) {
        std::size_t k = 0;
        for (const char* w : words) {
            if (t[i + k].text != w) break;
            ++k;
        }
        if (k == words.size()) return true;
    }
    return false;
}

// The recorder, after findClosest's definition (it needs Ray, Hit and findClosest).
const char* const kRecorder[] = {
    "uniform int uTraceRecord;  // the findClosest call to keep (1, 2, ...); 0: the summary",
    "int raylab_traceCalls = 0;",
    "vec4 raylab_trace0 = vec4(0.0), raylab_trace1 = vec4(0.0), raylab_trace2 = vec4(0.0), "
    "raylab_trace3 = vec4(0.0);",
    "bool raylab_traceFindClosest(Ray ray, out Hit hit, int site, vec3 weight, float stack, "
    "float depth)",
    "{",
    "    bool found = findClosest(ray, hit);",
    "    raylab_traceCalls += 1;",
    "    if (raylab_traceCalls == uTraceRecord) {",
    "        raylab_trace0 = vec4(ray.origin, float(site));",
    "        raylab_trace1 = vec4(ray.dir, found ? float(hit.id) : -1.0);",
    "        raylab_trace2 = vec4(found ? hit.t : -1.0, weight);",
    "        raylab_trace3 = vec4(stack, depth, found ? 1.0 : 0.0, 0.0);",
    "    }",
    "    return found;",
    "}",
};

}  // namespace

TraceRecording recordTrace(const ShaderSource& fragment) {
    const std::string& text = fragment.text;
    const GlslScan scan = scanGlsl(text);
    const std::vector<GlslToken>& t = scan.tokens;
    TraceRecording out;
    std::vector<Edit> edits;
    int findClosestEnd = 0;  // the line of its definition's closing brace
    bool hasMain = false;
    for (const GlslFunction& f : glslFunctions(t)) {
        if (f.name == "findClosest") {
            findClosestEnd = t[f.close].line;
            continue;
        }
        hasMain = hasMain || f.name == "main";
        // The guided lab's path state, where this function keeps it.
        const bool keepsPath = hasSequence(t, f.open, f.close, {"current", ".", "weight"}) &&
                               hasSequence(t, f.open, f.close, {"current", ".", "depth"}) &&
                               hasSequence(t, f.open, f.close, {"stackSize"});
        for (std::size_t i = f.open; i + 1 < f.close; ++i) {
            if (t[i].text != "findClosest" || t[i + 1].text != "(") continue;
            std::size_t close = i + 1;
            for (int nest = 0; close < f.close; ++close) {
                if (t[close].text == "(") ++nest;
                else if (t[close].text == ")" && --nest == 0) break;
            }
            const int site = int(out.sites.size());
            out.sites.push_back({f.name, fragment.where(t[i].line)});
            edits.push_back({t[i].pos, t[i].text.size(), "raylab_traceFindClosest"});
            edits.push_back(
                {t[close].pos, 0,
                 ", " + std::to_string(site) + ", " +
                     (keepsPath ? "current.weight, float(stackSize), float(current.depth)"
                                : "vec3(-1.0), -1.0, -1.0")});
        }
    }
    if (!findClosestEnd) throw Error("the program defines no findClosest() whose calls to record");
    if (out.sites.empty())
        throw Error("the program calls findClosest() nowhere: no path to record");
    if (!hasMain) throw Error("the program has no main()");
    // main() renamed: its name is the token before its parameter list.
    for (const GlslFunction& f : glslFunctions(t))
        if (f.name == "main")
            for (std::size_t i = f.open; i > 0; --i)
                if (t[i].text == "main") {
                    edits.push_back({t[i].pos, 4, "raylab_stageMain"});
                    break;
                }
    // The colour output main() writes: the first `out vec4 NAME` at file
    // scope (not a function's `out vec4` parameter).
    std::string colorOut;
    int nest = 0;  // braces and parentheses
    for (std::size_t i = 0; i + 2 < t.size() && colorOut.empty(); ++i) {
        const std::string& w = t[i].text;
        if (w == "{" || w == "(") ++nest;
        else if (w == "}" || w == ")") --nest;
        else if (nest == 0 && w == "out" && t[i + 1].text == "vec4") colorOut = t[i + 2].text;
    }
    if (colorOut.empty()) throw Error("the program declares no colour output (out vec4)");

    std::sort(edits.begin(), edits.end(),
              [](const Edit& a, const Edit& b) { return a.pos > b.pos; });
    std::string body = text;
    for (const Edit& e : edits) body.replace(e.pos, e.length, e.text);

    ShaderSource& s = out.fragment;
    s.files = fragment.files;
    int generated = 1;
    auto emitGenerated = [&](const std::string& line) {
        s.text += line + "\n";
        s.origin.push_back({"<raylab>", generated++});
    };
    std::size_t start = 0;
    for (int line = 1; start < body.size(); ++line) {
        std::size_t end = body.find('\n', start);
        if (end == std::string::npos) end = body.size();
        s.text += body.substr(start, end - start) + "\n";
        s.origin.push_back(fragment.where(line));
        if (line == findClosestEnd)
            for (const char* l : kRecorder) emitGenerated(l);
        start = end + 1;
    }
    for (const std::string& l : {
             std::string("layout(location = 1) out vec4 raylab_traceRay;"),
             std::string("layout(location = 2) out vec4 raylab_traceHit;"),
             std::string("layout(location = 3) out vec4 raylab_traceState;"),
             std::string("void main()"),
             std::string("{"),
             std::string("    raylab_stageMain();"),
             std::string("    if (uTraceRecord == 0) {  // the pixel's colour, and how many calls"),
             "        " + colorOut + " = vec4(" + colorOut + ".rgb, float(raylab_traceCalls));",
             std::string(
                 "        raylab_traceRay = raylab_traceHit = raylab_traceState = vec4(0.0);"),
             std::string("        return;"),
             std::string("    }"),
             "    " + colorOut + " = raylab_trace0;",
             std::string("    raylab_traceRay = raylab_trace1;"),
             std::string("    raylab_traceHit = raylab_trace2;"),
             std::string("    raylab_traceState = raylab_trace3;"),
             std::string("}"),
         })
        emitGenerated(l);
    return out;
}

}  // namespace raylab
