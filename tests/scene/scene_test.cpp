// Scenes load with usable meshes (UVs, unit warps ⟂ normals); malformed meshes are repaired or
// rejected; scene files with missing or bad fields are rejected naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "scene/mesh.h"
#include "scene/bounds.h"
#include "scene/procedural_meshes.h"
#include "scene/scene_file.h"
#include "scene/vertex_weld.h"

using namespace weft;
using glm::dvec3;

static const std::filesystem::path kDir = WEFT_SOURCE_ASSETS "/scenes";

static std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(Scene, AllPresetsLoadWithClothFramesFromUVs) {
  EXPECT_EQ(list_scene_presets(kDir),
            (std::vector<std::string>{"curtain", "drape", "pillow", "plaid_pillow", "showroom", "swatch", "teapot"}));
  SceneLoadOptions options;  // the showroom's glTF names its fabrics by preset
  options.fabrics_dir = WEFT_SOURCE_ASSETS "/fabrics";
  for (const auto& name : list_scene_presets(kDir)) {
    const Scene s = load_scene_preset(name, kDir, options);
    EXPECT_EQ(s.name, name);
    EXPECT_FALSE(s.environment.empty());
    bool has_cloth = false;
    for (const auto& o : s.objects) {
      const auto& m = o.mesh;
      EXPECT_LE(m.triangles.size(), 10000u) << name << "/" << o.name << ": keep meshes small";
      ASSERT_EQ(m.normals.size(), m.positions.size());
      // Every mesh has a frame per vertex (floors and occluders too: their visibility is baked in it).
      ASSERT_EQ(m.warps.size(), m.positions.size()) << name << "/" << o.name;
      for (size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.warps[i]), 1.0, 1e-9);
        EXPECT_NEAR(glm::dot(m.warps[i], m.normals[i]), 0.0, 1e-9);
      }
      if (o.material != Material::cloth) continue;
      has_cloth = true;
      ASSERT_EQ(m.uvs.size(), m.positions.size());
    }
    EXPECT_TRUE(has_cloth) << name;
  }
}

TEST(Scene, ClothObjectsAreTheClothInOrder) {
  Scene s;
  for (const char* name : {"floor", "seat", "wall", "cushion"}) {
    SceneObject o;
    o.name = name;
    o.material = std::string(name) == "seat" || std::string(name) == "cushion" ? Material::cloth : Material::lambertian;
    s.objects.push_back(o);
  }
  std::vector<std::string> names;
  for (const auto& o : s.cloth_objects()) names.push_back(o.name);
  EXPECT_EQ(names, (std::vector<std::string>{"seat", "cushion"}));
  for (auto& o : s.cloth_objects()) o.fabric = "satin";
  EXPECT_EQ(s.objects[1].fabric, "satin");
  EXPECT_EQ(s.objects[0].fabric, "");
}

TEST(Scene, SwatchWarpRunsAlongX) {
  const Scene s = load_scene_preset("swatch", kDir);
  for (const auto& w : s.objects[0].mesh.warps) EXPECT_NEAR(w.x, 1.0, 1e-12);
  for (const auto& n : s.objects[0].mesh.normals) EXPECT_NEAR(n.z, 1.0, 1e-12);
}

TEST(Scene, TeapotFromNewellPatches) {
  const Scene s = load_scene_preset("drape", kDir);
  const SceneObject* teapot = nullptr;
  for (const auto& o : s.objects)
    if (o.name == "teapot") teapot = &o;
  ASSERT_NE(teapot, nullptr);
  // The lid knob and the bottom are patches collapsed to a point: their first row of quads is
  // degenerate, and repair drops those triangles (8 quads × 2 halves... at least one per patch).
  EXPECT_GT(teapot->repair.degenerate_triangles_dropped, 0u);
  dvec3 lo(1e9), hi(-1e9);
  double reach = 0;  // distance from the pot's axis: rotation-invariant
  for (const auto& p : teapot->mesh.positions) {
    lo = glm::min(lo, p), hi = glm::max(hi, p);
    reach = std::max(reach, std::hypot(p.x, p.y));
  }
  // Newell's teapot: 3.15 tall; the spout's lip reaches x ≈ 3.4–3.5 (inside its control hull,
  // 3.525); scaled and lifted onto the cloth as the scene file says.
  const auto file = nlohmann::json::parse(read(kDir / "drape.json"));
  double scale = 0, lift = 0;
  for (const auto& o : file["objects"])
    if (o["name"] == "teapot") scale = o["mesh"]["scale"], lift = o["mesh"]["translate"][2];
  ASSERT_GT(scale, 0.0);
  EXPECT_NEAR(lo.z, lift, 1e-9);
  EXPECT_NEAR(hi.z - lo.z, scale * 3.15, 1e-3);
  EXPECT_GT(reach, scale * 3.3);
  EXPECT_LT(reach, scale * 3.53);
}

