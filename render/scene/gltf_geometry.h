#pragma once
// The glTF importer's geometry (gltf_scene.h): the node hierarchy's world transforms in Weft's
// frame, cameras, and each triangle primitive's attributes decoded, checked, repaired and merged
// into its material slot's mesh (gltf_materials.h's slots).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/mesh_orientation.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace weft {

class GltfGeometry {
public:
  // Messages start with `origin`; remarks for the log go to `notes`, which must outlive this.
  GltfGeometry(const tinygltf::Model& model, std::string origin, std::vector<std::string>& notes);

  // Every node with a mesh or a camera and its world transform (in Weft's frame), walking the
  // default scene's roots (without scenes, every node no other names as a child). A node reached
  // twice (the hierarchy is not a tree) or a non-finite transform is refused.
  std::vector<std::pair<int, glm::dmat4>> node_instances() const;
  // Node `node`'s camera seen from `world` when it is a perspective one, none otherwise.
  std::optional<Camera> perspective_camera(int node, const glm::dmat4& world) const;

  // Refuses a primitive that is not triangles or names a material the file lacks.
  void check_primitive(const tinygltf::Primitive& p, const std::string& where) const;
  // Decodes primitive `p` (checked) at `world` and merges it into its material slot's mesh;
  // `fabric` is the slot's ("" for Lambertian), for the repair and the log.
  void add_primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& fabric,
                     const std::string& where);
  // Turns the closed parts whose normals or winding point into them outwards, except one the
  // camera (when the file places one) stands inside: a room seen from within.
  void turn_inward_parts(const std::optional<glm::dvec3>& camera);

  // Slot `slot`'s merged mesh (empty when no primitive wears it), moved out, and its repairs.
  TriangleMesh take_mesh(size_t slot) { return std::move(groups_[slot]); }
  bool has_triangles(size_t slot) const { return !groups_[slot].triangles.empty(); }
  const MeshRepairReport& repair(size_t slot) const { return reports_[slot]; }

private:
  [[noreturn]] void fail(const std::string& what) const;
  struct Accessor;
  // Integer components: whether the accessor must say normalized (NORMAL, TANGENT), must not
  // (indices), or either (POSITION, TEXCOORD_0: KHR_mesh_quantization).
  enum class Integers { normalized, plain, either };
  Accessor accessor(int index, const std::string& where, std::initializer_list<int> types,
                    std::initializer_list<int> component_types, Integers integers = Integers::either) const;

  // A closed primitive whose normals or winding point into it (mesh_orientation.h), turned once
  // the camera is known.
  struct InwardPart {
    size_t group = 0, first_vertex = 0, vertices = 0, first_triangle = 0, triangles = 0;
    glm::dvec3 lo{0.0}, hi{0.0};
    MeshOrientation orientation;
    std::string where;
  };

  const tinygltf::Model& m_;
  std::string origin_;
  std::vector<std::string>& notes_;
  std::vector<TriangleMesh> groups_;  // per material slot
  std::vector<MeshRepairReport> reports_;
  std::vector<InwardPart> inward_;
  size_t vertices_ = 0, triangles_ = 0;  // so far, against the importer's caps
};

}  // namespace weft
