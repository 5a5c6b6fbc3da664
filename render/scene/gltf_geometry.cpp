#include "scene/gltf_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_names.h"
#include "scene/gltf_scene.h"
#include "scene/bounds.h"

namespace weft {

namespace {

// glTF (+Y up) to Weft (+Z up): (x, y, z) → (x, −z, y), a rotation about +x.
const glm::dmat4 kToWeft(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, -1, 0, 0),
                         glm::dvec4(0, 0, 0, 1));

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::dmat4 local_transform(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glm
  glm::dmat4 t(1.0);
  if (n.translation.size() == 3) t = glm::translate(t, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
  if (n.rotation.size() == 4) {
    glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // glTF: x, y, z, w
    const double l = glm::length(q);
    if (l > 0.0) t = t * glm::mat4_cast(q / l);
  }
  if (n.scale.size() == 3) t = glm::scale(t, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
  return t;
}

}  // namespace

// A validated view of one accessor's elements inside its buffer.
struct GltfGeometry::Accessor {
  const unsigned char* data = nullptr;
  size_t count = 0, stride = 0;
  int component_type = 0, components = 0;
  bool normalized = false;

  double component(size_t element, int c) const {
    const unsigned char* p = data + element * stride;
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
      // Normalized signed integers per glTF 2.0 (3.11): max(c / 127, −1), so that −128 is −1 too.
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = static_cast<int8_t>(p[c]);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = p[c];
        return normalized ? v / 255.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
    }
    return 0.0;
  }
};

GltfGeometry::GltfGeometry(const tinygltf::Model& model, std::string origin, std::vector<std::string>& notes)
    : m_(model), origin_(std::move(origin)), notes_(notes), groups_(model.materials.size() + 1),
      reports_(model.materials.size() + 1) {}

void GltfGeometry::fail(const std::string& what) const { throw SceneError(origin_ + ": " + what); }

GltfGeometry::Accessor GltfGeometry::accessor(int index, const std::string& where, std::initializer_list<int> types,
                                             std::initializer_list<int> component_types, Integers integers) const {
  if (index < 0 || static_cast<size_t>(index) >= m_.accessors.size())
    fail(where + ": accessor " + std::to_string(index) + " does not exist (" + std::to_string(m_.accessors.size()) +
         " accessors)");
  const tinygltf::Accessor& a = m_.accessors[index];
  const std::string at = where + " (accessor " + std::to_string(index) + ")";
  auto listed = [](auto names, auto list) {
    std::string out;
    for (int x : list) out += (out.empty() ? "" : ", ") + names(x);
    return out;
  };
  if (std::find(types.begin(), types.end(), a.type) == types.end())
    fail(at + ": wrong element type " + gltf_element_type_name(a.type) + " (expected " +
         listed(gltf_element_type_name, types) + ")");
  if (std::find(component_types.begin(), component_types.end(), a.componentType) == component_types.end())
    fail(at + ": wrong component type " + gltf_component_type_name(a.componentType) + " (expected " +
         listed(gltf_component_type_name, component_types) + ")");
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && integers == Integers::normalized && !a.normalized)
    fail(at + ": component type " + gltf_component_type_name(a.componentType) +
         " without normalized (integers here must be normalized, KHR_mesh_quantization)");
  if (integers == Integers::plain && a.normalized)
    fail(at + ": component type " + gltf_component_type_name(a.componentType) + " marked normalized (indices never are)");
  if (a.sparse.isSparse) fail(at + ": sparse accessors are not supported");
  if (a.bufferView < 0)
    fail(at + ": has no buffer view (its data would come from an extension; is the file compressed with one Weft "
              "does not read?)");
  if (static_cast<size_t>(a.bufferView) >= m_.bufferViews.size())
    fail(at + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
  const tinygltf::BufferView& v = m_.bufferViews[a.bufferView];
  if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= m_.buffers.size())
    fail(at + ": buffer " + std::to_string(v.buffer) + " does not exist");
  const size_t buffer_size = m_.buffers[v.buffer].data.size();
  if (v.byteOffset > buffer_size || v.byteLength > buffer_size - v.byteOffset)
    fail(at + ": buffer view " + std::to_string(a.bufferView) + " runs past the end of buffer " +
         std::to_string(v.buffer) + " (" + std::to_string(buffer_size) + " bytes; missing or short buffer file?)");
  Accessor d;
  d.component_type = a.componentType;
  d.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  d.normalized = a.normalized;
  d.count = a.count;
  const size_t element = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(a.componentType)) * d.components;
  d.stride = v.byteStride != 0 ? v.byteStride : element;
  if (d.stride < element) fail(at + ": byte stride " + std::to_string(d.stride) + " is smaller than an element");
  if (d.count > std::max(kGltfMaxVertices, 3 * kGltfMaxTriangles))
    fail(at + ": " + std::to_string(d.count) + " elements exceed the importer's limit");
  if (d.count == 0) fail(at + ": no elements");
  const size_t span = (d.count - 1) * d.stride + element;
  if (a.byteOffset > v.byteLength || span > v.byteLength - a.byteOffset)
    fail(at + ": " + std::to_string(d.count) + " elements run past the end of buffer view " +
         std::to_string(a.bufferView));
  d.data = m_.buffers[v.buffer].data.data() + v.byteOffset + a.byteOffset;
  return d;
}

