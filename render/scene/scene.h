#pragma once
// A showroom scene: camera, default lighting, and objects (cloth with a fabric, or Lambertian
// occluders with an albedo) whose meshes are generated from the parameters in the scene file.
// Format: assets/scenes/README.md.
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/fabric.h"
#include "image/texture_image.h"
#include "scene/mesh.h"

namespace weft {

// A scene file that cannot be used; what() names the file, the field and the problem.
class SceneError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct Camera {
  glm::dvec3 position{0, -3, 1};
  glm::dvec3 target{0, 0, 0};
  glm::dvec3 up{0, 0, 1};
  double fov_deg = 40.0;  // vertical field of view
};

// Unit direction of the pinhole ray through image point (px, py) of a width×height image;
// (0,0) is the top-left corner, pixel (x, y)'s centre is (x+½, y+½).
glm::dvec3 camera_ray(const Camera& camera, int width, int height, double px, double py);
// A camera that can be used: field of view within (1, 170) degrees, eye and target apart, up not
// along the view. Throws SceneError naming `where` and the problem.
void check_camera(const Camera& camera, const std::string& where);

enum class Material { cloth, lambertian };

// Where a texture is read for a mesh UV: KHR_texture_transform's uv' = T(offset)·R(rotation)·S(scale)·uv,
// that is u' = o_x + s_x·cos r·u + s_y·sin r·v, v' = o_y − s_x·sin r·u + s_y·cos r·v.
struct TextureTransform {
  glm::dvec2 offset{0.0}, scale{1.0};
  double rotation = 0.0;  // radians
  bool operator==(const TextureTransform&) const = default;
};
glm::dvec2 transformed_uv(const TextureTransform& t, glm::dvec2 uv);
// The same as the 3×3 matrix (column-major, as GLSL's mat3) acting on (u, v, 1).
glm::dmat3 texture_matrix(const TextureTransform& t);

// A texture on a cloth's threads: the thread's albedo is multiplied by the texel (linear RGB) at
// the point's UV, so a knob's colour edit recolours the pattern relative to it. `image` may be
// shared by several objects; `name` names it in messages and the bundle.
struct ThreadMap {
  std::shared_ptr<const TextureImage> image;
  std::string name;
  TextureTransform transform;
};
// A cloth's normal map (glTF normalTexture): tangent-space normals stored linearly (not sRGB), x and
// y times `scale`, read through the map's transform. Applied per pixel as seed 002 does
// (core/normal_map_frame.h: the threads' frame turned with the normal).
struct NormalMap {
  ThreadMap map;
  double scale = 1.0;
};
// The most texture images a scene may hold (the bundle's scene section lists them).
inline constexpr size_t kMaxSceneTextures = 64;

struct SceneObject {
  std::string name;
  Material material = Material::lambertian;
  std::string fabric;        // cloth: preset name
  std::optional<glm::dvec3> colour;  // cloth: the product's colour on the threads (object_base_fabric); none: the fabric's own
  double optical_thickness = 0.0;  // cloth: > 0 overrides the fabric's τ (object_fabric)
  glm::dvec2 weave_repeats_per_uv{0.0};  // cloth: > 0 sets the weave's repeats per UV unit (scene/weave_scale.h)
  // cloth: the kiosk label's text for this object, over its fabric's when not empty (glTF
  // extras.weft.display_name and .composition; core/fabric.h's rules).
  std::string display_name, composition;
  // cloth: per thread (warp, weft) its texture, none: untextured. A single map (glTF
  // baseColorTexture) is on both; extras.weft.weft_texture (or a scene's "weft_texture") gives
  // the weft its own.
  std::array<std::optional<ThreadMap>, 2> thread_maps;
  std::optional<NormalMap> normal_map;  // cloth: none, the surface's own normals
  glm::dvec3 albedo{0.5};    // lambertian
  TriangleMesh mesh;
  MeshRepairReport repair;
  bool is_cloth() const { return material == Material::cloth; }
  bool textured() const { return thread_maps[0] || thread_maps[1]; }
};

// What thread j's albedo is multiplied by at mesh UV `uv`: the texel of its map (linear RGB,
// sample_texture), or 1 without one.
glm::dvec3 thread_tint(const SceneObject& o, int thread, glm::dvec2 uv);

// The unit tangent-space normal of o's normal map at mesh UV `uv` (sample_stored_texture, then
// tangent_space_normal), or (0, 0, 1) without one.
glm::dvec3 normal_map_tangent(const SceneObject& o, glm::dvec2 uv);

// The most weave repeats per UV unit a scene or glTF may give.
inline constexpr double kMaxWeaveRepeatsPerUv = 1e6;

// The fabric cloth object `o` is drawn with: `fabric` (its base fabric, or a knob's edit of it) with
// the object's own overrides (its optical thickness, when it gives one). The colour is not among
// them: a knob's colour edit must win.
Fabric object_fabric(const SceneObject& o, Fabric fabric);
// The fabric cloth object `o` starts from, the one source of its look for the bake, the reference,
// every method and the knobs: its preset `fabric` in the object's colour (product_coloured), when
// it has one. The map form looks the preset up by o.fabric (std::out_of_range naming it if absent).
Fabric object_base_fabric(const SceneObject& o, Fabric fabric);
Fabric object_base_fabric(const SceneObject& o, const std::map<std::string, Fabric>& fabrics);

// A colour as a scene, glTF or colourway gives it: three finite numbers in [0, 1]. Throws
// SceneError naming `where` and the problem.
glm::dvec3 product_colour(const std::vector<double>& rgb, const std::string& where);

// The cloth objects among a scene's objects, in order (Scene::cloth_objects). Hand-written
// rather than std::views::filter: the fuzz build's clang 14 cannot compile libstdc++ 12's ranges.
template <class Object>
class ClothObjects {
public:
  class iterator {
  public:
    iterator(Object* at, Object* end) : at_(at), end_(end) { skip(); }
    Object& operator*() const { return *at_; }
    Object* operator->() const { return at_; }
    iterator& operator++() {
      ++at_;
      skip();
      return *this;
    }
    bool operator==(const iterator& other) const { return at_ == other.at_; }

