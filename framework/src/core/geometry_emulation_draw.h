#pragma once
// The emulated geometry shader's words and its draw (geometry_emulation.h):
// values packed into the 32-bit words transform feedback keeps and read
// back, and the vertex shader that makes the strips' primitives from the
// emissions' texture. Students need not read this file.
#include "geometry_emulation.h"

#include <string>
#include <vector>

namespace raylab {

// An output of the geometry shader: its type and name, and its declaration
// as the student wrote it (for the draw).
struct EmulatedOutputDeclaration {
    std::string type, name, declaration;
    SourceLine from;
};

// The GLSL expression of a value of TYPE read from 32-bit words starting at
// WORD (word w is component w % 4 of the uvec4 <PREFIX><w / 4>).
std::string readWords(const std::string& type, int word, const std::string& prefix);

// The 32-bit words of NAME, a value of TYPE, one GLSL expression each.
std::vector<std::string> wordsOf(const std::string& type, const std::string& name);

// The draw of E: the primitive of slot and corner gl_VertexID read from the
// emissions' texture, the OUTPUTS declared as the student did (VERSION: the
// shader's first line).
ShaderSource emulationDrawShader(const EmulatedGeometry& e, const std::string& version,
                                 const std::vector<EmulatedOutputDeclaration>& outputs);

}  // namespace raylab
