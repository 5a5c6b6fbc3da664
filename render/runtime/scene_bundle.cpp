#include "runtime/scene_bundle.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "lighting/sg_set_io.h"
#include "scene/object_schema.h"
#include "scene/vertex_pass_mesh.h"

namespace weft {

namespace scene_section {
std::string mesh(size_t object, const char* attribute) {
  return "mesh/" + std::to_string(object) + "/" + attribute;
}
std::string texture(size_t index) { return "texture/" + std::to_string(index); }
}  // namespace scene_section

namespace {

using nlohmann::json;

bundle::BundleError bad(const bundle::BundleReader& r, const std::string& section, const std::string& detail) {
  return bundle::BundleError(r.origin(), "section '" + section + "'", section, detail);
}

json parse_json(const bundle::BundleReader& r, const std::string& section) {
  try {
    return json::parse(r.json(section));
  } catch (const json::exception& e) {
    throw bad(r, section, std::string("not valid JSON: ") + e.what());
  }
}

glm::dvec3 read_vec3(const bundle::BundleReader& r, const std::string& section, const json& j) {
  if (!j.is_array() || j.size() != 3) throw bad(r, section, "expected a 3-vector, got " + j.dump());
  glm::dvec3 v;
  for (int k = 0; k < 3; ++k) {
    if (!j[k].is_number() || !std::isfinite(j[k].get<double>())) throw bad(r, section, "non-finite vector " + j.dump());
    v[k] = j[k].get<double>();
  }
  return v;
}

// An [n, width] f32 section as n vectors; n must equal `expected_rows` unless that is 0 (any).
template <class V>
std::vector<V> read_rows(const bundle::BundleReader& r, const std::string& name, int width, size_t expected_rows) {
  const auto& info = r.section(name);
  const auto values = r.array<float>(name);
  if (info.shape.size() != 2 || info.shape[1] != static_cast<uint64_t>(width) ||
      (expected_rows && info.shape[0] != expected_rows))
    throw bad(r, name, "expected shape [" + (expected_rows ? std::to_string(expected_rows) : std::string("n")) +
                           ", " + std::to_string(width) + "]");
  std::vector<V> out(info.shape[0]);
  for (size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < width; ++k) {
      const float x = values[i * width + k];
      if (!std::isfinite(x)) throw bad(r, name, "non-finite value in row " + std::to_string(i));
      out[i][k] = x;
    }
  return out;
}

// Object i's per-vertex passes' vertices (scene/vertex_pass_mesh.h) for its n mesh vertices: pass
// vertices ascending and below n, three corners per mesh vertex below the pass's count, weights
// finite, not negative, summing to 1.
std::shared_ptr<const VertexPassMesh> read_pass_mesh(const bundle::BundleReader& r, size_t i, size_t n) {
  VertexPassMesh p;
  const std::string vs = scene_section::mesh(i, "pass_vertices"), cs = scene_section::mesh(i, "pass_corners"),
                    ws = scene_section::mesh(i, "pass_weights");
  const auto& vinfo = r.section(vs);
  if (vinfo.shape.size() != 1 || vinfo.shape[0] == 0) throw bad(r, vs, "expected shape [p], p > 0");
  const auto vertices = r.array<uint32_t>(vs);
  p.vertices.assign(vertices.begin(), vertices.end());
  for (size_t k = 0; k < p.vertices.size(); ++k)
    if (p.vertices[k] >= n || (k > 0 && p.vertices[k] <= p.vertices[k - 1]))
      throw bad(r, vs, "pass vertex " + std::to_string(k) + " is not a mesh vertex in ascending order");
  const auto& cinfo = r.section(cs);
  if (cinfo.shape.size() != 2 || cinfo.shape[0] != n || cinfo.shape[1] != 3) throw bad(r, cs, "expected shape [n, 3], n the mesh's vertices");
  const auto corners = r.array<uint32_t>(cs);
  const std::vector<glm::dvec3> weights = read_rows<glm::dvec3>(r, ws, 3, n);
  p.corners.resize(n);
  p.weights.resize(n);
  for (size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      p.corners[v][k] = corners[v * 3 + k];
      if (p.corners[v][k] >= p.vertices.size()) throw bad(r, cs, "vertex " + std::to_string(v) + " blends a corner past the pass vertices");
    }
    const glm::dvec3 w = weights[v];
    if (!(w.x >= -1e-4 && w.y >= -1e-4 && w.z >= -1e-4) || !(std::abs(w.x + w.y + w.z - 1.0) <= 1e-3))
      throw bad(r, ws, "vertex " + std::to_string(v) + ": weights that are not a blend");
    p.weights[v] = glm::vec3(w);
  }
  return std::make_shared<const VertexPassMesh>(std::move(p));
}

// The scene's "textures": each decoded from its section's PNG, its size as the list says.
std::vector<SectionTexture> read_textures(const bundle::BundleReader& r, const json& j) {
  std::vector<SectionTexture> out;
  if (!j.contains("textures")) return out;
  const json& list = j.at("textures");
  const std::string S = scene_section::kScene;
  if (!list.is_array() || list.empty() || list.size() > kMaxSceneTextures)
    throw bad(r, S, "textures: expected a list of 1 to " + std::to_string(kMaxSceneTextures) + " images");
  for (size_t n = 0; n < list.size(); ++n) {
    const std::string name = scene_section::texture(n);
    const auto& info = r.section(name);  // throws naming it when absent
    if (info.type != bundle::ElementType::U8 || info.shape.size() != 1)
      throw bad(r, name, "expected the bytes of a PNG (u8, rank 1)");
    const auto bytes = r.array<std::uint8_t>(name);
    TextureImage image;
    try {
      image = decode_texture(std::span<const std::uint8_t>(bytes.data(), bytes.size()), "texture");
    } catch (const TextureError& e) {
      throw bad(r, name, e.what());
    }
    const json& t = list[n];
    if (t.at("width").get<long>() != image.width || t.at("height").get<long>() != image.height)
      throw bad(r, name, "the image is " + std::to_string(image.width) + "×" + std::to_string(image.height) +
                             ", the scene section says " + t.at("width").dump() + "×" + t.at("height").dump());
    out.push_back({std::make_shared<const TextureImage>(std::move(image)), t.at("name").get<std::string>()});
  }
  return out;
}

}  // namespace