  private:
    void skip() {
      while (at_ != end_ && !at_->is_cloth()) ++at_;
    }
    Object* at_;
    Object* end_;
  };
  ClothObjects(Object* first, Object* last) : first_(first), last_(last) {}
  iterator begin() const { return iterator(first_, last_); }
  iterator end() const { return iterator(last_, last_); }
  bool empty() const { return begin() == end(); }

private:
  Object* first_;
  Object* last_;
};

// What a colourway dresses one cloth object in: a fabric (preset name or file) and the product's
// colour on it (none: the fabric's own).
struct ClothLook {
  std::string fabric;
  std::optional<glm::dvec3> colour;
  bool operator==(const ClothLook&) const = default;
};

// One of a product's colourways (a glTF's KHR_materials_variants variant, a scene file's
// "colourways" entry): new looks for some cloth objects, by object name; the others keep the
// scene's own. A colourway that changes colours only needs no tables of its own: the weighting
// tables are per fabric, the colour multiplies them at run time.
struct Colourway {
  std::string name;
  std::map<std::string, ClothLook> objects;
};

struct Scene {
  std::string name;
  std::string description;
  Camera camera;
  std::optional<Camera> closeup;  // the close-up the kiosk's zoom moves to (a scene's "closeup_camera")
  std::string environment;   // env map name (assets/envmaps/NAME.exr); the scene is laid out
                             // around its bright directions (e.g. the curtain's window)
  std::vector<SceneObject> objects;
  std::vector<Colourway> colourways;  // none: the scene has its own look only
  std::vector<std::string> warnings;  // what an importer let through with a remark, for the log
  // The cloth objects in order, a view of `objects`: the k-th is the renderer's cloth object k
  // (gpu::SceneRenderer takes their fabrics in this order).
  ClothObjects<const SceneObject> cloth_objects() const& { return {objects.data(), objects.data() + objects.size()}; }
  ClothObjects<SceneObject> cloth_objects() & { return {objects.data(), objects.data() + objects.size()}; }
  void cloth_objects() const&& = delete;  // a view of a temporary would dangle
};

// The look of every cloth object in order (Scene::cloth_objects) as the scene has it.
std::vector<ClothLook> cloth_looks(const Scene& s);
// The looks colourway `k` gives the cloth objects, in order: its own where it names the object,
// `base`'s (cloth_looks of the scene without a colourway) elsewhere.
std::vector<ClothLook> colourway_looks(const Scene& s, const std::vector<ClothLook>& base, size_t k);
// Dresses the cloth objects in `looks` (one per cloth object, in order).
void wear_looks(Scene& s, const std::vector<ClothLook>& looks);
// Every fabric the scene's cloth wears, in its own look or in a colourway's, each once in order
// of first use: the fabrics a bake needs tables for.
std::vector<std::string> worn_fabrics(const Scene& s);
// Checks colourways against the scene's cloth objects: a name each, unique; at least one object
// each, every one a cloth object of the scene, with a fabric. Throws SceneError starting with
// `origin`, naming the colourway and the problem.
void check_colourways(const Scene& s, const std::string& origin);

}  // namespace weft
