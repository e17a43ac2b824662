#pragma once
// A linked GLSL program built from assembled shaders (vertex, optional
// geometry, fragment). Compile and link
// errors are reported with the students' file names and lines.
#include "gl.h"
#include "shader_source.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace raylab {

// Thrown when a shader does not compile or link. what() is one line: the first
// error, mapped to file:line; log() has every mapped line.
class ShaderError : public std::runtime_error {
public:
    ShaderError(const std::string& firstLine, std::string log)
        : std::runtime_error(firstLine), log_(std::move(log)) {}
    const std::string& log() const { return log_; }

private:
    std::string log_;
};

class ShaderProgram {
public:
    ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment);
    // With a geometry shader between them.
    ShaderProgram(const ShaderSource& vertex, const ShaderSource& geometry,
                  const ShaderSource& fragment);
    // Linked for transform feedback of FEEDBACK (output names, interleaved
    // into one buffer in this order).
    ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment,
                  const std::vector<std::string>& feedback);
    ShaderProgram(const ShaderSource& vertex, const ShaderSource& geometry,
                  const ShaderSource& fragment, const std::vector<std::string>& feedback);
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { glUseProgram(id_); }
    GLuint id() const { return id_; }  // for calls this class does not wrap (uniform blocks)
    // -1 when the program has no such (active) uniform; setting it is then a no-op.
    GLint uniform(const std::string& name) const;

private:
    ShaderProgram(const ShaderSource& vertex, const ShaderSource* geometry,
                  const ShaderSource& fragment, const std::vector<std::string>& feedback);
    GLuint id_ = 0;
    mutable std::unordered_map<std::string, GLint> uniforms_;
};

}  // namespace raylab