SceneBundle read_scene_bundle(const bundle::BundleReader& r) {
  SceneBundle out;
  const std::string F = scene_section::kFabrics;
  const json fabrics = parse_json(r, F);
  if (!fabrics.is_object() || fabrics.empty()) throw bad(r, F, "expected an object of fabric presets");
  for (const auto& [name, fj] : fabrics.items()) {
    const std::string text = fj.dump();
    try {
      out.fabrics.emplace(name, parse_fabric(text, r.origin() + ":" + F + "." + name));
    } catch (const std::exception& e) {
      throw bad(r, F, e.what());
    }
    out.fabric_json.emplace(name, text);
  }
  const std::string S = scene_section::kScene;
  const json j = parse_json(r, S);
  try {
    if (j.value("format", "") != "weft-scene-bundle" || j.value("version", 0) != 1)
      throw bad(r, S, "not a weft-scene-bundle version 1 description");
    Scene& s = out.scene;
    s.name = j.at("name").get<std::string>();
    s.description = j.value("description", "");
    s.environment = j.value("environment", "");
    auto camera = [&](const json& c, const std::string& what) {
      Camera cam;
      cam.position = read_vec3(r, S, c.at("position"));
      cam.target = read_vec3(r, S, c.at("target"));
      cam.up = read_vec3(r, S, c.at("up"));
      cam.fov_deg = c.at("fov_deg").get<double>();
      if (!(cam.fov_deg > 0 && cam.fov_deg < 180)) throw bad(r, S, what + " fov_deg out of (0, 180)");
      if (!(glm::length(cam.target - cam.position) > 1e-9)) throw bad(r, S, what + ": position and target coincide");
      return cam;
    };
    s.camera = camera(j.at("camera"), "camera");
    if (j.contains("closeup_camera")) s.closeup = camera(j.at("closeup_camera"), "closeup_camera");
    const std::vector<SectionTexture> textures = read_textures(r, j);
    const json& objects = j.at("objects");
    if (!objects.is_array() || objects.empty()) throw bad(r, S, "no objects");
    for (size_t i = 0; i < objects.size(); ++i) {
      SceneObject o;
      try {
        o = read_scene_object(objects[i], "objects[" + std::to_string(i) + "]", textures);
      } catch (const SceneError& e) {
        throw bad(r, S, e.what());
      }
      if (o.is_cloth() && !out.fabrics.count(o.fabric))
        throw bad(r, F, "no fabric '" + o.fabric + "' for object '" + o.name + "'");
      TriangleMesh& m = o.mesh;
      m.positions = read_rows<glm::dvec3>(r, scene_section::mesh(i, "positions"), 3, 0);
      const size_t n = m.positions.size();
      m.normals = read_rows<glm::dvec3>(r, scene_section::mesh(i, "normals"), 3, n);
      if (r.has(scene_section::mesh(i, "uvs"))) m.uvs = read_rows<glm::dvec2>(r, scene_section::mesh(i, "uvs"), 2, n);
      if (r.has(scene_section::mesh(i, "warps")))
        m.warps = read_rows<glm::dvec3>(r, scene_section::mesh(i, "warps"), 3, n);
      if ((o.textured() || o.normal_map) && m.uvs.empty())
        throw bad(r, scene_section::mesh(i, "uvs"), "textured cloth object '" + o.name + "' has no UVs");
      if (o.material == Material::cloth && m.warps.empty())
        throw bad(r, scene_section::mesh(i, "warps"), "cloth object '" + o.name + "' has no warp directions");
      const std::string is = scene_section::mesh(i, "indices");
      const auto& info = r.section(is);
      const auto idx = r.array<uint32_t>(is);
      if (info.shape.size() != 2 || info.shape[1] != 3 || info.shape[0] == 0) throw bad(r, is, "expected shape [t, 3], t > 0");
      m.triangles.resize(info.shape[0]);
      for (size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
          const uint32_t v = idx[t * 3 + k];
          if (v >= n) throw bad(r, is, "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                                           " of " + std::to_string(n));
          m.triangles[t][k] = v;
        }
      if (r.has(scene_section::mesh(i, "pass_vertices"))) m.pass = read_pass_mesh(r, i, n);
      s.objects.push_back(std::move(o));
    }
    if (j.contains("colourways")) {
      const json& cs = j.at("colourways");
      if (!cs.is_array() || cs.empty()) throw bad(r, S, "colourways: expected a non-empty list");
      for (size_t k = 0; k < cs.size(); ++k) {
        const json& jc = cs[k];
        Colourway c;
        c.name = jc.at("name").get<std::string>();
        for (const auto& [object, jl] : jc.at("objects").items()) {
          ClothLook look;
          look.fabric = jl.at("fabric").get<std::string>();
          if (!out.fabrics.count(look.fabric))
            throw bad(r, F, "no fabric '" + look.fabric + "' for colourway '" + c.name + "'");
          if (jl.contains("colour")) {
            const std::string where = "colourways[" + std::to_string(k) + "] ('" + c.name + "').objects." + object + ".colour";
            try {
              look.colour = colour_from_json(jl.at("colour"), where);
            } catch (const SceneError& e) {
              throw bad(r, S, e.what());
            }
          }
          c.objects[object] = look;
        }
        s.colourways.push_back(std::move(c));
      }
      try {
        check_colourways(s, "colourways");
      } catch (const SceneError& e) {
        throw bad(r, S, e.what());
      }
    }
  } catch (const json::exception& e) {
    throw bad(r, S, std::string("bad field: ") + e.what());
  }
  const json sg = parse_json(r, scene_section::kSgs);
  try {
    out.sgs = sg_set_from_json(sg, r.origin() + ":" + scene_section::kSgs);
  } catch (const std::exception& e) {
    throw bad(r, scene_section::kSgs, e.what());
  }
  return out;
}

SceneBundle load_scene_bundle(const std::filesystem::path& file) {
  return read_scene_bundle(bundle::BundleReader::open(file));
}

}  // namespace weft
