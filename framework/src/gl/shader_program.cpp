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

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertex);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragment);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDetachShader(id_, vs);
    glDetachShader(id_, fs);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log = mapCompilerLog(infoLog(id_, true), fragment);
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
