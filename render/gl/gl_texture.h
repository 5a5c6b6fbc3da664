#pragma once
// An owned GL texture name (glGenTextures / glDeleteTextures); what it holds is the user's.
#include <GLES3/gl3.h>

namespace weft::gpu {

class GlTexture {
public:
  GlTexture();
  GlTexture(GlTexture&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  GlTexture(const GlTexture&) = delete;
  ~GlTexture();
  GLuint id() const { return id_; }

private:
  GLuint id_ = 0;
};

}  // namespace weft::gpu
