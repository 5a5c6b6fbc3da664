#include "methods/thread_map_textures.h"

#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_error.h"

namespace weft::gpu {

namespace {

// `image` into `texture` as `internal_format`, with its mipmaps, repeating.
void upload_repeating(const GlTexture& texture, const TextureImage& image, GLenum internal_format, const char* what) {
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.rgba.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  check_gl(what);
}

}  // namespace

ThreadMapTexture::ThreadMapTexture(const TextureImage& image) {
  upload_repeating(texture_, image, GL_SRGB8_ALPHA8, "uploading a cloth texture");
}

NormalMapTexture::NormalMapTexture(const TextureImage& image) {
  upload_repeating(texture_, image, GL_RGBA8, "uploading a cloth normal map");
}

WhiteTexture::WhiteTexture() {
  const unsigned char white[4] = {255, 255, 255, 255};
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void bind_thread_maps(const GlProgram& program, const ThreadMaps& maps, GLuint white, int first_unit) {
  const char* samplers[2] = {"u_warp_map", "u_weft_map"};
  const char* transforms[2] = {"u_warp_uv", "u_weft_uv"};
  glUniform1i(program.uniform("u_textured"), maps.textured() ? 1 : 0);
  for (int j = 0; j < 2; ++j) {
    glActiveTexture(GLenum(GL_TEXTURE0 + first_unit + j));
    glBindTexture(GL_TEXTURE_2D, maps.textures[j] ? maps.textures[j] : white);
    glUniform1i(program.uniform(samplers[j]), first_unit + j);
    glUniformMatrix3fv(program.uniform(transforms[j]), 1, GL_FALSE, glm::value_ptr(maps.uv[j]));
  }
  glUniform1i(program.uniform("u_normal_mapped"), maps.normal_texture ? 1 : 0);
  glActiveTexture(GLenum(GL_TEXTURE0 + first_unit + 2));
  glBindTexture(GL_TEXTURE_2D, maps.normal_texture ? maps.normal_texture : white);
  glUniform1i(program.uniform("u_normal_map"), first_unit + 2);
  glUniformMatrix3fv(program.uniform("u_normal_uv"), 1, GL_FALSE, glm::value_ptr(maps.normal_uv));
  glUniform1f(program.uniform("u_normal_scale"), maps.normal_scale);
}

}  // namespace weft::gpu
