#include "gl/gl_texture.h"

namespace weft::gpu {

GlTexture::GlTexture() { glGenTextures(1, &id_); }
GlTexture::~GlTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

}  // namespace weft::gpu
