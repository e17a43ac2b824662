#include "trace_recording.h"

#include "error.h"
#include "glsl_declarations.h"
#include "glsl_edits.h"
#include "glsl_scan.h"
#include "shader_constants.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

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
    std::vector<TextEdit> edits;
    int findClosestEnd = 0;  // the line of its definition's closing brace
    bool hasMain = false;
    for (const GlslFunction& f : glslFunctions(t)) {
        if (f.name == "findClosest") {
            findClosestEnd = t[f.close].line;
            continue;
        }
        if (f.name == "main") {  // renamed: the stage's main runs inside the recorder's
            edits.push_back({t[f.nameToken].pos, 4, "raylab_stageMain"});
            hasMain = true;
        }
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
    // The colour output main() writes: the first global `out vec4`.
    std::string colorOut;
    for (const GlslStatement& st : fileScopeStatements(t)) {
        std::vector<GlslVarying> outs;
        if (parseVaryings(t, st, "out", outs, fragment) && outs[0].type == "vec4") {
            colorOut = outs[0].name;
            break;
        }
    }
    if (colorOut.empty()) throw Error("the program declares no colour output (out vec4)");

    ShaderSource& s = out.fragment;
    s.files = fragment.files;
    int generated = 1;
    const std::vector<std::string> lines = splitLines(applyEdits(text, std::move(edits)));
    for (std::size_t i = 0; i < lines.size(); ++i) {
        appendLine(s, lines[i], fragment.where(int(i) + 1));
        if (int(i) + 1 == findClosestEnd)
            for (const char* l : kRecorder) appendGenerated(s, l, &generated);
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
        appendGenerated(s, l, &generated);
    return out;
}

std::string formatTracedPath(const std::vector<TraceCallSite>& sites,
                             const std::vector<float>& summary, const std::vector<float>& records,
                             double scale, glm::dvec3 offset) {
    if (summary.size() < 4 || records.size() % 16 != 0)
        throw Error("a traced path: a summary of 4 floats and 16 per call");
    auto number = [](double v) { return significant(v, 4); };
    auto point = [&](const float* p) {
        return "(" + number((p[0] - offset.x) / scale) + ", " + number((p[1] - offset.y) / scale) +
               ", " + number((p[2] - offset.z) / scale) + ")";
    };
    auto direction = [&](const float* p) {
        return "(" + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) + ")";
    };
    std::string out;
    const std::size_t calls = records.size() / 16;
    for (std::size_t i = 0; i < calls; ++i) {
        const float* r = &records[16 * i];  // origin site | dir id | t weight | stack depth hit
        const int site = int(std::lround(r[3]));
        std::string where = "?";
        if (site >= 0 && std::size_t(site) < sites.size()) {
            const TraceCallSite& c = sites[std::size_t(site)];
            where = c.function + ", " + c.where.file + ":" + std::to_string(c.where.line);
        }
        out += "ray " + std::to_string(i + 1) + " (" + where;
        if (r[13] >= 0.0f)
            out += "; depth " + number(r[13]) + ", weight " + number(r[9]) + "," + number(r[10]) +
                   "," + number(r[11]) + ", stack " + number(r[12]);
        out += ") from " + point(r) + " along " + direction(r + 4) + ": ";
        if (r[14] > 0.5f) {
            const int id = int(std::lround(r[7]));
            const int kind = id / shader::kObjectKindStride;
            out += "hits " +
                   std::string(kind >= 0 && kind < int(std::size(shader::kKindNames))
                                   ? shader::kKindNames[kind]
                                   : "object") +
                   " " + std::to_string(id % shader::kObjectKindStride) +
                   " at t=" + number(double(r[8]) / scale) + "\n";
        } else {
            out += "misses everything\n";
        }
    }
    const int total = int(std::lround(summary[3]));
    if (total > int(calls)) out += "(" + std::to_string(total - int(calls)) + " more not shown)\n";
    auto byte = [](float c) {
        return std::to_string(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
    };
    return out + "rays traced: " + std::to_string(total) + "\ncolour: (" + number(summary[0]) +
           ", " + number(summary[1]) + ", " + number(summary[2]) + ") = " + byte(summary[0]) +
           ", " + byte(summary[1]) + ", " + byte(summary[2]) + " of 255\n";
}

}  // namespace raylab
