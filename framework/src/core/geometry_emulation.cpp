#include "geometry_emulation.h"

#include "geometry_emulation_draw.h"

#include "error.h"
#include "glsl_declarations.h"
#include "glsl_edits.h"
#include "glsl_scan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace raylab {

namespace {

std::string at(const ShaderSource& source, int line) {
    const SourceLine w = source.where(line);
    return w.file + ":" + std::to_string(w.line) + ": ";
}

// The file the shader was assembled from: the first line not generated.
std::string entryFile(const ShaderSource& source) {
    for (const SourceLine& l : source.origin)
        if (l.file != "<raylab>") return l.file;
    return "<raylab>";
}

[[noreturn]] void notInThePage(const ShaderSource& gs, int line, const std::string& what) {
    throw Error(at(gs, line) + what +
                " is not available where geometry shaders are emulated (the page: WebGL 2 has "
                "none); raylab run and check run it natively");
}

}  // namespace

std::string EmulatedGeometry::json() const {
    static const char* const kOutputs[] = {"points", "lines", "triangles"};
    return nlohmann::json{{"input", inputName},
                          {"corners", corners},
                          {"recordWords", recordWords},
                          {"attributes", attributes},
                          {"captured", captured},
                          {"emitted", emitted},
                          {"output", kOutputs[int(output)]},
                          {"maxVertices", maxVertices},
                          {"slots", slots},
                          {"verticesPerSlot", verticesPerSlot},
                          {"emissionTexels", emissionTexels},
                          {"emissionsPerRun", emissionsPerRun},
                          {"runs", runs},
                          {"textureWidth", kEmissionTextureWidth},
                          {"layerRows", kEmissionLayerRows},
                          {"textureUnit", kEmissionTextureUnit}}
        .dump();
}

EmissionTextureSize emissionTextureSize(const EmulatedGeometry& e, long primitives) {
    const long long texels =
        std::max(1LL, (long long)primitives * e.emissionsPerPrimitive() * e.emissionTexels);
    const long long rows = (texels + kEmissionTextureWidth - 1) / kEmissionTextureWidth;
    EmissionTextureSize out;
    out.layers = int((rows + kEmissionLayerRows - 1) / kEmissionLayerRows);
    out.rows = int(std::min<long long>(rows, kEmissionLayerRows));
    return out;
}

ShaderSource captureFragmentShader(const std::string& version) {
    ShaderSource s;
    s.text = version + "\nvoid main() {}\n";
    s.origin = {{"<raylab>", 1}, {"<raylab>", 2}};
    return s;
}