TEST(Mesh, WarpIsDpDuOrthogonalisedAgainstNormal) {
  // A plane tilted about x, with u running along (cos 30°, sin 30°) in its own coordinates.
  const double a = glm::radians(30.0);
  TriangleMesh m = parametric_grid(4, 4, [](double s, double t) { return dvec3(s, t, 0.5 * t); });
  for (auto& uv : m.uvs) uv = glm::dvec2(std::cos(a) * uv.x + std::sin(a) * uv.y, -std::sin(a) * uv.x + std::cos(a) * uv.y);
  finish_mesh(m, true, "tilted");
  // P(s,t) = (s, t, t/2); (u,v) = R(a)(s,t) ⇒ (s,t) = R(−a)(u,v): dP/du = cos a·P_s + sin a·P_t.
  const dvec3 dpdu = std::cos(a) * dvec3(1, 0, 0) + std::sin(a) * dvec3(0, 1, 0.5);
  const dvec3 n = glm::normalize(glm::cross(dvec3(1, 0, 0), dvec3(0, 1, 0.5)));
  const dvec3 expect = glm::normalize(dpdu - glm::dot(dpdu, n) * n);
  for (size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(m.warps[i] - expect), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(m.normals[i] - n), 0.0, 1e-9);
  }
}

static TriangleMesh two_triangles() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(Mesh, DegenerateTrianglesAreDroppedAndCounted) {
  TriangleMesh m = two_triangles();
  m.positions.push_back({2, 0, 0});                         // collinear with 0 and 1
  m.uvs.push_back({2, 0});
  m.triangles.push_back({0, 1, 4});                         // zero area
  m.triangles.push_back({1, 1, 2});                         // repeated index
  const MeshRepairReport r = finish_mesh(m, true, "t");
  EXPECT_EQ(r.degenerate_triangles_dropped, 2u);
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(r.unused_vertices, 1u);
}

TEST(Mesh, ClothTriangleWithDegenerateUVsIsDropped) {
  TriangleMesh m = two_triangles();
  m.uvs[1] = {0.5, 0.5};  // triangle 0's UVs collinear: no dP/du there
  EXPECT_EQ(finish_mesh(m, true, "t").degenerate_triangles_dropped, 1u);
}

static std::string mesh_error(TriangleMesh m, bool cloth) {
  try {
    finish_mesh(m, cloth, "bad");
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

// Two quads side by side, their shared edge's vertices duplicated (a UV seam): welding by position
// merges the duplicates, by position and UV keeps those whose UVs differ.
TEST(Mesh, WeldMergesVerticesByPositionAndUv) {
  const std::vector<glm::dvec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0, 1e-9}, {1, 1, 0}, {2, 0, 0}};
  const std::vector<glm::dvec2> uv{{0, 0}, {1, 0}, {1, 1}, {1, 0}, {0, 1}, {1, 0}};
  EXPECT_EQ(welded_ids(p, 1e-6), (std::vector<uint32_t>{0, 1, 2, 1, 2, 3}));
  EXPECT_EQ(welded_ids(p, 1e-6, glm::dvec3(0.0), uv), (std::vector<uint32_t>{0, 1, 2, 1, 3, 4}));
  // Rounded from the origin given: 0.4 and 0.6 fall apart from 0, together from 0.5.
  const std::vector<glm::dvec3> q{{0.4, 0, 0}, {0.6, 0, 0}};
  EXPECT_EQ(welded_ids(q, 1.0), (std::vector<uint32_t>{0, 1}));
  EXPECT_EQ(welded_ids(q, 1.0, glm::dvec3(0.5, 0, 0)), (std::vector<uint32_t>{0, 0}));

  TriangleMesh m;
  m.positions = p;
  m.uvs = uv;
  m.triangles = {{0, 1, 2}, {3, 5, 4}};
  weld_vertices(m, 1e-6);
  EXPECT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.triangles[1], (std::array<uint32_t, 3>{1, 4, 3}));
}

