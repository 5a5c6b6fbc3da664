#pragma once
// A textured cloth's thread maps on the GPU (scene/scene.h's ThreadMap; thread_maps.glsl reads
// them). An image is uploaded once as sRGB RGBA8, so the sampler returns linear RGB and filters
// after decoding, and its mip levels are made by glGenerateMipmap: the bundle stores level 0 only
// (a PNG, a third smaller than one with its levels), and the driver's box filter of sRGB levels
// is what the reference's supersampled pixels average to. Wrapping repeats (glTF's default).
#include <array>
#include <memory>

#include <glm/glm.hpp>

#include "gl/gl_program.h"
#include "gl/gl_texture.h"
#include "image/texture_image.h"
#include "scene/scene.h"

namespace weft::gpu {

class ThreadMapTexture {
public:
  explicit ThreadMapTexture(const TextureImage& image);  // needs a current GLES 3 context
  GLuint id() const { return texture_.id(); }

private:
  GlTexture texture_;
};

// A cloth's normal map on the GPU (cloth_normal_map.glsl reads it): RGBA8 stored linearly, since
// its values are vector components rather than colours, with glGenerateMipmap's levels (whose
// averaged normals are short: the shader renormalizes). Wrapping repeats.
class NormalMapTexture {
public:
  explicit NormalMapTexture(const TextureImage& image);  // needs a current GLES 3 context
  GLuint id() const { return texture_.id(); }

private:
  GlTexture texture_;
};

// What a method draws one cloth's threads with: per thread its texture (0: untextured) and the
// map's UV transform (texture_matrix).
struct ThreadMaps {
  std::array<GLuint, 2> textures{0, 0};
  std::array<glm::mat3, 2> uv{glm::mat3(1.0f), glm::mat3(1.0f)};
  // The normal map (0: none), its UV transform and scale.
  GLuint normal_texture = 0;
  glm::mat3 normal_uv{1.0f};
  float normal_scale = 1.0f;
  bool textured() const { return textures[0] != 0 || textures[1] != 0; }
};

// The maps of object `o` from textures already uploaded (`upload(image)` returns its colour
// texture, `upload_normal(image)` its normal map texture).
template <class Upload, class UploadNormal>
ThreadMaps thread_maps_of(const SceneObject& o, Upload&& upload, UploadNormal&& upload_normal) {
  ThreadMaps m;
  for (int j = 0; j < 2; ++j)
    if (o.thread_maps[j]) {
      m.textures[j] = upload(*o.thread_maps[j]->image);
      m.uv[j] = glm::mat3(texture_matrix(o.thread_maps[j]->transform));
    }
  if (o.normal_map) {
    m.normal_texture = upload_normal(*o.normal_map->map.image);
    m.normal_uv = glm::mat3(texture_matrix(o.normal_map->map.transform));
    m.normal_scale = float(o.normal_map->scale);
  }
  return m;
}

// A 1×1 white texture: what thread_maps.glsl's samplers hold on untextured cloth.
class WhiteTexture {
public:
  WhiteTexture();
  GLuint id() const { return texture_.id(); }

private:
  GlTexture texture_;
};

// Sets thread_maps.glsl's and cloth_normal_map.glsl's uniforms on `program` (in use), the maps on
// units first_unit and first_unit + 1 (`white` where a thread has none), the normal map on
// first_unit + 2 (`white` without one; u_normal_mapped then says not to read it).
void bind_thread_maps(const GlProgram& program, const ThreadMaps& maps, GLuint white, int first_unit);

}  // namespace weft::gpu