EmulatedGeometry emulateGeometryShader(const ShaderSource& vertex, const ShaderSource& geometry) {
    const std::string& text = geometry.text;
    const GlslScan gs = scanGlsl(text);
    const std::vector<GlslToken>& t = gs.tokens;
    EmulatedGeometry out;
    std::vector<TextEdit> edits;
    auto blank = [&](const GlslStatement& s) {
        const std::size_t from = t[s.begin].pos, to = t[s.end - 1].pos + 1;
        edits.push_back({from, to - from, keepingLines(text, from, to, "")});
    };

    // The vertex shader's outputs, by name.
    std::map<std::string, GlslVarying> written;
    {
        const GlslScan vs = scanGlsl(vertex.text);
        std::vector<GlslVarying> outs;
        for (const GlslStatement& s : fileScopeStatements(vs.tokens))
            parseVaryings(vs.tokens, s, "out", outs, vertex);
        for (const GlslVarying& v : outs) written[v.name] = v;
    }

    // The layouts, the inputs and the outputs.
    std::vector<GlslVarying> inputs, outputs;
    std::vector<EmulatedOutputDeclaration> declared;  // the outputs, for the draw
    int layoutLine = 0;
    for (const GlslStatement& s : fileScopeStatements(t)) {
        std::vector<std::string> words;
        const std::size_t afterLayout = skipLayout(t, s.begin, s.end, &words);
        if (afterLayout != s.begin && afterLayout + 2 == s.end &&
            (t[afterLayout].text == "in" || t[afterLayout].text == "out")) {
            const bool in = t[afterLayout].text == "in";
            for (std::size_t k = 0; k < words.size(); ++k) {
                const std::string& w = words[k];
                if (in && (w == "points" || w == "lines" || w == "lines_adjacency" ||
                           w == "triangles" || w == "triangles_adjacency")) {
                    out.inputName = w;
                    out.corners = w == "points"            ? 1
                                  : w == "lines"           ? 2
                                  : w == "lines_adjacency" ? 4
                                  : w == "triangles"       ? 3
                                                           : 6;
                    layoutLine = t[s.begin].line;
                } else if (in && w == "invocations") {
                    notInThePage(geometry, t[s.begin].line,
                                 "an instanced geometry shader (invocations)");
                } else if (!in && (w == "points" || w == "line_strip" || w == "triangle_strip")) {
                    out.output = w == "points"       ? EmulatedOutput::Points
                                 : w == "line_strip" ? EmulatedOutput::Lines
                                                     : EmulatedOutput::Triangles;
                    out.verticesPerSlot = w == "points" ? 1 : w == "line_strip" ? 2 : 3;
                } else if (!in && w == "max_vertices" && k + 2 < words.size() &&
                           words[k + 1] == "=") {
                    out.maxVertices = int(glslWholeNumber(words[k + 2], gs.macros));
                    if (out.maxVertices < 0)
                        throw Error(at(geometry, t[s.begin].line) + "max_vertices = " +
                                    words[k + 2] + " is not a whole number the page can read");
                }
            }
            blank(s);
            continue;
        }
        const std::size_t before = inputs.size();
        if (parseVaryings(t, s, "in", inputs, geometry)) {
            std::string decl;
            for (std::size_t k = before; k < inputs.size(); ++k) {
                if (!inputs[k].array)
                    throw Error(at(geometry, inputs[k].line) + "a geometry shader's input " +
                                inputs[k].name + " must be an array (" + inputs[k].name + "[])");
                decl += inputs[k].type + " " + inputs[k].name + "[RAYLAB_CORNERS]; ";
            }
            const std::size_t from = t[s.begin].pos, to = t[s.end - 1].pos + 1;
            edits.push_back({from, to - from, keepingLines(text, from, to, decl)});
            continue;
        }
        const std::size_t outputsBefore = outputs.size();
        if (parseVaryings(t, s, "out", outputs, geometry)) {
            // The draw declares it as written; here it is a plain variable
            // the body writes and each EmitVertex() reads.
            std::string declaration, plain;
            for (std::size_t k = s.begin; k < s.end; ++k) {
                const std::string& w = t[k].text;
                const bool space = k > s.begin && w != ";" && w != "," && w != ")" && w != "]" &&
                                   t[k - 1].text != "(" && t[k - 1].text != "[";
                declaration += (space ? " " : "") + w;
            }
            for (std::size_t k = outputsBefore; k < outputs.size(); ++k) {
                plain += outputs[k].type + " " + outputs[k].name + "; ";
                declared.push_back({outputs[k].type, outputs[k].name, declaration,
                                    geometry.where(t[s.begin].line)});
            }
            const std::size_t from = t[s.begin].pos, to = t[s.end - 1].pos + 1;
            edits.push_back({from, to - from, keepingLines(text, from, to, plain)});
        }
    }
    if (!out.corners)
        throw Error(entryFile(geometry) + ": the geometry shader declares no input primitive "
                                          "(layout(triangles) in;)");
    if (!out.verticesPerSlot || out.maxVertices <= 0)
        throw Error(at(geometry, layoutLine) + "the geometry shader declares no output "
                                               "(layout(triangle_strip, max_vertices = N) out;)");
    for (const GlslVarying& v : outputs)
        if (v.array || !basicType(v.type).components)
            throw Error(at(geometry, v.line) + "the output " + v.name + " (" + v.type +
                        (v.array ? "[]" : "") +
                        ") cannot be emulated: use float, int or uint scalars and vectors");

    // The calls and built-ins, with where each function body is.
    std::set<std::size_t> voidBodies;  // token index of a void function's "{"
    for (const GlslFunction& f : glslFunctions(t))
        if (f.returnType == "void") voidBodies.insert(f.open);
    bool readsPositions = false;
    int depth = 0;
    std::vector<bool> inVoid;  // per open brace: inside a void function
    for (std::size_t i = 0; i < t.size(); ++i) {
        const GlslToken& k = t[i];
        const std::string& w = k.text;
        if (w == "{") {
            inVoid.push_back(depth == 0 ? voidBodies.count(i) > 0 : inVoid.back());
            ++depth;
        } else if (w == "}") {
            if (depth > 0) --depth, inVoid.pop_back();
        } else if (w == "main" && depth == 0 && i + 1 < t.size() && t[i + 1].text == "(") {
            edits.push_back({k.pos, w.size(), "raylab_geometryMain"});
        } else if (w == "EmitVertex") {
            const bool statement = i + 3 < t.size() && t[i + 1].text == "(" &&
                                   t[i + 2].text == ")" && t[i + 3].text == ";";
            if (statement && depth > 0 && inVoid.back()) {
                // Its emissions kept, the body stops here (in a void function).
                edits.push_back(
                    {k.pos, t[i + 3].pos + 1 - k.pos, "{ if (raylab_emitVertex()) return; }"});
                i += 3;
            } else {
                edits.push_back({k.pos, w.size(), "raylab_emitVertex"});
            }
        } else if (w == "EndPrimitive") {
            edits.push_back({k.pos, w.size(), "raylab_endPrimitive"});
        } else if (w == "gl_PrimitiveIDIn") {
            edits.push_back({k.pos, w.size(), "raylab_primitiveId"});
        } else if (w == "gl_in") {
            // gl_in[i].gl_Position -> raylab_inPosition[i]
            std::size_t close = i + 1, nest = 0;
            for (; close < t.size(); ++close) {
                if (t[close].text == "[") ++nest;
                else if (t[close].text == "]" && --nest == 0) break;
            }
            if (i + 1 >= t.size() || t[i + 1].text != "[" || close + 2 >= t.size() ||
                t[close + 1].text != "." || t[close + 2].text != "gl_Position")
                notInThePage(geometry, k.line, "gl_in other than gl_in[i].gl_Position");
            edits.push_back({k.pos, w.size(), "raylab_inPosition"});
            edits.push_back({t[close + 1].pos, t[close + 2].pos + 11 - t[close + 1].pos, ""});
            readsPositions = true;
        } else if (w == "gl_InvocationID" || w == "gl_Layer" || w == "gl_ViewportIndex" ||
                   w == "gl_PrimitiveID" || w == "EmitStreamVertex" || w == "EndStreamPrimitive" ||
                   w == "gl_PointSize" || w == "gl_ClipDistance") {
            notInThePage(geometry, k.line, w);
        }
    }

    // The record: each input, as the vertex shader wrote it; gl_Position last.
    std::string fill;  // the wrapper's copies from the attributes into the inputs
    std::vector<std::pair<std::string, std::string>> fields;  // type, name
    for (const GlslVarying& v : inputs) {
        const auto w = written.find(v.name);
        if (w == written.end())
            throw Error(at(geometry, v.line) + "the input " + v.name +
                        " is not an output of the vertex shader");
        if (w->second.type != v.type)
            throw Error(at(geometry, v.line) + "the input " + v.name + " is " + v.type +
                        ", the vertex shader's output " + w->second.type);
        if (!basicType(v.type).components)
            throw Error(at(geometry, v.line) + "the input " + v.name + " (" + v.type +
                        ") cannot be emulated: use float, int or uint scalars and vectors");
        fields.push_back({v.type, v.name});
    }
    if (readsPositions) fields.push_back({"vec4", "gl_Position"});
    std::vector<int> offsets;
    for (const auto& [type, name] : fields) {
        offsets.push_back(out.recordWords);
        out.recordWords += basicType(type).components;
        out.captured.push_back(name);
    }
    for (int c = 0; c < out.corners; ++c)
        for (std::size_t f = 0; f < fields.size(); ++f) {
            const std::string target =
                fields[f].second == "gl_Position" ? "raylab_inPosition" : fields[f].second;
            fill += "    " + target + "[" + std::to_string(c) + "] = " +
                    readWords(fields[f].first, c * out.recordWords + offsets[f], "raylab_in") +
                    ";\n";
        }
    out.attributes = std::max(1, (out.corners * out.recordWords + 3) / 4);
    constexpr int kMaxAttributes = 16;  // WebGL 2's guaranteed vertex attributes
    if (out.attributes > kMaxAttributes)
        throw Error(at(geometry, layoutLine) +
                    "the vertex shader's outputs the geometry shader "
                    "reads take " +
                    std::to_string(out.recordWords) + " components per vertex, " +
                    std::to_string(out.corners * out.recordWords) +
                    " per primitive; the page "
                    "passes at most " +
                    std::to_string(4 * kMaxAttributes));
    out.slots = std::max(0, out.maxVertices - (out.verticesPerSlot - 1));

    // An emission's words: its strip's, gl_Position, the outputs.
    std::vector<std::string> words = {"raylab_head"};
    for (const std::string& w : wordsOf("vec4", "gl_Position")) words.push_back(w);
    for (const EmulatedOutputDeclaration& o : declared)
        for (const std::string& w : wordsOf(o.type, o.name)) words.push_back(w);
    out.emissionTexels = int(words.size() + 3) / 4;
    constexpr int kFeedbackTexels = 16;  // WebGL 2's least: 64 interleaved components
    if (out.emissionTexels > kFeedbackTexels)
        throw Error(at(geometry, layoutLine) + "the geometry shader's outputs take " +
                    std::to_string(words.size() - 1) +
                    " components per vertex with gl_Position; the page passes at most " +
                    std::to_string(4 * kFeedbackTexels - 1));
    out.emissionsPerRun = std::min(out.maxVertices, kFeedbackTexels / out.emissionTexels);
    out.runs = (out.maxVertices + out.emissionsPerRun - 1) / out.emissionsPerRun;
    const int texels = out.emissionTexels, perRun = out.emissionsPerRun;
    for (int i = 0; i < perRun * texels; ++i) out.emitted.push_back("raylab_e" + std::to_string(i));

    const std::vector<std::string> lines = splitLines(applyEdits(text, std::move(edits)));

    // Declarations the body needs before its own code, after #version (and
    // its #extension lines): generated lines, which errors name as such.
    const std::string n = std::to_string(out.corners);
    std::vector<std::string> head = {
        "#define RAYLAB_CORNERS " + n,
        "int raylab_primitiveId;",
        "bool raylab_emitVertex();",
        "void raylab_endPrimitive();",
    };
    if (readsPositions) head.push_back("vec4 raylab_inPosition[RAYLAB_CORNERS];");

    // The wrapper: inputs in, the student's main, this run's emissions out.
    const auto str = [](int i) { return std::to_string(i); };
    std::string tail;
    for (int a = 0; a < out.attributes; ++a) tail += "in uvec4 raylab_in" + str(a) + ";\n";
    for (const std::string& e : out.emitted) tail += "flat out uvec4 " + e + ";\n";
    tail +=
        "int raylab_emitted = 0, raylab_strip = 0, raylab_stripStart = 0, raylab_first = 0;\n"
        "bool raylab_emitVertex()\n{\n"
        "    int n = raylab_emitted;\n"
        "    if (n >= " +
        str(out.maxVertices) +
        ") return true;\n"
        "    raylab_emitted = n + 1;\n"
        "    int k = n - raylab_first;\n"
        "    if (k < 0) return false;\n"
        "    if (k >= " +
        str(perRun) +
        ") return true;\n"
        "    int place = n - raylab_stripStart;\n"
        "    uint raylab_head = uint(raylab_strip + 1) * 4u + uint(place < 2 ? place : 2 + place % "
        "2);\n";
    for (int a = 0; a < texels; ++a) {
        std::string w;
        for (int c = 0; c < 4; ++c) {
            const std::size_t i = std::size_t(4 * a + c);
            w += (c ? ", " : "") + (i < words.size() ? words[i] : std::string("0u"));
        }
        tail += "    uvec4 w" + str(a) + " = uvec4(" + w + ");\n";
    }
    // Separate outputs, each written at a constant place: an output array
    // written at a run-time index is where softpipe goes wrong
    // (docs/bench/README.md, "On Mesa's softpipe").
    for (int k = 0; k < perRun; ++k) {
        tail += std::string(k ? "    else if" : "    if") + " (k == " + str(k) + ") {";
        for (int a = 0; a < texels; ++a)
            tail += " raylab_e" + str(k * texels + a) + " = w" + str(a) + ";";
        tail += " }\n";
    }
    tail += "    return k == " + str(perRun - 1) +
            ";\n"
            "}\n"
            "void raylab_endPrimitive()\n{\n"
            "    raylab_strip += 1;\n"
            "    raylab_stripStart = raylab_emitted;\n"
            "}\n"
            "void main()\n{\n"
            "    raylab_primitiveId = gl_VertexID;\n"
            "    raylab_first = gl_InstanceID * " +
            str(perRun) + ";\n" + fill;
    for (const std::string& e : out.emitted) tail += "    " + e + " = uvec4(0u);\n";
    tail +=
        "    raylab_geometryMain();\n"
        "    gl_Position = vec4(0.0);  // drawn nowhere: transform feedback keeps the emissions\n"
        "}\n";

    // Assemble with the origin: line 1, its #extension lines, the head, the
    // body's other lines, the tail.
    std::size_t afterVersion = lines.empty() ? 0 : 1;
    while (afterVersion < lines.size() && lines[afterVersion].rfind("#extension", 0) == 0)
        ++afterVersion;
    ShaderSource& s = out.expand;
    s.files = geometry.files;
    for (std::size_t i = 0; i < afterVersion; ++i)
        appendLine(s, lines[i], geometry.where(int(i) + 1));
    int generated = 1;
    for (const std::string& h : head) appendGenerated(s, h, &generated);
    for (std::size_t i = afterVersion; i < lines.size(); ++i)
        appendLine(s, lines[i], geometry.where(int(i) + 1));
    appendGenerated(s, tail, &generated);
    out.draw = emulationDrawShader(out, lines.empty() ? kGlslVersionLine : lines[0], declared);
    out.draw.files = geometry.files;
    return out;
}

}  // namespace raylab