// The product's bounds: its cloth, or everything where nothing is cloth; none for an empty scene.
TEST(Scene, ProductBoundsAreTheClothsOrEverything) {
  Scene s;
  SceneObject floor, cloth;
  floor.mesh.positions = {{-5, -5, 0}, {5, 5, 0}};
  cloth.material = Material::cloth;
  cloth.mesh.positions = {{0, 1, 2}, {1, 3, 4}, {0.5, 2, 3}};
  s.objects = {floor};
  EXPECT_EQ(product_bounds(s).lo, glm::dvec3(-5, -5, 0));
  s.objects.push_back(cloth);
  const Bounds b = product_bounds(s);
  EXPECT_EQ(b.lo, glm::dvec3(0, 1, 2));
  EXPECT_EQ(b.hi, glm::dvec3(1, 3, 4));
  EXPECT_EQ(b.centre(), glm::dvec3(0.5, 2, 3));
  EXPECT_TRUE(product_bounds(Scene{}).empty());
}

TEST(Mesh, MalformedMeshesAreRejectedClearly) {
  TriangleMesh nan = two_triangles();
  nan.positions[2].y = std::nan("");
  EXPECT_NE(mesh_error(nan, false).find("position of vertex 2 is not finite"), std::string::npos) << mesh_error(nan, false);

  TriangleMesh no_uv = two_triangles();
  no_uv.uvs.clear();
  EXPECT_NE(mesh_error(no_uv, true).find("cloth needs UVs"), std::string::npos);
  EXPECT_EQ(mesh_error(no_uv, false), "");  // an occluder needs none

  TriangleMesh out_of_range = two_triangles();
  out_of_range.triangles[1][2] = 7;
  EXPECT_NE(mesh_error(out_of_range, false).find("uses vertex 7 of 4"), std::string::npos);

  TriangleMesh short_uvs = two_triangles();
  short_uvs.uvs.pop_back();
  EXPECT_NE(mesh_error(short_uvs, true).find("3 UVs for 4 vertices"), std::string::npos);

  TriangleMesh flat = two_triangles();
  for (auto& p : flat.positions) p.y = 0.0;
  EXPECT_NE(mesh_error(flat, false).find("every triangle is degenerate"), std::string::npos);

  TriangleMesh empty;
  EXPECT_NE(mesh_error(empty, false).find("no vertices"), std::string::npos);
}

TEST(Mesh, TruncatedPatchFileIsRejected) {
  const auto file = std::filesystem::temp_directory_path() / "weft_scene_test_truncated.bpt";
  std::ofstream(file) << "2\n1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16\n";
  EXPECT_THROW(bezier_patch_mesh(file, 4), MeshError);
  std::filesystem::remove(file);
  EXPECT_THROW(bezier_patch_mesh("/nonexistent/teapot.bpt", 4), MeshError);
}

