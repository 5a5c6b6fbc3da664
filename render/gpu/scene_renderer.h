#pragma once
// Draws a showroom scene with one runtime method into a linear float target: cloth with the
// method's shader, Lambertian surfaces with their SG irradiance (computed per vertex on the
// CPU whenever the lighting changes, not per pixel per frame).
#include <memory>
#include <string>
#include <vector>

#include "core/cloth_bsdf.h"
#include "core/spherical_gaussian.h"
#include "gpu/gl_program.h"
#include "gpu/gpu_mesh.h"
#include "gpu/iwasaki_cloth.h"
#include "image/image.h"
#include "scene/scene.h"

namespace weft::gpu {

enum class Method { sgpoint, iwasaki };
Method parse_method(const std::string& name);  // throws std::invalid_argument listing the methods

class SceneRenderer {
public:
  // Needs a current GLES 3 context. `fabrics[i]` is the fabric of the i-th cloth object.
  // Method::iwasaki draws cloth from `iwasaki` (a bundle's seed 000 tables; required for it).
  SceneRenderer(const Scene& scene, std::vector<Fabric> fabrics, Method method, int tangent_samples = 16,
                std::shared_ptr<const IwasakiBundleData> iwasaki = nullptr);
  ~SceneRenderer();

  void set_lighting(const SgLighting& sgs);
  // Knob edits: new thread albedo / gloss for a cloth object, no re-bake.
  void set_fabric(size_t cloth_index, const Fabric& fabric);
  // Renders into the currently bound framebuffer of size width × height.
  void draw(const Camera& camera, int width, int height);

private:
  struct Object;
  std::vector<std::unique_ptr<Object>> objects_;
  std::unique_ptr<GlProgram> cloth_program_, lambert_program_;
  std::unique_ptr<IwasakiCloth> iwasaki_;  // Method::iwasaki only
  SgLighting sgs_;
  int tangent_samples_;
};

// The frame as linear radiance (row 0 at the top) from a float target of the given size.
Image read_linear_image(int width, int height);

// Tone-maps a float texture to the bound framebuffer: the write_png operator.
class ToneMapper {
public:
  ToneMapper();
  void draw(GLuint linear_texture, float exposure) const;

private:
  GlProgram program_;
};

}  // namespace weft::gpu
