#include "scene/scene_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/preset_names.h"
#include "scene/gltf_scene.h"
#include "scene/object_schema.h"
#include "scene/procedural_meshes.h"
#include "scene/thread_maps.h"

namespace weft {

namespace {

using json = nlohmann::json;

std::string read_text(const std::filesystem::path& file, const char* what) {
  std::ifstream in(file);
  if (!in) throw SceneError(std::string("cannot open ") + what + " " + file.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Field readers: `where` is "file: objects[2].mesh" style; messages name the field.
const json& field(const json& j, const std::string& key, const std::string& where) {
  if (!j.is_object()) throw SceneError(where + ": expected an object");
  auto it = j.find(key);
  if (it == j.end()) throw SceneError(where + ": missing field '" + key + "'");
  return *it;
}

double number(const json& v, const std::string& where) {
  if (!v.is_number()) throw SceneError(where + ": expected a number, got " + v.dump());
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw SceneError(where + ": not a finite number");
  return x;
}

double number_or(const json& j, const std::string& key, double fallback, const std::string& where, double lo,
                 double hi) {
  if (!j.contains(key)) return fallback;
  const double x = number(j[key], where + "." + key);
  if (x < lo || x > hi)
    throw SceneError(where + "." + key + ": " + std::to_string(x) + " is outside [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return x;
}

glm::dvec3 vec3(const json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 3) throw SceneError(where + ": expected [x, y, z], got " + v.dump());
  return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
}

std::string text(const json& v, const std::string& where) {
  if (!v.is_string()) throw SceneError(where + ": expected a string, got " + v.dump());
  return v.get<std::string>();
}

TriangleMesh generate_mesh(const json& m, const std::string& where, const std::filesystem::path& base_dir) {
  const std::string gen = text(field(m, "generator", where), where + ".generator");
  auto num = [&](const char* key, double fallback, double lo, double hi) {
    return number_or(m, key, fallback, where, lo, hi);
  };
  auto res = [&](double fallback) { return static_cast<int>(num("resolution", fallback, 1, 256)); };
  TriangleMesh mesh;
  if (gen == "swatch") {
    mesh = swatch_mesh(num("size", 1.0, 1e-3, 1e3), res(16));
  } else if (gen == "quad") {
    const double sx = num("size_x", 10.0, 1e-3, 1e4), sy = num("size_y", 10.0, 1e-3, 1e4);
    if (m.contains("fine_size")) {  // graded for per-vertex shadows (procedural_meshes.h)
      const double fine = num("fine_size", 1.0, 1e-3, 1e4), spacing = num("fine_spacing", 0.05, 1e-3, 1e3);
      if (std::min(fine, std::max(sx, sy)) / spacing > 512)
        throw SceneError(where + ": fine_size / fine_spacing gives over 512 cells per side");
      mesh = graded_quad_mesh(sx, sy, fine, spacing, num("growth", 1.3, 1.01, 4.0));
    } else {
      mesh = quad_mesh(sx, sy);
    }
  } else if (gen == "pillow") {
    mesh = pillow_mesh(num("size_x", 1.0, 1e-3, 1e3), num("size_y", 1.0, 1e-3, 1e3), num("height", 0.3, 1e-3, 1e3),
                       num("wrinkle", 0.02, 0.0, 1e2), res(40));
  } else if (gen == "floor_cloth") {
    mesh = floor_cloth_mesh(num("size_x", 6.0, 1e-3, 1e3), num("size_y", 6.0, 1e-3, 1e3),
                            num("fold_height", 0.3, 0.0, 1e2), num("flat_radius", 1.0, 0.0, 1e3), res(48));
  } else if (gen == "curtain") {
    mesh = curtain_mesh(num("width", 2.0, 1e-3, 1e3), num("height", 2.5, 1e-3, 1e3),
                        static_cast<int>(num("folds", 5, 0, 100)), num("fold_depth", 0.1, 0.0, 1e2), res(32));
  } else if (gen == "bezier_patches") {
    const std::string file = text(field(m, "file", where), where + ".file");
    mesh = bezier_patch_mesh(base_dir / file, res(8));
  } else {
    throw SceneError(where + ".generator: unknown generator '" + gen +
                     "' (swatch, quad, pillow, floor_cloth, curtain, bezier_patches)");
  }
  glm::dvec3 translate(0.0);
  if (m.contains("translate")) translate = vec3(m["translate"], where + ".translate");
  transform_mesh(mesh, num("scale", 1.0, 1e-6, 1e6), num("rotate_z_deg", 0.0, -360, 360), translate);
  return mesh;
}

bool fabric_preset_exists(const std::filesystem::path& dir, const std::string& name) {
  if (dir.empty() || name.empty() || name.find('/') != std::string::npos || name.find('.') != std::string::npos)
    return false;
  std::error_code ec;
  return std::filesystem::is_regular_file(dir / (name + ".json"), ec);
}

// A scene file's "gltf" field: the imported scene, with the file's fabric overrides applied.
Scene import_gltf(const json& j, const std::string& origin, const std::filesystem::path& base_dir,
                  const SceneLoadOptions& options) {
  GltfImportOptions g;
  g.fabrics_dir = options.fabrics_dir;
  g.fallback_fabric = options.fallback_fabric;
  if (j.contains("fabrics")) {
    const json& f = j["fabrics"];
    if (!f.is_object()) throw SceneError(origin + ": fabrics: expected {\"material name\": \"preset or file\"}");
    for (const auto& [material, value] : f.items()) {
      const std::string named = text(value, origin + ": fabrics." + material);
      // A preset name stays a name; anything else is a fabric file relative to the scene file.
      g.fabric_overrides[material] =
          fabric_preset_exists(options.fabrics_dir, named) ? named : (base_dir / named).lexically_normal().string();
    }
  }
  const std::string file = text(j["gltf"], origin + ": gltf");
  return load_gltf_scene((base_dir / file).lexically_normal(), g);
}

// A scene file's "colourways": [{"name", "objects": {object: {"fabric"?, "colour"?}}}]. A look
// without "fabric" keeps the object's; one without "colour" shows the fabric's own.
std::vector<Colourway> parse_colourways(const json& j, const Scene& s, const std::string& origin,
                                        const std::filesystem::path& base_dir, const SceneLoadOptions& options) {
  const std::string where = origin + ": colourways";
  if (!j.is_array()) throw SceneError(where + ": expected a list of {\"name\", \"objects\"}");
  if (j.empty()) throw SceneError(where + ": the list is empty (leave it out for the scene's own look)");
  std::vector<Colourway> out;
  for (size_t k = 0; k < j.size(); ++k) {
    const std::string at = where + "[" + std::to_string(k) + "]";
    Colourway c;
    c.name = text(field(j[k], "name", at), at + ".name");
    const json& objects = field(j[k], "objects", at);
    if (!objects.is_object()) throw SceneError(at + ".objects: expected {\"object name\": {\"fabric\", \"colour\"}}");
    for (const auto& [object, look] : objects.items()) {
      const std::string lw = at + ".objects." + object;
      if (!look.is_object()) throw SceneError(lw + ": expected {\"fabric\", \"colour\"}");
      for (const auto& [key, value] : look.items())
        if (key != "fabric" && key != "colour") throw SceneError(lw + "." + key + ": unknown (known: fabric, colour)");
      ClothLook l;
      const auto it = std::find_if(s.objects.begin(), s.objects.end(), [&](const SceneObject& o) { return o.name == object; });
      if (look.contains("fabric")) {
        const std::string named = text(look["fabric"], lw + ".fabric");
        l.fabric = fabric_preset_exists(options.fabrics_dir, named) || !names_fabric_file(named)
                       ? named
                       : (base_dir / named).lexically_normal().string();
      } else if (it != s.objects.end()) {
        l.fabric = it->fabric;
      }
      if (look.contains("colour")) l.colour = colour_from_json(look["colour"], lw + ".colour");
      c.objects[object] = l;
    }
    out.push_back(std::move(c));
  }
  return out;
}

Camera parse_camera(const json& cam, const std::string& cw) {
  Camera c;
  c.position = vec3(field(cam, "position", cw), cw + ".position");
  c.target = vec3(field(cam, "target", cw), cw + ".target");
  c.up = vec3(field(cam, "up", cw), cw + ".up");
  c.fov_deg = number(field(cam, "fov_deg", cw), cw + ".fov_deg");
  check_camera(c, cw);
  return c;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& origin, const std::filesystem::path& base_dir,
                  const SceneLoadOptions& options) {
  json j;
  try {
    j = json::parse(json_text);
  } catch (const json::exception& e) {
    throw SceneError(origin + ": not valid JSON (" + e.what() + ")");
  }
  if (j.is_object() && j.contains("gltf")) {
    // Objects come from the glTF; the scene file may name it, add a camera, an environment
    // and further (generated) objects.
    Scene s = import_gltf(j, origin, base_dir, options);
    if (j.contains("name")) s.name = text(j["name"], origin + ": name");
    if (j.contains("description")) s.description = text(j["description"], origin + ": description");
    if (j.contains("camera")) s.camera = parse_camera(j["camera"], origin + ": camera");
    if (j.contains("closeup_camera")) s.closeup = parse_camera(j["closeup_camera"], origin + ": closeup_camera");
    if (j.contains("environment")) s.environment = text(j["environment"], origin + ": environment");
    if (j.contains("objects")) {
      json rest = j;
      rest.erase("gltf");
      rest["name"] = s.name;
      rest["camera"] = json{{"position", {s.camera.position.x, s.camera.position.y, s.camera.position.z}},
                            {"target", {s.camera.target.x, s.camera.target.y, s.camera.target.z}},
                            {"up", {s.camera.up.x, s.camera.up.y, s.camera.up.z}},
                            {"fov_deg", s.camera.fov_deg}};
      rest["environment"] = s.environment;
      rest.erase("closeup_camera");
      rest.erase("colourways");
      Scene extra = parse_scene(rest.dump(), origin, base_dir, options);
      for (auto& o : extra.objects) s.objects.push_back(std::move(o));
    }
    // The scene file's colourways replace the glTF's variants.
    if (j.contains("colourways")) s.colourways = parse_colourways(j["colourways"], s, origin, base_dir, options);
    check_colourways(s, origin);
    return s;
  }
  Scene s;
  s.name = text(field(j, "name", origin), origin + ": name");
  if (j.contains("description")) s.description = text(j["description"], origin + ": description");

  const std::string cw = origin + ": camera";
  const json& cam = field(j, "camera", origin);
  s.camera = parse_camera(cam, cw);
  if (j.contains("closeup_camera")) s.closeup = parse_camera(j["closeup_camera"], origin + ": closeup_camera");

  s.environment = text(field(j, "environment", origin), origin + ": environment");

  const json& objects = field(j, "objects", origin);
  if (!objects.is_array() || objects.empty()) throw SceneError(origin + ": objects: expected a non-empty array");
  TextureFiles textures;
  for (size_t i = 0; i < objects.size(); ++i) {
    const json& o = objects[i];
    const std::string where = origin + ": objects[" + std::to_string(i) + "]";
    SceneObject obj;
    obj.name = read_object_name(o, where);
    obj.material = read_material(o, where);
    if (obj.is_cloth()) {
      obj.fabric = read_fabric(o, where);
      obj.optical_thickness = read_optical_thickness(o, where);
      obj.weave_repeats_per_uv = read_weave_repeats_per_uv(o, where);
      obj.colour = read_colour(o, where);
      if (o.contains("texture")) {
        obj.thread_maps[0] = parse_thread_map(o["texture"], where + ".texture", base_dir, textures);
        obj.thread_maps[1] = obj.thread_maps[0];
      }
      if (o.contains("weft_texture")) {
        if (!o.contains("texture")) throw SceneError(where + ".weft_texture: give the warp's \"texture\" too");
        obj.thread_maps[1] = parse_thread_map(o["weft_texture"], where + ".weft_texture", base_dir, textures);
      }
      if (o.contains("normal_map")) obj.normal_map = parse_normal_map(o["normal_map"], where + ".normal_map", base_dir, textures);
    } else {
      obj.albedo = read_albedo(o, where);
    }
    try {
      obj.mesh = generate_mesh(field(o, "mesh", where), where + ".mesh", base_dir);
      obj.repair = finish_mesh(obj.mesh, obj.is_cloth(), s.name + "/" + obj.name);
    } catch (const MeshError& e) {
      throw SceneError(where + ": " + e.what());
    }
    s.objects.push_back(std::move(obj));
  }
  if (j.contains("colourways")) s.colourways = parse_colourways(j["colourways"], s, origin, base_dir, options);
  check_colourways(s, origin);
  return s;
}

Scene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options) {
  if (is_gltf_path(file.string())) {
    GltfImportOptions g;
    g.fabrics_dir = options.fabrics_dir;
    g.fallback_fabric = options.fallback_fabric;
    return load_gltf_scene(file, g);
  }
  return parse_scene(read_text(file, "scene file"), file.string(), file.parent_path(), options);
}

bool names_scene_file(const std::string& name) {
  const std::filesystem::path p(name);
  return p.has_parent_path() || p.extension() == ".json" || is_gltf_path(name);
}

Scene load_scene_named(const std::string& name, const std::filesystem::path& assets, const std::string& fallback_fabric) {
  SceneLoadOptions options;
  options.fabrics_dir = assets / "fabrics";
  options.fallback_fabric = fallback_fabric;
  if (names_scene_file(name)) return load_scene(name, options);
  return load_scene_preset(name, assets / "scenes", options);
}

Scene load_scene_preset(const std::string& name, const std::filesystem::path& dir, const SceneLoadOptions& options) {
  const auto file = dir / (name + ".json");
  if (!std::filesystem::exists(file)) {
    std::string known;
    for (const auto& n : list_scene_presets(dir)) known += (known.empty() ? "" : ", ") + n;
    throw SceneError("no scene '" + name + "' in " + dir.string() + " (known: " + known + ")");
  }
  return load_scene(file, options);
}

std::vector<std::string> list_scene_presets(const std::filesystem::path& dir) {
  return preset_names(dir);
}

}  // namespace weft
