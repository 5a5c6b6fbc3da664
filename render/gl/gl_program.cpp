#include "gl/gl_program.h"

#include <sstream>
#include <vector>

#include "gl/gl_error.h"

namespace weft::gpu {

const char* fullscreen_triangle_vs() {
  return R"(#version 300 es
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
})";
}

namespace {

// Shader info logs name lines as "0:LINE:"; quote that line of the source beside the log.
std::string with_source_line(const std::string& log, const std::string& source) {
  std::string out = log;
  const size_t colon = log.find("0:");
  if (colon != std::string::npos) {
    const int line = std::atoi(log.c_str() + colon + 2);
    std::istringstream in(source);
    std::string text;
    for (int i = 1; std::getline(in, text); ++i)
      if (i == line) out += "\n  line " + std::to_string(line) + ": " + text;
  }
  return out;
}

GLuint compile(GLenum type, const std::string& source) {
  GLuint s = glCreateShader(type);
  const char* src = source.c_str();
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(std::max(len, 1));
    glGetShaderInfoLog(s, len, nullptr, log.data());
    glDeleteShader(s);
    throw GpuError(std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader does not compile: " +
                   with_source_line(log.data(), source));
  }
  return s;
}

}  // namespace

GlProgram::GlProgram(const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(std::max(len, 1));
    glGetProgramInfoLog(id_, len, nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw GpuError(std::string("program does not link: ") + log.data());
  }
}

GlProgram::~GlProgram() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace weft::gpu
