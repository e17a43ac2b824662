#include "geometry_emulation_draw.h"

#include "glsl_declarations.h"
#include "glsl_edits.h"

#include <set>

namespace raylab {

// The GLSL expression of a value of TYPE read from 32-bit words starting at
// WORD (word w is component w % 4 of the uvec4 <PREFIX><w / 4>).
std::string readWords(const std::string& type, int word, const std::string& prefix) {
    const BasicType b = basicType(type);
    std::string words;
    for (int c = 0; c < b.components; ++c) {
        const int w = word + c;
        words += (c ? ", " : "") + prefix + std::to_string(w / 4) + "." + "xyzw"[w % 4];
    }
    const std::string u =
        b.components == 1 ? words : "uvec" + std::to_string(b.components) + "(" + words + ")";
    if (b.base == 'f') return "uintBitsToFloat(" + u + ")";
    if (b.base == 'i') return type + "(" + u + ")";
    return u;
}

// The 32-bit words of NAME, a value of TYPE, one expression each.
std::vector<std::string> wordsOf(const std::string& type, const std::string& name) {
    const BasicType b = basicType(type);
    std::vector<std::string> out;
    for (int c = 0; c < b.components; ++c) {
        const std::string v = b.components == 1 ? name : name + "." + std::string(1, "xyzw"[c]);
        out.push_back(b.base == 'f'   ? "floatBitsToUint(" + v + ")"
                      : b.base == 'i' ? "uint(" + v + ")"
                                      : v);
    }
    return out;
}

// The draw: the primitives of slot and corner gl_VertexID reads from the
// emissions' texture, the outputs declared as the student did.
ShaderSource emulationDrawShader(const EmulatedGeometry& e, const std::string& version,
                                 const std::vector<EmulatedOutputDeclaration>& outputs) {
    ShaderSource s;
    int generated = 1;
    appendGenerated(s, version, &generated);
    appendGenerated(s, std::string("uniform highp usampler2DArray ") + kEmissionSampler + ";",
                    &generated);
    std::set<std::string> declared;
    for (const EmulatedOutputDeclaration& o : outputs)
        if (declared.insert(o.declaration).second) appendLine(s, o.declaration, o.from);
    const int v = e.verticesPerSlot, texels = e.emissionTexels;
    const auto n = [](int i) { return std::to_string(i); };
    const int perRun = e.emissionsPerRun;
    std::string body = std::string("flat out int ") + kEmulationKeptOutput +
                       ";\n"
                       "uniform int " +
                       kEmulationPrimitivesUniform +
                       ";\n"
                       "uvec4 raylab_texel(int t)\n{\n"
                       "    return texelFetch(" +
                       kEmissionSampler + ", ivec3(t % " + n(kEmissionTextureWidth) + ", (t / " +
                       n(kEmissionTextureWidth) + ") % " + n(kEmissionLayerRows) + ", t / " +
                       n(kEmissionTextureWidth * kEmissionLayerRows) +
                       "), 0);\n"
                       "}\n"
                       "// The first texel of emission E of PRIMITIVE: the expand wrote run by\n"
                       "// run, each run's primitives in order, " +
                       n(perRun) + " emissions of " + n(texels) +
                       " texels each.\n"
                       "int raylab_emission(int primitive, int e)\n{\n"
                       "    int run = e / " +
                       n(perRun) +
                       ";\n"
                       "    return ((run * " +
                       kEmulationPrimitivesUniform + " + primitive) * " + n(perRun) +
                       " + e - run * " + n(perRun) + ") * " + n(texels) +
                       ";\n"
                       "}\n"
                       "void main()\n{\n"
                       "    int primitive = gl_VertexID / " +
                       n(e.verticesPerPrimitive()) +
                       ";\n"
                       "    int vertex = gl_VertexID - primitive * " +
                       n(e.verticesPerPrimitive()) +
                       ";\n"
                       "    int slot = vertex / " +
                       n(v) + ", corner = vertex - slot * " + n(v) +
                       ";\n"
                       "    // A slot is a primitive made where its last emission is at least\n"
                       "    // its vertices - 1 into its strip. That emission's first word:\n"
                       "    // (strip + 1) * 4 + its place in the strip (0, 1, then 2 or 3 as\n"
                       "    // the place is even or odd); 0 where the body made none.\n"
                       "    uint last = raylab_texel(raylab_emission(primitive, slot + " +
                       n(v - 1) +
                       ")).x;\n"
                       "    bool kept = last != 0u && (last & 3u) >= " +
                       n(v - 1) + "u;\n";
    if (e.output == EmulatedOutput::Triangles)
        body += "    // The odd triangles of a strip swap their first two corners.\n"
                "    bool odd = (last & 1u) == 1u;\n"
                "    int at = raylab_emission(primitive, slot + (odd && corner < 2 ? 1 - corner : "
                "corner));\n";
    else body += "    int at = raylab_emission(primitive, slot + corner);\n";
    body += "    // A primitive not made: a point outside the view.\n"
            "    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n";
    std::string read;
    for (int a = 0; a < texels; ++a)
        read += "        uvec4 raylab_w" + n(a) + " = raylab_texel(at + " + n(a) + ");\n";
    read += "        gl_Position = " + readWords("vec4", 1, "raylab_w") + ";\n";
    std::string zero;
    int word = 5;
    for (const EmulatedOutputDeclaration& o : outputs) {
        read += "        " + o.name + " = " + readWords(o.type, word, "raylab_w") + ";\n";
        zero += "        " + o.name + " = " + o.type + "(0);\n";
        word += basicType(o.type).components;
    }
    // Read only where kept: a run of slots not made costs no texel reads.
    body += "    if (kept) {\n" + read + "    } else {\n" + zero + "    }\n";
    body += "    " + std::string(kEmulationKeptOutput) + " = kept ? 1 : 0;\n}\n";
    appendGenerated(s, body, &generated);
    return s;
}

}  // namespace raylab
