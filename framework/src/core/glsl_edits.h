#pragma once
// Edits of a shader's text that keep its line numbers, and its lines put
// back together with their origin (shader_source.h): the rewrites of
// geometry_emulation.h and trace_recording.h. Students need not read this file.
#include "shader_source.h"

#include <string>
#include <vector>

namespace raylab {

// An edit of the text: the characters [pos, pos + length) become TEXT.
struct TextEdit {
    std::size_t pos = 0, length = 0;
    std::string text;
};

// TEXT with EDITS made (they must not overlap), last first so that
// positions stay right.
std::string applyEdits(std::string text, std::vector<TextEdit> edits);

// TEXT for the span [from, to) of SOURCE, with as many newlines as the span
// had, so that every later line keeps its number.
std::string keepingLines(const std::string& source, std::size_t from, std::size_t to,
                         const std::string& text);

// TEXT's lines, without their newlines (a last line without one too).
std::vector<std::string> splitLines(const std::string& text);

// Appends LINE to S, from FROM; appends each line of TEXT as generated
// (file "<raylab>"), numbered on from *GENERATED.
void appendLine(ShaderSource& s, const std::string& line, const SourceLine& from);
void appendGenerated(ShaderSource& s, const std::string& text, int* generated);

}  // namespace raylab
