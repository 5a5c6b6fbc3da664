#include "bake/writers/scene_bundle_writer.h"

#include <nlohmann/json.hpp>

#include "lighting/sg_set_io.h"
#include "scene/object_schema.h"
#include "scene/vertex_pass_mesh.h"

namespace weft {

namespace {

using nlohmann::json;

json vec3(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

template <class V>
std::vector<float> flatten(const std::vector<V>& values, int n) {
  std::vector<float> out;
  out.reserve(values.size() * n);
  for (const auto& v : values)
    for (int k = 0; k < n; ++k) out.push_back(static_cast<float>(v[k]));
  return out;
}

}  // namespace

size_t mesh_section_bytes(const TriangleMesh& m) {
  const size_t per_vertex = 3 + 3 + (m.uvs.empty() ? 0 : 2) + (m.warps.empty() ? 0 : 3);  // floats
  return 4 * (per_vertex * m.positions.size() + 3 * m.triangles.size());
}

void add_scene_sections(bundle::BundleWriter& writer, const SceneBundleInput& in) {
  const Scene& s = in.scene;
  json scene;
  scene["format"] = "weft-scene-bundle";
  scene["version"] = 1;
  scene["name"] = s.name;
  scene["description"] = s.description;
  scene["environment"] = s.environment;
  scene["camera"] = {{"position", vec3(s.camera.position)}, {"target", vec3(s.camera.target)},
                     {"up", vec3(s.camera.up)}, {"fov_deg", s.camera.fov_deg}};
  if (s.closeup)
    scene["closeup_camera"] = {{"position", vec3(s.closeup->position)}, {"target", vec3(s.closeup->target)},
                               {"up", vec3(s.closeup->up)}, {"fov_deg", s.closeup->fov_deg}};
  // Each image once, in order of first use: its PNG in section texture/<n>.
  std::map<const TextureImage*, size_t> texture_index;
  json textures = json::array();
  // A normal map's image is stored the same way; its object's "normal_map" says it is read linearly.
  for (const SceneObject& o : s.objects)
    for (const auto& m : {o.thread_maps[0], o.thread_maps[1],
                          o.normal_map ? std::optional<ThreadMap>(o.normal_map->map) : std::nullopt}) {
      if (!m || texture_index.count(m->image.get())) continue;
      const size_t n = texture_index.size();
      texture_index.emplace(m->image.get(), n);
      const std::vector<std::uint8_t> png = encode_png(*m->image);
      writer.add_array<std::uint8_t>(scene_section::texture(n), png, {png.size()});
      textures.push_back({{"name", m->name}, {"width", m->image->width}, {"height", m->image->height}});
    }
  if (!textures.empty()) scene["textures"] = textures;
  json objects = json::array();
  for (size_t i = 0; i < s.objects.size(); ++i) {
    const SceneObject& o = s.objects[i];
    if (o.is_cloth() && !in.fabrics.count(o.fabric))
      throw std::invalid_argument("scene bundle: no fabric text for '" + o.fabric + "' (object " + o.name + ")");
    objects.push_back(write_scene_object(o, [&](const ThreadMap& m) { return texture_index.at(m.image.get()); }));
    const TriangleMesh& m = o.mesh;
    const uint64_t n = m.positions.size();
    writer.add_array<float>(scene_section::mesh(i, "positions"), flatten(m.positions, 3), {n, 3});
    writer.add_array<float>(scene_section::mesh(i, "normals"), flatten(m.normals, 3), {n, 3});
    if (!m.uvs.empty()) writer.add_array<float>(scene_section::mesh(i, "uvs"), flatten(m.uvs, 2), {n, 2});
    if (!m.warps.empty()) writer.add_array<float>(scene_section::mesh(i, "warps"), flatten(m.warps, 3), {n, 3});
    std::vector<uint32_t> idx;
    idx.reserve(m.triangles.size() * 3);
    for (const auto& t : m.triangles) idx.insert(idx.end(), t.begin(), t.end());
    writer.add_array<uint32_t>(scene_section::mesh(i, "indices"), idx, {m.triangles.size(), 3});
    if (m.pass && !m.pass->whole() && m.pass->corners.size() == n) {  // the per-vertex passes' vertices
      const VertexPassMesh& p = *m.pass;
      writer.add_array<uint32_t>(scene_section::mesh(i, "pass_vertices"), p.vertices, {p.vertices.size()});
      std::vector<uint32_t> corners;
      std::vector<float> weights;
      for (size_t v = 0; v < n; ++v) {
        corners.insert(corners.end(), p.corners[v].begin(), p.corners[v].end());
        weights.insert(weights.end(), {p.weights[v].x, p.weights[v].y, p.weights[v].z});
      }
      writer.add_array<uint32_t>(scene_section::mesh(i, "pass_corners"), corners, {n, 3});
      writer.add_array<float>(scene_section::mesh(i, "pass_weights"), weights, {n, 3});
    }
  }
  scene["objects"] = objects;
  if (!s.colourways.empty()) {
    json colourways = json::array();
    for (const Colourway& c : s.colourways) {
      json looks = json::object();
      for (const auto& [object, look] : c.objects) {
        if (!in.fabrics.count(look.fabric))
          throw std::invalid_argument("scene bundle: no fabric text for '" + look.fabric + "' (colourway " + c.name + ")");
        json jl{{"fabric", look.fabric}};
        if (look.colour) jl["colour"] = vec3(*look.colour);
        looks[object] = jl;
      }
      colourways.push_back({{"name", c.name}, {"objects", looks}});
    }
    scene["colourways"] = colourways;
  }
  writer.add_json(scene_section::kScene, scene.dump(2));
  json fabrics = json::object();
  for (const auto& [name, text] : in.fabrics) fabrics[name] = json::parse(text);
  writer.add_json(scene_section::kFabrics, fabrics.dump(2));
  writer.add_json(scene_section::kSgs, sg_set_to_json(in.sgs).dump(2));
}

}  // namespace weft
