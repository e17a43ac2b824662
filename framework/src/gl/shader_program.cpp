#include "shader_program.h"

#include <sstream>
#include <vector>

namespace raylab {

namespace {

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1, '\0');
    if (length > 0)
        isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
                  : glGetShaderInfoLog(object, length, nullptr, log.data());
    return log.data();
}

// The first line that reports an error, else the first non-empty line.
std::string firstErrorLine(const std::string& log) {
    std::istringstream in(log);
    std::string line, first;
    while (std::getline(in, line)) {
        if (line.find("error") != std::string::npos || line.find("ERROR") != std::string::npos)
            return line;
        if (first.empty() && !line.empty()) first = line;
    }
    return first.empty() ? "unknown error" : first;
}

GLuint compile(GLenum kind, const ShaderSource& source) {
    GLuint shader = glCreateShader(kind);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log = mapCompilerLog(infoLog(shader, false), source);
        glDeleteShader(shader);
        throw ShaderError(firstErrorLine(log), log);
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment)
    : ShaderProgram(vertex, nullptr, fragment, {}) {}

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment,
                             const std::vector<std::string>& feedback)
    : ShaderProgram(vertex, nullptr, fragment, feedback) {}

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource& geometry,
                             const ShaderSource& fragment)
    : ShaderProgram(vertex, &geometry, fragment, {}) {}

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource& geometry,
                             const ShaderSource& fragment, const std::vector<std::string>& feedback)
    : ShaderProgram(vertex, &geometry, fragment, feedback) {}

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource* geometry,
                             const ShaderSource& fragment,
                             const std::vector<std::string>& feedback) {
    // Compiled in pipeline order, so the first error reported is the first
    // a reader meets; what compiled is deleted when a later stage fails.
    std::vector<GLuint> shaders;
    try {
        shaders.push_back(compile(GL_VERTEX_SHADER, vertex));
        if (geometry) shaders.push_back(compile(GL_GEOMETRY_SHADER, *geometry));
        shaders.push_back(compile(GL_FRAGMENT_SHADER, fragment));
    } catch (...) {
        for (GLuint sh : shaders) glDeleteShader(sh);
        throw;
    }
    id_ = glCreateProgram();
    for (GLuint sh : shaders) glAttachShader(id_, sh);
    if (!feedback.empty()) {
        std::vector<const char*> names;
        for (const std::string& n : feedback) names.push_back(n.c_str());
        glTransformFeedbackVaryings(id_, GLsizei(names.size()), names.data(),
                                    GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(id_);
    for (GLuint sh : shaders) {
        glDetachShader(id_, sh);
        glDeleteShader(sh);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log = mapCompilerLog(infoLog(id_, true), geometry           ? *geometry
                                                             : feedback.empty() ? fragment
                                                                                : vertex);
        glDeleteProgram(id_);
        throw ShaderError("link error: " + firstErrorLine(log), log);
    }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

GLint ShaderProgram::uniform(const std::string& name) const {
    auto it = uniforms_.find(name);
    if (it != uniforms_.end()) return it->second;
    GLint location = glGetUniformLocation(id_, name.c_str());
    uniforms_.emplace(name, location);
    return location;
}

}  // namespace raylab
