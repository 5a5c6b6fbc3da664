#include "gl/gl_error.h"

#include <GLES3/gl3.h>

#include <cstdio>
#include <string>

namespace weft::gpu {

void check_gl(const char* what) {
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "%04x", e);
    throw GpuError(std::string(what) + ": GL error 0x" + code);
  }
}

}  // namespace weft::gpu