// Scene files: each required field removed in turn must give a SceneError naming it.
static std::string scene_error(const nlohmann::json& j) {
  try {
    parse_scene(j.dump(), "test.json", kDir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneFile, MissingFieldsAreNamed) {
  const nlohmann::json good = nlohmann::json::parse(read(kDir / "pillow.json"));
  EXPECT_EQ(scene_error(good), "");
  auto without = [&](auto&& edit) {
    nlohmann::json j = good;
    edit(j);
    return scene_error(j);
  };
  EXPECT_NE(without([](auto& j) { j.erase("camera"); }).find("missing field 'camera'"), std::string::npos);
  EXPECT_NE(without([](auto& j) { j["camera"].erase("fov_deg"); }).find("camera: missing field 'fov_deg'"),
            std::string::npos);
  EXPECT_NE(without([](auto& j) { j.erase("environment"); }).find("missing field 'environment'"), std::string::npos);
  EXPECT_NE(without([](auto& j) { j.erase("objects"); }).find("missing field 'objects'"), std::string::npos);
  EXPECT_NE(without([](auto& j) { j["objects"][0].erase("fabric"); }).find("objects[0]: missing field 'fabric'"),
            std::string::npos);
  EXPECT_NE(without([](auto& j) { j["objects"][1].erase("albedo"); }).find("objects[1]: missing field 'albedo'"),
            std::string::npos);
  EXPECT_NE(without([](auto& j) { j["objects"][0]["mesh"].erase("generator"); })
                .find("objects[0].mesh: missing field 'generator'"),
            std::string::npos);
}

TEST(SceneFile, BadValuesAreNamed) {
  const nlohmann::json good = nlohmann::json::parse(read(kDir / "pillow.json"));
  auto with = [&](auto&& edit) {
    nlohmann::json j = good;
    edit(j);
    return scene_error(j);
  };
  EXPECT_NE(with([](auto& j) { j["camera"]["position"] = {1, 2}; }).find("camera.position: expected [x, y, z]"),
            std::string::npos);
  EXPECT_NE(with([](auto& j) { j["camera"]["target"] = j["camera"]["position"]; }).find("coincide"),
            std::string::npos);
  EXPECT_NE(with([](auto& j) { j["camera"]["up"] = {0, 0, 0}; }).find("camera.up"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["objects"][0]["material"] = "metal"; }).find("'metal' is neither"),
            std::string::npos);
  EXPECT_NE(with([](auto& j) { j["objects"][0]["mesh"]["generator"] = "torus"; }).find("unknown generator 'torus'"),
            std::string::npos);
  EXPECT_NE(with([](auto& j) { j["objects"][0]["mesh"]["resolution"] = 100000; }).find("resolution"),
            std::string::npos);
  EXPECT_NE(with([](auto& j) { j["objects"][1]["albedo"] = {0.5, 2.0, 0.5}; }).find("albedo"), std::string::npos);
  EXPECT_NE(scene_error(nlohmann::json("not an object")).find("expected an object"), std::string::npos);
  try {
    parse_scene("{ \"name\": ", "broken.json", kDir);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: not valid JSON"), std::string::npos);
  }
  EXPECT_THROW(load_scene_preset("no_such_scene", kDir), SceneError);
}

TEST(Camera, CentreRayPointsAtTarget) {
  Camera c;
  c.position = {1, -2, 3};
  c.target = {0, 0.5, 0.2};
  const dvec3 d = camera_ray(c, 101, 51, 50.5, 25.5);
  EXPECT_NEAR(glm::length(d - glm::normalize(c.target - c.position)), 0.0, 1e-12);
  // Top edge of the image is fov/2 above the centre.
  const dvec3 top = camera_ray(c, 101, 51, 50.5, 0.0);
  EXPECT_NEAR(std::acos(glm::dot(top, d)), glm::radians(c.fov_deg / 2), 1e-9);
  EXPECT_GT(top.z, d.z);
}

TEST(SceneFile, ClothOpticalThicknessOverridesTheFabrics) {
  nlohmann::json j = nlohmann::json::parse(read(kDir / "curtain.json"));
  EXPECT_EQ(parse_scene(j.dump(), "test.json", kDir).objects[0].optical_thickness, 0.0);  // the fabric's own
  j["objects"][0]["optical_thickness"] = 0.7;
  const Scene s = parse_scene(j.dump(), "test.json", kDir);
  EXPECT_DOUBLE_EQ(s.objects[0].optical_thickness, 0.7);
  Fabric voile;
  voile.optical_thickness = 0.4;
  EXPECT_DOUBLE_EQ(object_fabric(s.objects[0], voile).optical_thickness, 0.7);
  EXPECT_DOUBLE_EQ(object_fabric(s.objects[1], voile).optical_thickness, 0.4);  // no override: the fabric's
  for (double bad : {0.0, -1.0, 25.0}) {
    j["objects"][0]["optical_thickness"] = bad;
    EXPECT_NE(scene_error(j).find("objects[0].optical_thickness"), std::string::npos) << bad << ": " << scene_error(j);
  }
}