std::vector<std::pair<int, glm::dmat4>> GltfGeometry::node_instances() const {
  const size_t n = m_.nodes.size();
  std::vector<int> roots;
  if (!m_.scenes.empty()) {
    const int s = m_.defaultScene >= 0 ? m_.defaultScene : 0;
    if (static_cast<size_t>(s) >= m_.scenes.size()) fail("scene " + std::to_string(s) + " does not exist");
    roots = m_.scenes[s].nodes;
  } else {  // no scenes: every node nobody names as a child
    std::vector<bool> child(n, false);
    for (const auto& node : m_.nodes)
      for (int c : node.children)
        if (c >= 0 && static_cast<size_t>(c) < n) child[c] = true;
    for (size_t i = 0; i < n; ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  std::vector<bool> seen(n, false);
  std::vector<std::pair<int, glm::dmat4>> stack, out;
  for (int r : roots) stack.emplace_back(r, kToWeft);
  while (!stack.empty()) {
    auto [i, parent] = stack.back();
    stack.pop_back();
    if (i < 0 || static_cast<size_t>(i) >= n) fail("node " + std::to_string(i) + " does not exist");
    if (seen[i]) fail("node " + std::to_string(i) + " is reached twice: the node hierarchy is not a tree");
    seen[i] = true;
    const tinygltf::Node& node = m_.nodes[i];
    for (double x : node.matrix)
      if (!std::isfinite(x)) fail("nodes[" + std::to_string(i) + "].matrix is not finite");
    for (const auto* v : {&node.translation, &node.rotation, &node.scale})
      for (double x : *v)
        if (!std::isfinite(x)) fail("nodes[" + std::to_string(i) + "] has a non-finite transform");
    const glm::dmat4 world = parent * local_transform(node);
    if (node.mesh >= 0 || node.camera >= 0) out.emplace_back(i, world);
    for (int c : node.children) stack.emplace_back(c, world);
  }
  return out;
}

std::optional<Camera> GltfGeometry::perspective_camera(int node, const glm::dmat4& world) const {
  const tinygltf::Node& n = m_.nodes[size_t(node)];
  if (n.camera < 0) return std::nullopt;
  if (static_cast<size_t>(n.camera) >= m_.cameras.size()) fail("camera " + std::to_string(n.camera) + " does not exist");
  const tinygltf::Camera& c = m_.cameras[n.camera];
  if (c.type != "perspective") return std::nullopt;
  const double fov = c.perspective.yfov * 180.0 / 3.14159265358979323846;
  if (!(fov > 1.0 && fov < 170.0))
    fail("cameras[" + std::to_string(n.camera) + "].yfov: must be in (1, 170) degrees, got " + std::to_string(fov));
  // A glTF camera looks down its local −Z with +Y up.
  Camera camera;
  camera.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
  const glm::dvec3 forward = glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
  const glm::dvec3 up = glm::dvec3(world * glm::dvec4(0, 1, 0, 0));
  if (!(glm::length(forward) > 1e-12) || !(glm::length(glm::cross(forward, up)) > 1e-12 * glm::length(forward)))
    fail("nodes[" + std::to_string(node) + "]: camera transform is singular");
  camera.target = camera.position + glm::normalize(forward);
  camera.up = glm::normalize(up);
  camera.fov_deg = fov;
  return camera;
}

void GltfGeometry::check_primitive(const tinygltf::Primitive& p, const std::string& where) const {
  if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES)
    fail(where + ": mode " + std::to_string(p.mode) + " (" + gltf_mode_name(p.mode) +
         ") is not TRIANGLES (4), the only mode Weft reads");
  if (p.material < -1 || p.material >= static_cast<int>(m_.materials.size()))
    fail(where + ": material " + std::to_string(p.material) + " does not exist");
}

void GltfGeometry::add_primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& fabric,
                                 const std::string& where) {
  const bool cloth = !fabric.empty();
  auto attribute = [&](const char* name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
  };
  const int pos_i = attribute("POSITION"), nrm_i = attribute("NORMAL"), uv_i = attribute("TEXCOORD_0"),
            tan_i = attribute("TANGENT");
  if (pos_i < 0) fail(where + ": no POSITION attribute");
  constexpr int F = TINYGLTF_COMPONENT_TYPE_FLOAT, B = TINYGLTF_COMPONENT_TYPE_BYTE,
                UB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, S = TINYGLTF_COMPONENT_TYPE_SHORT,
                US = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  // Integer positions and UVs (KHR_mesh_quantization) are read as numbers; the node transform
  // that the quantizer wrote scales them back.
  const Accessor pos = accessor(pos_i, where + ".POSITION", {TINYGLTF_TYPE_VEC3}, {F, B, UB, S, US});
  const size_t nv = pos.count;
  if (nv > kGltfMaxVertices - vertices_)
    fail("more than " + std::to_string(kGltfMaxVertices) + " vertices in all (the importer's limit)");

  TriangleMesh mesh;
  mesh.positions.resize(nv);
  for (size_t v = 0; v < nv; ++v) mesh.positions[v] = {pos.component(v, 0), pos.component(v, 1), pos.component(v, 2)};
  auto same_count = [&](const Accessor& a, const char* name) {
    if (a.count != nv)
      fail(where + "." + name + ": " + std::to_string(a.count) + " elements for " + std::to_string(nv) + " positions");
  };
  if (nrm_i >= 0) {
    const Accessor a = accessor(nrm_i, where + ".NORMAL", {TINYGLTF_TYPE_VEC3}, {F, B, S}, Integers::normalized);
    same_count(a, "NORMAL");
    mesh.normals.resize(nv);
    for (size_t v = 0; v < nv; ++v) mesh.normals[v] = {a.component(v, 0), a.component(v, 1), a.component(v, 2)};
  }
  if (uv_i >= 0) {
    const Accessor a = accessor(uv_i, where + ".TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, {F, B, UB, S, US});
    same_count(a, "TEXCOORD_0");
    mesh.uvs.resize(nv);
    for (size_t v = 0; v < nv; ++v) mesh.uvs[v] = {a.component(v, 0), a.component(v, 1)};
  }
  std::vector<glm::dvec3> tangents;
  if (tan_i >= 0) {
    const Accessor a = accessor(tan_i, where + ".TANGENT", {TINYGLTF_TYPE_VEC4}, {F, B, S}, Integers::normalized);
    same_count(a, "TANGENT");
    tangents.resize(nv);
    for (size_t v = 0; v < nv; ++v) {
      tangents[v] = {a.component(v, 0), a.component(v, 1), a.component(v, 2)};
      if (!finite(tangents[v])) fail(where + ".TANGENT: vertex " + std::to_string(v) + " is not finite (NaN/Inf)");
    }
  }
  // Cloth with neither: the importer's fixed warp (compute_warp_directions) and no weave, which
  // needs UVs to lay its threads out; the fabric level needs only a frame.
  if (cloth && tangents.empty() && mesh.uvs.empty())
    notes_.push_back(where + ": cloth (fabric '" + fabric +
                     "') without TANGENT or TEXCOORD_0: its warp is a fixed direction (x × its normal), and no "
                     "weave is drawn up close");

  if (p.indices >= 0) {
    const Accessor a = accessor(p.indices, where + ".indices", {TINYGLTF_TYPE_SCALAR},
                                    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                    Integers::plain);
    if (a.count % 3 != 0) fail(where + ".indices: " + std::to_string(a.count) + " indices are not whole triangles");
    if (a.count / 3 > kGltfMaxTriangles - triangles_)
      fail("more than " + std::to_string(kGltfMaxTriangles) + " triangles in all (the importer's limit)");
    mesh.triangles.resize(a.count / 3);
    for (size_t t = 0; t < a.count / 3; ++t)
      for (int k = 0; k < 3; ++k) {
        const double idx = a.component(3 * t + k, 0);
        if (idx >= static_cast<double>(nv))
          fail(where + ".indices: index " + std::to_string(static_cast<uint64_t>(idx)) + " is out of range (" +
               std::to_string(nv) + " vertices)");
        mesh.triangles[t][k] = static_cast<uint32_t>(idx);
      }
  } else {
    if (nv % 3 != 0) fail(where + ": " + std::to_string(nv) + " unindexed vertices are not whole triangles");
    mesh.triangles.resize(nv / 3);
    for (size_t t = 0; t < nv / 3; ++t)
      mesh.triangles[t] = {uint32_t(3 * t), uint32_t(3 * t + 1), uint32_t(3 * t + 2)};
  }

  // Into Weft's frame: points by the world matrix, normals by its inverse transpose, tangents
  // by its linear part; a mirroring transform flips the winding so that faces keep their side.
  const glm::dmat3 linear(world);
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  if (!(std::abs(glm::determinant(linear)) > 0.0)) fail(where + ": its node transform is singular");
  for (auto& q : mesh.positions) q = glm::dvec3(world * glm::dvec4(q, 1.0));
  for (auto& q : mesh.normals) q = normal_matrix * q;
  for (auto& q : tangents) q = linear * q;
  if (glm::determinant(linear) < 0.0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);

  MeshRepairReport report;
  try {
    // UV-degenerate triangles matter only where the warp comes from the UVs.
    report = repair_mesh(mesh, cloth && tangents.empty() && !mesh.uvs.empty(), where);
    if (mesh.normals.empty()) compute_vertex_normals(mesh);
    for (size_t v = 0; v < nv; ++v) {
      const double l = glm::length(mesh.normals[v]);
      if (!(l > 1e-12)) fail(where + ".NORMAL: vertex " + std::to_string(v) + " has a zero-length normal");
      mesh.normals[v] /= l;
    }
    if (tangents.empty()) {
      compute_warp_directions(mesh);
    } else {
      mesh.warps = std::move(tangents);
      // A TANGENT along the normal (or NaN) gets a fixed warp: any keeps the frame valid.
      for (size_t v = 0; v < nv; ++v) mesh.warps[v] = unit_tangent(mesh.warps[v], mesh.normals[v]);
    }
  } catch (const MeshError& e) {
    fail(e.what());
  }

  // Merge into the material's object.
  TriangleMesh& g = groups_[p.material + 1];
  if (const MeshOrientation o = mesh_orientation(mesh); o.closed && o.inward()) {
    const Bounds b = bounds_of(mesh.positions);
    InwardPart part{size_t(p.material + 1), g.positions.size(), mesh.positions.size(), g.triangles.size(),
                    mesh.triangles.size(), b.lo, b.hi, o, where};
    inward_.push_back(std::move(part));
  }
  MeshRepairReport& r = reports_[p.material + 1];
  r.degenerate_triangles_dropped += report.degenerate_triangles_dropped;
  r.unused_vertices += report.unused_vertices;
  const uint32_t base = static_cast<uint32_t>(g.positions.size());
  const bool had_uvs = g.positions.empty() || !g.uvs.empty();
  g.positions.insert(g.positions.end(), mesh.positions.begin(), mesh.positions.end());
  g.normals.insert(g.normals.end(), mesh.normals.begin(), mesh.normals.end());
  g.warps.insert(g.warps.end(), mesh.warps.begin(), mesh.warps.end());
  if (had_uvs && !mesh.uvs.empty())
    g.uvs.insert(g.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
  else
    g.uvs.clear();  // UVs are kept only where every merged primitive has them
  for (const auto& t : mesh.triangles) g.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  vertices_ += nv;
  triangles_ += mesh.triangles.size();
}

void GltfGeometry::turn_inward_parts(const std::optional<glm::dvec3>& camera) {
  for (const InwardPart& part : inward_) {
    const std::string what = std::string(part.orientation.normals_inward ? "normals" : "") +
                             (part.orientation.normals_inward && part.orientation.winding_inward ? " and " : "") +
                             (part.orientation.winding_inward ? "winding" : "");
    if (camera && glm::all(glm::greaterThanEqual(*camera, part.lo)) && glm::all(glm::lessThanEqual(*camera, part.hi))) {
      notes_.push_back(part.where + ": a closed part whose " + what + " point inwards, kept so: the camera is inside it");
      continue;
    }
    TriangleMesh& g = groups_[part.group];
    turn_outward(std::span(g.triangles).subspan(part.first_triangle, part.triangles),
                 std::span(g.normals).subspan(part.first_vertex, part.vertices), part.orientation);
    notes_.push_back(part.where + ": a closed part whose " + what +
                     " pointed inwards (its shading and shadows would come from inside it): turned outwards");
  }
}

}  // namespace weft
