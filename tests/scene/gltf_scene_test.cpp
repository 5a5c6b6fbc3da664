// glTF 2.0 import: Khronos and assimp sample files (Debian's assimp-testmodels) import with the
// counts their own accessors give, the broken ones are refused with a message and none crash; a
// glTF written here checks the frame conversion, hierarchy, cameras and warps by hand.
#include <gtest/gtest.h>

#include <numeric>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "scene/gltf_cloth_names.h"
#include "scene/gltf_scene.h"
#include "scene/scene_file.h"
#include "support/base64_text.h"
#include "support/scene_refusal.h"

using namespace weft;
using glm::dvec3;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models/glTF2";
const fs::path kFabrics = WEFT_SOURCE_ASSETS "/fabrics";

#define SKIP_WITHOUT_MODELS()                                                                            \
  if (!fs::is_directory(kModels)) GTEST_SKIP() << kModels << " absent (apt-get install assimp-testmodels)"

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The JSON of a .gltf, or a .glb's first chunk.
json gltf_json(const fs::path& p) {
  const std::string b = read_bytes(p);
  if (p.extension() != ".glb") return json::parse(b);
  uint32_t length;
  std::memcpy(&length, b.data() + 12, 4);
  return json::parse(b.substr(20, length));
}

GltfImportOptions options(const std::string& fallback = "") {
  GltfImportOptions o;
  o.fabrics_dir = kFabrics;
  o.fallback_fabric = fallback;
  return o;
}

// Vertices and triangles the file's scene instantiates, from its accessors' counts.
struct Counts {
  size_t vertices = 0, triangles = 0;
};
Counts expected_counts(const json& j) {
  Counts c;
  std::vector<int> stack = j["scenes"][j.value("scene", 0)]["nodes"].get<std::vector<int>>();
  while (!stack.empty()) {
    const json& node = j["nodes"][stack.back()];
    stack.pop_back();
    if (node.contains("mesh"))
      for (const json& p : j["meshes"][node["mesh"].get<int>()]["primitives"]) {
        c.vertices += j["accessors"][p["attributes"]["POSITION"].get<int>()]["count"].get<size_t>();
        c.triangles += j["accessors"][p["indices"].get<int>()]["count"].get<size_t>() / 3;
      }
    if (node.contains("children"))
      for (int k : node["children"]) stack.push_back(k);
  }
  return c;
}

Counts imported_counts(const Scene& s, size_t* dropped = nullptr) {
  Counts c;
  for (const auto& o : s.objects) {
    c.vertices += o.mesh.positions.size();
    c.triangles += o.mesh.triangles.size();
    if (dropped) *dropped += o.repair.degenerate_triangles_dropped;
  }
  return c;
}

using test::base64;

// A one-buffer glTF built attribute by attribute (floats, or uint16 indices).
struct GltfBuilder {
  json j = {{"asset", {{"version", "2.0"}}}, {"bufferViews", json::array()}, {"accessors", json::array()}};
  std::string buffer;

  int add(const void* data, size_t bytes, size_t count, const char* type, int component) {
    while (buffer.size() % 4) buffer.push_back('\0');
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", bytes}});
    buffer.append(static_cast<const char*>(data), bytes);
    j["accessors"].push_back({{"bufferView", j["bufferViews"].size() - 1}, {"componentType", component},
                              {"count", count}, {"type", type}});
    return static_cast<int>(j["accessors"].size() - 1);
  }
  int floats(const std::vector<float>& v, int n, const char* type) {
    return add(v.data(), v.size() * 4, v.size() / n, type, 5126);
  }
  int indices(const std::vector<uint16_t>& v) { return add(v.data(), v.size() * 2, v.size(), "SCALAR", 5123); }
  std::string text() {
    j["buffers"] = json::array({{{"byteLength", buffer.size()},
                                 {"uri", "data:application/octet-stream;base64," + base64(buffer)}}});
    return j.dump();
  }
};

// A 2 m × 1 m quad on glTF's ground (y = 0), u running along glTF −z (Weft +y), child of a node
// translated by (1, 2, 3); material "Sofa" names linen_plain in its extras.
GltfBuilder quad(bool with_uvs = true, bool with_tangents = false) {
  GltfBuilder b;
  json attributes = {{"POSITION", b.floats({0, 0, 0, 2, 0, 0, 2, 0, -1, 0, 0, -1}, 3, "VEC3")}};
  if (with_uvs) attributes["TEXCOORD_0"] = b.floats({0, 0, 0, 1, 1, 1, 1, 0}, 2, "VEC2");
  if (with_tangents) attributes["TANGENT"] = b.floats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1}, 4, "VEC4");
  const int idx = b.indices({0, 1, 2, 0, 2, 3});
  b.j["meshes"] = json::array({{{"primitives", json::array({{{"attributes", attributes}, {"indices", idx},
                                                              {"material", 0}}})}}});
  b.j["materials"] = json::array({{{"name", "Sofa"}, {"extras", {{"weft", {{"fabric", "linen_plain"}}}}}}});
  b.j["nodes"] = json::array({{{"translation", {1, 2, 3}}, {"children", {1}}}, {{"mesh", 0}}});
  b.j["scenes"] = json::array({{{"nodes", {0}}}});
  b.j["scene"] = 0;
  return b;
}

Scene parse(GltfBuilder b, const GltfImportOptions& o = options()) {
  return parse_gltf_scene(b.text(), "test.gltf", fs::temp_directory_path(), o);
}

void expect_near(const dvec3& a, const dvec3& b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

using test::refusal;

}  // namespace

// A 1 m box exported inside out (its normals and winding pointing in), as a product tool leaves a
// part whose "outside" was never recalculated; `camera_inside`: a camera node at its centre.
GltfBuilder inside_out_box(bool camera_inside) {
  GltfBuilder b;
  std::vector<float> p, n;
  std::vector<uint16_t> idx;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      float nn[3] = {0, 0, 0};
      nn[axis] = side;
      const float u[3] = {nn[1], nn[2], nn[0]};
      const float v[3] = {nn[1] * u[2] - nn[2] * u[1], nn[2] * u[0] - nn[0] * u[2], nn[0] * u[1] - nn[1] * u[0]};
      const uint16_t base = uint16_t(p.size() / 3);
      for (auto [a, c] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
        for (int k = 0; k < 3; ++k) p.push_back(0.5f * (nn[k] + a * u[k] + c * v[k]));
        for (int k = 0; k < 3; ++k) n.push_back(-nn[k]);  // into the box
      }
      for (uint16_t i : {0, 2, 1, 0, 3, 2}) idx.push_back(uint16_t(base + i));  // wound inwards
    }
  json attributes = {{"POSITION", b.floats(p, 3, "VEC3")}, {"NORMAL", b.floats(n, 3, "VEC3")}};
  const int indices = b.indices(idx);
  b.j["meshes"] = json::array({{{"primitives", json::array({{{"attributes", attributes}, {"indices", indices},
                                                              {"material", 0}}})}}});
  b.j["materials"] = json::array({{{"name", "Steel"}}});
  b.j["nodes"] = json::array({{{"mesh", 0}}});
  b.j["scenes"] = json::array({{{"nodes", {0}}}});
  if (camera_inside) {
    b.j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.01}}}}});
    b.j["nodes"].push_back({{"camera", 0}});
    b.j["scenes"][0]["nodes"].push_back(1);
  }
  b.j["scene"] = 0;
  return b;
}

TEST(GltfScene, AClosedPartExportedInsideOutIsTurnedOutwardsUnlessTheCameraIsInIt) {
  for (const bool camera_inside : {false, true}) {
    const Scene s = parse(inside_out_box(camera_inside));
    ASSERT_EQ(s.objects.size(), 1u);
    const TriangleMesh& m = s.objects[0].mesh;
    double outward = 0.0, volume = 0.0;
    for (size_t v = 0; v < m.positions.size(); ++v) outward += glm::dot(m.normals[v], m.positions[v]);
    for (const auto& t : m.triangles)
      volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
    const std::string log = std::accumulate(s.warnings.begin(), s.warnings.end(), std::string(),
                                            [](std::string a, const std::string& w) { return a + w + "\n"; });
    if (camera_inside) {
      EXPECT_LT(outward, 0.0);  // a room seen from within keeps its inward faces
      EXPECT_NEAR(volume, -1.0, 1e-6);
      EXPECT_NE(log.find("kept so: the camera is inside it"), std::string::npos) << log;
    } else {
      EXPECT_GT(outward, 0.0);
      EXPECT_NEAR(volume, 1.0, 1e-6);
      EXPECT_NE(log.find("normals and winding pointed inwards"), std::string::npos) << log;
    }
  }
}

TEST(GltfScene, HandMadeQuadInWeftFrameWithWarpFromUVs) {
  const Scene s = parse(quad());
  ASSERT_EQ(s.objects.size(), 1u);
  const SceneObject& o = s.objects[0];
  EXPECT_EQ(o.name, "Sofa");
  EXPECT_EQ(o.material, Material::cloth);
  EXPECT_EQ(o.fabric, "linen_plain");
  EXPECT_EQ(s.environment, "studio");
  ASSERT_EQ(o.mesh.positions.size(), 4u);
  // (x, y, z)_glTF + (1, 2, 3) → (x, −z, y).
  expect_near(o.mesh.positions[0], {1, -3, 2});
  expect_near(o.mesh.positions[1], {3, -3, 2});
  expect_near(o.mesh.positions[2], {3, -2, 2});
  expect_near(o.mesh.positions[3], {1, -2, 2});
  for (int v = 0; v < 4; ++v) {
    expect_near(o.mesh.normals[v], {0, 0, 1});  // computed (no NORMAL): glTF's +y is Weft's +z
    expect_near(o.mesh.warps[v], {0, 1, 0});    // dP/du: u grows along glTF −z
  }
  EXPECT_EQ(o.mesh.triangles.size(), 2u);
  // No camera in the file: framed on the cloth, looking at its centre from above.
  expect_near(s.camera.target, {2, -2.5, 2});
  EXPECT_GT(s.camera.position.z, 2.0);
}

TEST(GltfScene, NodeRotationAndMirrorFollowTheHierarchy) {
  GltfBuilder b = quad();
  // Child turned 90° about glTF +y ((x, y, z) → (z, y, −x)) under the parent's (1, 2, 3).
  b.j["nodes"][1]["rotation"] = {0, std::sqrt(0.5), 0, std::sqrt(0.5)};
  const Scene r = parse(b);
  const auto& m = r.objects.at(0).mesh;
  expect_near(m.positions[1], {1, -1, 2}, 1e-6);  // (2, 0, 0) → (0, 0, −2) + (1, 2, 3) → Weft
  expect_near(m.positions[2], {0, -1, 2}, 1e-6);  // (2, 0, −1) → (−1, 0, −2) + (1, 2, 3) → Weft
  expect_near(m.warps[0], {-1, 0, 0}, 1e-6);      // u ran along glTF −z, now along glTF −x
  expect_near(m.normals[0], {0, 0, 1}, 1e-6);
  // A mirroring node keeps the faces' side: the winding flips with it.
  b.j["nodes"][1].erase("rotation");
  b.j["nodes"][1]["scale"] = {-1, 1, 1};
  const Scene mirrored = parse(b);
  expect_near(mirrored.objects.at(0).mesh.positions[1], {-1, -3, 2});
  for (const auto& n : mirrored.objects.at(0).mesh.normals) expect_near(n, {0, 0, 1});
}

TEST(GltfScene, TangentOverridesUVsAndClothWithNeitherGetsAFixedWarpAndNoWeave) {
  const Scene s = parse(quad(true, true));
  for (const auto& w : s.objects[0].mesh.warps) expect_near(w, {1, 0, 0});  // glTF +x stays +x
  const Scene t = parse(quad(false, true));
  for (const auto& w : t.objects[0].mesh.warps) expect_near(w, {1, 0, 0});
  // Neither: still cloth, its warp x × n (here n = +z: −y), no UVs for a weave, and a note saying so.
  const Scene u = parse(quad(false, false));
  ASSERT_EQ(u.objects.size(), 1u);
  EXPECT_TRUE(u.objects[0].is_cloth());
  EXPECT_TRUE(u.objects[0].mesh.uvs.empty());
  for (size_t v = 0; v < u.objects[0].mesh.warps.size(); ++v) {
    const glm::dvec3 n = u.objects[0].mesh.normals[v];
    expect_near(u.objects[0].mesh.warps[v], glm::normalize(glm::cross(glm::dvec3(1, 0, 0), n)), 1e-9);
  }
  bool noted = false;
  for (const std::string& w : u.warnings) noted = noted || (w.find("test.gltf") != std::string::npos && w.find("no weave") != std::string::npos);
  EXPECT_TRUE(noted) << "no note that the cloth without UVs gets no weave";
}

TEST(GltfScene, MaterialNamedLikeAPresetIsClothOtherwiseLambertianOrFallback) {
  GltfBuilder b = quad();
  b.j["materials"][0] = {{"name", "velvet"}};
  EXPECT_EQ(parse(b).objects[0].fabric, "velvet");
  b.j["materials"][0] = {{"name", "Wood"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}}}};
  const Scene wood = parse(b);
  EXPECT_EQ(wood.objects[0].material, Material::lambertian);
  expect_near(wood.objects[0].mesh.warps[0], wood.objects[0].mesh.warps[0]);
  EXPECT_NEAR(wood.objects[0].albedo.g, 0.4, 1e-12);
  const Scene fallback = parse(b, options("silk_shot"));
  EXPECT_EQ(fallback.objects[0].material, Material::cloth);
  EXPECT_EQ(fallback.objects[0].fabric, "silk_shot");
  GltfImportOptions o = options("silk_shot");
  o.fabric_overrides["Wood"] = "velvet";
  EXPECT_EQ(parse(b, o).objects[0].fabric, "velvet");
}

TEST(GltfScene, FabricFileInExtrasIsResolvedBesideTheGltf) {
  const fs::path dir = fs::temp_directory_path() / "weft_gltf_fabric_test";
  fs::create_directories(dir);
  fs::copy_file(kFabrics / "velvet.json", dir / "my_velvet.json", fs::copy_options::overwrite_existing);
  GltfBuilder b = quad();
  b.j["materials"][0]["extras"]["weft"]["fabric"] = "my_velvet.json";
  std::ofstream(dir / "quad.gltf") << b.text();
  const Scene s = load_gltf_scene(dir / "quad.gltf", options());
  EXPECT_EQ(s.objects[0].fabric, (dir / "my_velvet.json").string());
  b.j["materials"][0]["extras"]["weft"]["fabric"] = "missing.json";
  std::ofstream(dir / "quad.gltf") << b.text();
  const std::string why = refusal([&] { load_gltf_scene(dir / "quad.gltf", options()); });
  EXPECT_NE(why.find("missing.json"), std::string::npos) << why;
}

TEST(GltfScene, OpticalThicknessInExtrasMakesTheClothASheer) {
  GltfBuilder b = quad();
  EXPECT_EQ(parse(b).objects[0].optical_thickness, 0.0);
  b.j["materials"][0]["extras"]["weft"]["optical_thickness"] = 0.35;
  const Scene s = parse(b);
  EXPECT_EQ(s.objects[0].material, Material::cloth);
  EXPECT_DOUBLE_EQ(s.objects[0].optical_thickness, 0.35);
  for (const json& bad : {json(0.0), json(-2), json(50), json("thin")}) {
    b.j["materials"][0]["extras"]["weft"]["optical_thickness"] = bad;
    const std::string why = refusal([&] { parse(b); });
    EXPECT_NE(why.find("extras.weft.optical_thickness"), std::string::npos) << bad.dump() << ": " << why;
  }
}

TEST(GltfScene, DisplayNameAndCompositionInExtrasAreTheLabelsText) {
  GltfBuilder b = quad();
  EXPECT_EQ(parse(b).objects[0].display_name, "");
  b.j["materials"][0]["extras"]["weft"]["display_name"] = "Sofa linen";
  b.j["materials"][0]["extras"]["weft"]["composition"] = "55 % linen, 45 % cotton";
  const Scene s = parse(b);
  EXPECT_EQ(s.objects[0].display_name, "Sofa linen");
  EXPECT_EQ(s.objects[0].composition, "55 % linen, 45 % cotton");
  for (const json& bad : {json(3), json("two\nlines"), json(std::string(200, 'x'))}) {
    b.j["materials"][0]["extras"]["weft"]["composition"] = bad;
    const std::string why = refusal([&] { parse(b); });
    EXPECT_NE(why.find("extras.weft.composition"), std::string::npos) << bad.dump() << ": " << why;
  }
}

TEST(GltfScene, SceneFileReferencesGltfWithOverridesCameraAndEnvironment) {
  const fs::path dir = fs::temp_directory_path() / "weft_gltf_scene_file_test";
  fs::create_directories(dir);
  std::ofstream(dir / "quad.gltf") << quad().text();
  std::ofstream(dir / "room.json") << R"({"gltf": "quad.gltf", "environment": "interior",
    "fabrics": {"Sofa": "velvet"},
    "camera": {"position": [0, -5, 3], "target": [0, 0, 0], "up": [0, 0, 1], "fov_deg": 35}})";
  const Scene s = load_scene_named((dir / "room.json").string(), WEFT_SOURCE_ASSETS);
  EXPECT_EQ(s.environment, "interior");
  EXPECT_EQ(s.objects.at(0).fabric, "velvet");
  EXPECT_DOUBLE_EQ(s.camera.fov_deg, 35.0);
  expect_near(s.camera.position, {0, -5, 3});
  // The glTF by path directly, and a preset by name, through the same entry.
  EXPECT_EQ(load_scene_named((dir / "quad.gltf").string(), WEFT_SOURCE_ASSETS).objects.at(0).fabric, "linen_plain");
  EXPECT_EQ(load_scene_named("swatch", WEFT_SOURCE_ASSETS).name, "swatch");
}

TEST(GltfScene, HostileHandMadeFilesAreRefused) {
  struct Case {
    const char* what;
    std::function<void(GltfBuilder&)> spoil;
    const char* reason;
  };
  const std::vector<Case> cases = {
      {"index out of range", [](GltfBuilder& b) { b.j["meshes"][0]["primitives"][0]["indices"] = b.indices({0, 1, 9}); },
       "out of range"},
      {"NaN position",
       [](GltfBuilder& b) {
         b.j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] =
             b.floats({0, 0, 0, 2, 0, 0, 2, 0, -1, 0, NAN, -1}, 3, "VEC3");
       },
       "not finite"},
      {"lines", [](GltfBuilder& b) { b.j["meshes"][0]["primitives"][0]["mode"] = 1; }, "mode 1"},
      {"POSITION as VEC2",
       [](GltfBuilder& b) { b.j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 1; }, "element type"},
      {"absurd count", [](GltfBuilder& b) { b.j["accessors"][0]["count"] = 4000000000u; }, ""},
      {"missing accessor", [](GltfBuilder& b) { b.j["meshes"][0]["primitives"][0]["indices"] = 99; }, ""},
      {"node cycle", [](GltfBuilder& b) { b.j["nodes"][1]["children"] = {0}; }, ""},
      {"no meshes", [](GltfBuilder& b) { b.j["scenes"][0]["nodes"] = json::array(); }, "no triangle"},
  };
  for (const auto& c : cases) {
    GltfBuilder b = quad();
    c.spoil(b);
    const std::string why = refusal([&] { parse(b); });
    EXPECT_NE(why.find("test.gltf"), std::string::npos) << c.what << ": " << why;
    EXPECT_NE(why.find(c.reason), std::string::npos) << c.what << ": " << why;
  }
  EXPECT_NE(refusal([] { parse_gltf_scene("not json", "junk.gltf", ".", options()); }).find("junk.gltf"),
            std::string::npos);
  EXPECT_NE(refusal([] { parse_gltf_scene(std::string("glTF\2\0\0\0", 8), "cut.glb", ".", options()); }).find("cut.glb"),
            std::string::npos);
}

TEST(GltfScene, KhronosBoxTexturedImportsWithItsAccessorCounts) {
  SKIP_WITHOUT_MODELS();
  for (const char* f : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                        "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    const fs::path file = kModels / f;
    const json j = gltf_json(file);
    const Counts want = expected_counts(j);
    EXPECT_EQ(want.vertices, 24u);
    EXPECT_EQ(want.triangles, 12u);
    const Scene s = load_gltf_scene(file, options("linen_plain"));
    const Counts got = imported_counts(s);
    EXPECT_EQ(got.vertices, want.vertices) << f;
    EXPECT_EQ(got.triangles, want.triangles) << f;
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].material, Material::cloth);  // its material is no preset: the fallback applies
    EXPECT_EQ(s.objects[0].mesh.uvs.size(), 24u);
    for (size_t v = 0; v < 24; ++v) {
      EXPECT_NEAR(glm::length(s.objects[0].mesh.warps[v]), 1.0, 1e-9);
      EXPECT_NEAR(glm::dot(s.objects[0].mesh.warps[v], s.objects[0].mesh.normals[v]), 0.0, 1e-9);
    }
  }
}

TEST(GltfScene, BoxRootMatrixUndoesTheFrameChange) {
  SKIP_WITHOUT_MODELS();
  // The Khronos box's root node maps Z-up to Y-up ((x, y, z) → (x, z, −y)); Weft's change back
  // makes each imported vertex its accessor's own value.
  const fs::path file = kModels / "BoxTextured-glTF-Binary/BoxTextured.glb";
  const json j = gltf_json(file);
  ASSERT_EQ(j["nodes"][0]["matrix"], json({1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1}));
  const std::string b = read_bytes(file);
  uint32_t json_length;
  std::memcpy(&json_length, b.data() + 12, 4);
  const char* bin = b.data() + 20 + json_length + 8;
  const json& acc = j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>()];
  const json& view = j["bufferViews"][acc["bufferView"].get<int>()];
  const size_t offset = view.value("byteOffset", 0) + acc.value("byteOffset", 0);
  const size_t stride = view.value("byteStride", 12);
  const Scene s = load_gltf_scene(file, options());
  ASSERT_EQ(s.objects.size(), 1u);
  for (size_t v = 0; v < 24; ++v) {
    float p[3];
    std::memcpy(p, bin + offset + v * stride, 12);
    expect_near(s.objects[0].mesh.positions[v], {p[0], p[1], p[2]}, 1e-6);
  }
}

TEST(GltfScene, TwoCylinderEngineHierarchyImportsEveryInstance) {
  SKIP_WITHOUT_MODELS();
  const fs::path file = kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  const json j = gltf_json(file);
  const Counts want = expected_counts(j);
  size_t dropped = 0;
  const Scene s = load_gltf_scene(file, options());
  const Counts got = imported_counts(s, &dropped);
  EXPECT_EQ(got.vertices, want.vertices);
  EXPECT_EQ(got.triangles + dropped, want.triangles);
  EXPECT_GT(s.objects.size(), 1u);  // one object per material used
  for (const auto& o : s.objects) EXPECT_EQ(o.material, Material::lambertian);
}

TEST(GltfScene, CamerasFileGivesItsPerspectiveCamera) {
  SKIP_WITHOUT_MODELS();
  const Scene s = load_gltf_scene(kModels / "cameras/Cameras.gltf", options());
  // Node 1: translation (0.5, 0.5, 3), yfov 0.7 rad, looking down glTF −z (Weft +y), up glTF +y (Weft +z).
  expect_near(s.camera.position, {0.5, -3.0, 0.5});
  expect_near(glm::normalize(s.camera.target - s.camera.position), {0, 1, 0});
  expect_near(s.camera.up, {0, 0, 1});
  EXPECT_NEAR(s.camera.fov_deg, 0.7 * 180 / M_PI, 1e-9);
}

TEST(GltfScene, BrokenSampleFilesAreRefusedWithAReason) {
  SKIP_WITHOUT_MODELS();
  const std::vector<std::pair<const char*, const char*>> cases = {
      {"IndexOutOfRange/IndexOutOfRange.gltf", "index 255 is out of range (24 vertices)"},
      {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "out of range"},
      {"MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
      {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "not finite"},
      {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", "zero-length normal"},
      {"RecursiveNodes/RecursiveNodes.gltf", "not a tree"},
      {"TestNoRootNode/SceneWithoutNodes.gltf", "no triangle meshes"},
      {"IncorrectVertexArrays/Cube.gltf", "mode 1"},
  };
  for (const auto& [f, reason] : cases) {
    const fs::path file = kModels / f;
    const std::string why = refusal([&] { load_gltf_scene(file, options()); });
    EXPECT_NE(why.find(file.string()), std::string::npos) << f << ": " << why;
    EXPECT_NE(why.find(reason), std::string::npos) << f << ": " << why;
  }
  // The cameras sample has neither UVs nor tangents: as cloth it gets a fixed warp and no weave.
  const Scene cameras = load_gltf_scene(kModels / "cameras/Cameras.gltf", options("linen_plain"));
  bool noted = false;
  for (const std::string& w : cameras.warnings) noted = noted || w.find("no weave") != std::string::npos;
  EXPECT_TRUE(noted);
  for (const auto& o : cameras.objects)
    for (size_t v = 0; v < o.mesh.warps.size(); ++v) {
      EXPECT_NEAR(glm::length(o.mesh.warps[v]), 1.0, 1e-9);
      EXPECT_NEAR(glm::dot(o.mesh.warps[v], o.mesh.normals[v]), 0.0, 1e-9);
    }
}

TEST(GltfScene, PrimitiveModesOtherThanTrianglesAreRefused) {
  SKIP_WITHOUT_MODELS();
  const fs::path dir = kModels / "glTF-Asset-Generator/Mesh_PrimitiveMode";
  int triangles = 0, others = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".gltf") continue;
    const json j = gltf_json(e.path());
    const int mode = j["meshes"][0]["primitives"][0].value("mode", 4);
    const std::string why = refusal([&] { load_gltf_scene(e.path(), options()); });
    if (mode == 4) {
      ++triangles;
      EXPECT_EQ(why, "") << e.path();
    } else {
      ++others;
      EXPECT_NE(why.find("mode " + std::to_string(mode)), std::string::npos) << e.path() << ": " << why;
    }
  }
  EXPECT_GT(triangles, 0);
  EXPECT_GT(others, 0);
}

TEST(GltfScene, EverySampleFileImportsOrIsRefusedWithoutCrashing) {
  SKIP_WITHOUT_MODELS();
  int loaded = 0, refused = 0;
  for (const auto& e : fs::recursive_directory_iterator(kModels)) {
    if (!is_gltf_path(e.path().string())) continue;
    for (const std::string fallback : {"", "linen_plain"}) {
      try {
        const Scene s = load_gltf_scene(e.path(), options(fallback));
        EXPECT_FALSE(s.objects.empty());
        ++loaded;
      } catch (const SceneError& err) {
        EXPECT_NE(std::string(err.what()).find(e.path().string()), std::string::npos) << err.what();
        ++refused;
      }
    }
  }
  EXPECT_GT(loaded, 10);
  EXPECT_GT(refused, 10);
}

TEST(GltfScene, BlenderCopySuffixMatchesItsPreset) {
  GltfBuilder b = quad();
  b.j["materials"][0] = {{"name", "linen_plain.001"}};
  EXPECT_EQ(parse(b).objects[0].fabric, "linen_plain");
  EXPECT_TRUE(parse(b).warnings.empty());  // the preset's own name: nothing inferred to report
  b.j["materials"][0] = {{"name", ".001"}};
  EXPECT_EQ(parse(b).objects[0].material, Material::lambertian);
  // No copy suffix: not the preset's name, but the word "linen" in it is (the name rule, logged).
  for (const std::string name : {"linen_plain.", "linen_plain.a01", "linen_plain.001.002x"}) {
    b.j["materials"][0] = {{"name", name}};
    const Scene s = parse(b);
    EXPECT_EQ(s.objects[0].fabric, "linen_plain") << name;
    ASSERT_EQ(s.warnings.size(), 1u) << name;
    EXPECT_NE(s.warnings[0].find("taken as cloth (name: linen)"), std::string::npos) << s.warnings[0];
  }
}

// The preset file's own numbers, read here as plain JSON: what the import must keep or scale.
json preset_json(const std::string& name) { return json::parse(read_bytes(kFabrics / (name + ".json"))); }

TEST(GltfScene, BaseColorFactorColoursTheNamedFabricAtEachThreadsScale) {
  GltfBuilder b = quad();
  b.j["materials"][0]["pbrMetallicRoughness"] = {{"baseColorFactor", {0.8, 0.1, 0.05, 1.0}}};
  const Scene s = parse(b);
  const SceneObject& o = s.objects[0];
  ASSERT_TRUE(o.colour.has_value());
  expect_near(*o.colour, dvec3(0.8, 0.1, 0.05));
  const json file = preset_json("linen_plain");
  const Fabric coloured = object_base_fabric(o, load_fabric_preset("linen_plain", kFabrics));
  for (int t = 0; t < 2; ++t) {
    const double scale = file["threads"][t]["albedo_scale"].get<double>();
    expect_near(coloured.threads[t].albedo, scale * dvec3(0.8, 0.1, 0.05), 1e-12);
    // The fabric keeps its weave, gloss and thread structure.
    EXPECT_NEAR(glm::degrees(coloured.threads[t].gamma_s), file["threads"][t]["gamma_s_deg"].get<double>(), 1e-9);
    EXPECT_NEAR(coloured.threads[t].kd, file["threads"][t]["kd"].get<double>(), 1e-12);
  }
  EXPECT_EQ(coloured.weave.ends_per_cm, file["weave"]["ends_per_cm"].get<double>());

  // Shot silk: one product colour on both threads, each at its own scale (0.2 and 0.6).
  b.j["materials"][0]["extras"]["weft"]["fabric"] = "silk_shot";
  const Scene silk = parse(b);
  const Fabric shot = object_base_fabric(silk.objects[0], load_fabric_preset("silk_shot", kFabrics));
  const json silk_file = preset_json("silk_shot");
  for (int t = 0; t < 2; ++t)
    expect_near(shot.threads[t].albedo, silk_file["threads"][t]["albedo_scale"].get<double>() * dvec3(0.8, 0.1, 0.05), 1e-12);

  // No baseColorFactor in the file (glTF's default white): the fabric's own colour.
  const Scene plain = parse(quad());
  EXPECT_FALSE(plain.objects[0].colour.has_value());
  const Fabric own = object_base_fabric(plain.objects[0], load_fabric_preset("linen_plain", kFabrics));
  const auto& c = file["threads"][0]["albedo"];
  expect_near(own.threads[0].albedo, file["threads"][0]["albedo_scale"].get<double>() *
                                          dvec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()), 1e-12);
}

TEST(GltfScene, AFabricThatPinsItsColourKeepsItUnderAProductColour) {
  const fs::path dir = fs::temp_directory_path() / "weft_gltf_pinned_test";
  fs::create_directories(dir);
  json pinned = preset_json("velvet");
  pinned["pin_colour"] = true;
  std::ofstream(dir / "house_velvet.json") << pinned.dump();
  GltfBuilder b = quad();
  b.j["materials"][0]["extras"]["weft"]["fabric"] = "house_velvet.json";
  b.j["materials"][0]["pbrMetallicRoughness"] = {{"baseColorFactor", {0.9, 0.0, 0.0, 1.0}}};
  std::ofstream(dir / "quad.gltf") << b.text();
  const Scene s = load_gltf_scene(dir / "quad.gltf", options());
  ASSERT_TRUE(s.objects[0].colour.has_value());  // the product's colour is kept, the fabric declines it
  const Fabric file_fabric = load_fabric(dir / "house_velvet.json");
  EXPECT_TRUE(file_fabric.pin_colour);
  const Fabric drawn = object_base_fabric(s.objects[0], file_fabric);
  const Fabric preset = load_fabric_preset("velvet", kFabrics);
  for (int t = 0; t < 2; ++t) expect_near(drawn.threads[t].albedo, preset.threads[t].albedo, 0.0);
  pinned["pin_colour"] = "yes";
  try {
    parse_fabric(pinned.dump(), "house_velvet.json");
    FAIL() << "pin_colour \"yes\" was accepted";
  } catch (const FabricError& e) {
    EXPECT_NE(std::string(e.what()).find("pin_colour"), std::string::npos) << e.what();
  }
}

TEST(GltfScene, AClothColourOutsideZeroToOneIsRefusedNamingTheMaterial) {
  GltfBuilder b = quad();
  b.j["materials"][0]["pbrMetallicRoughness"] = {{"baseColorFactor", {1.5, 0.1, 0.1, 1.0}}};
  const std::string why = refusal([&] { parse(b); });
  EXPECT_NE(why.find("test.gltf"), std::string::npos) << why;
  EXPECT_NE(why.find("baseColorFactor"), std::string::npos) << why;
  EXPECT_NE(why.find("'Sofa'"), std::string::npos) << why;
}

// The quad with KHR_materials_variants: "Sofa" (linen, red) by default; variant "Ocean" dresses it
// in material 1 (linen, blue), "Moss" in material 2 (velvet, green), "Red" leaves it as it is.
GltfBuilder quad_with_variants() {
  GltfBuilder b = quad();
  b.j["materials"][0]["pbrMetallicRoughness"] = {{"baseColorFactor", {0.7, 0.1, 0.1, 1.0}}};
  b.j["materials"].push_back({{"name", "Sofa_ocean"}, {"extras", {{"weft", {{"fabric", "linen_plain"}}}}},
                              {"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.3, 0.6, 1.0}}}}});
  b.j["materials"].push_back({{"name", "velvet"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.5, 0.1, 1.0}}}}});
  b.j["materials"].push_back({{"name", "Wood"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.4, 0.3, 0.2, 1.0}}}}});
  b.j["extensionsUsed"] = json::array({"KHR_materials_variants"});
  b.j["extensions"]["KHR_materials_variants"]["variants"] = json::array({{{"name", "Red"}}, {{"name", "Ocean"}}, {{"name", "Moss"}}});
  b.j["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] =
      json::array({{{"material", 1}, {"variants", {1}}}, {{"material", 2}, {"variants", {2}}}});
  return b;
}

TEST(GltfScene, MaterialVariantsBecomeColourwaysWithTheirMaterialsColours) {
  const Scene s = parse(quad_with_variants());
  EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];  // the extension is read, not ignored
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.colourways.size(), 3u);
  const std::vector<std::tuple<std::string, std::string, dvec3>> expected = {
      {"Red", "linen_plain", {0.7, 0.1, 0.1}}, {"Ocean", "linen_plain", {0.1, 0.3, 0.6}}, {"Moss", "velvet", {0.2, 0.5, 0.1}}};
  for (size_t k = 0; k < expected.size(); ++k) {
    const auto& [name, fabric, colour] = expected[k];
    EXPECT_EQ(s.colourways[k].name, name);
    ASSERT_EQ(s.colourways[k].objects.count("Sofa"), 1u) << name;
    const ClothLook& look = s.colourways[k].objects.at("Sofa");
    EXPECT_EQ(look.fabric, fabric) << name;
    ASSERT_TRUE(look.colour.has_value()) << name;
    expect_near(*look.colour, colour);
  }
  // Worn: the colourway's fabric in its colour, at that fabric's thread scales.
  Scene worn = s;
  wear_looks(worn, colourway_looks(s, cloth_looks(s), 2));
  const Fabric moss = object_base_fabric(worn.objects[0], load_fabric_preset("velvet", kFabrics));
  const json velvet = preset_json("velvet");
  for (int t = 0; t < 2; ++t)
    expect_near(moss.threads[t].albedo, velvet["threads"][t]["albedo_scale"].get<double>() * dvec3(0.2, 0.5, 0.1), 1e-12);
  EXPECT_EQ(worn_fabrics(s), (std::vector<std::string>{"linen_plain", "velvet"}));
}

TEST(GltfScene, BadMaterialVariantsAreRefusedNamingTheFileAndTheProblem) {
  const auto refused = [](GltfBuilder b, const std::vector<std::string>& words) {
    const std::string why = refusal([&] { parse(b); });
    EXPECT_NE(why.find("test.gltf"), std::string::npos) << why;
    for (const auto& w : words) EXPECT_NE(why.find(w), std::string::npos) << "'" << w << "' not in: " << why;
  };
  GltfBuilder missing_material = quad_with_variants();
  missing_material.j["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][1]["material"] = 9;
  refused(missing_material, {"mappings[1].material", "material 9", "does not exist", "4 materials"});
  GltfBuilder missing_variant = quad_with_variants();
  missing_variant.j["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][0]["variants"] = {5};
  refused(missing_variant, {"mappings[0].variants[0]", "3 variants"});
  GltfBuilder empty = quad_with_variants();
  empty.j["extensions"]["KHR_materials_variants"]["variants"] = json::array();
  refused(empty, {"KHR_materials_variants.variants", "non-empty"});
  GltfBuilder unnamed = quad_with_variants();
  unnamed.j["extensions"]["KHR_materials_variants"]["variants"][1] = {{"name", 5}};
  refused(unnamed, {"variants[1]", "no name"});
  GltfBuilder twice = quad_with_variants();
  twice.j["extensions"]["KHR_materials_variants"]["variants"][2]["name"] = "Red";
  refused(twice, {"'Red'", "taken"});
  GltfBuilder to_wood = quad_with_variants();
  to_wood.j["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][0]["material"] = 3;
  refused(to_wood, {"variant 'Ocean'", "'Wood'", "is not"});
  GltfBuilder bad_colour = quad_with_variants();
  bad_colour.j["materials"][1]["pbrMetallicRoughness"]["baseColorFactor"] = {0.1, -0.5, 0.6, 1.0};
  refused(bad_colour, {"Sofa_ocean", "baseColorFactor"});
  // Infinity or NaN cannot be spelled in JSON; a number too large for a double reads as one.
  std::string huge = quad_with_variants().text();
  const std::string blue = "[0.1,0.3,0.6,1.0]";
  ASSERT_NE(huge.find(blue), std::string::npos);
  huge.replace(huge.find(blue), blue.size(), "[0.1,1e999,0.6,1.0]");
  const std::string why = refusal([&] { parse_gltf_scene(huge, "test.gltf", fs::temp_directory_path(), options()); });
  EXPECT_NE(why.find("test.gltf"), std::string::npos) << why;
  EXPECT_FALSE(why.empty());
}

TEST(GltfScene, SceneFileColourwaysDressTheGltfsClothObjects) {
  const fs::path dir = fs::temp_directory_path() / "weft_gltf_colourways_test";
  fs::create_directories(dir);
  std::ofstream(dir / "quad.gltf") << quad().text();
  std::ofstream(dir / "room.json") << R"({"gltf": "quad.gltf", "colourways": [
      {"name": "Ocean", "objects": {"Sofa": {"fabric": "linen_plain", "colour": [0.1, 0.3, 0.6]}}},
      {"name": "Velvet", "objects": {"Sofa": {"fabric": "velvet"}}},
      {"name": "Sand", "objects": {"Sofa": {"colour": [0.8, 0.7, 0.5]}}}]})";
  SceneLoadOptions o;
  o.fabrics_dir = kFabrics;
  const Scene s = load_scene(dir / "room.json", o);
  ASSERT_EQ(s.colourways.size(), 3u);
  EXPECT_EQ(s.colourways[0].objects.at("Sofa"), (ClothLook{"linen_plain", dvec3(0.1, 0.3, 0.6)}));
  EXPECT_EQ(s.colourways[1].objects.at("Sofa"), (ClothLook{"velvet", std::nullopt}));
  EXPECT_EQ(s.colourways[2].objects.at("Sofa"), (ClothLook{"linen_plain", dvec3(0.8, 0.7, 0.5)}));  // keeps its fabric
  const auto refused = [&](const std::string& colourways, const std::vector<std::string>& words) {
    std::ofstream(dir / "bad.json") << R"({"gltf": "quad.gltf", "colourways": )" + colourways + "}";
    const std::string why = refusal([&] { load_scene(dir / "bad.json", o); });
    EXPECT_NE(why.find("bad.json"), std::string::npos) << why;
    for (const auto& w : words) EXPECT_NE(why.find(w), std::string::npos) << "'" << w << "' not in: " << why;
  };
  refused("[]", {"colourways", "empty"});
  refused(R"([{"name": "A", "objects": {"Chair": {"colour": [0.1, 0.2, 0.3]}}}])", {"colourways[0]", "'Chair'", "not a cloth object", "Sofa"});
  refused(R"([{"name": "A", "objects": {"Sofa": {"colour": [0.1, 1e999, 0.3]}}}])", {"1e999"});  // JSON has no NaN or infinity
  refused(R"([{"name": "A", "objects": {"Sofa": {"colour": [0.1, -0.2, 0.3]}}}])", {"colourways[0].objects.Sofa.colour", "[0, 1]"});
  refused(R"([{"name": "A", "objects": {"Sofa": {"colour": [0.1, 0.3]}}}])", {"colour", "got 2"});
  refused(R"([{"name": "A", "objects": {}}])", {"'A'", "dresses no object"});
  refused(R"([{"name": "A", "objects": {"Sofa": {"tint": 1}}}])", {"tint", "unknown"});
}

TEST(GltfScene, ExtensionsAreNamedWarnedOrRefused) {
  GltfBuilder b = quad();
  EXPECT_TRUE(parse(b).warnings.empty());
  b.j["extensionsUsed"] = json::array({"KHR_materials_clearcoat"});
  const Scene s = parse(b);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("KHR_materials_clearcoat"), std::string::npos) << s.warnings[0];
  b.j["extensionsUsed"] = json::array({"KHR_mesh_quantization", "EXT_texture_webp"});
  b.j["extensionsRequired"] = json::array({"KHR_mesh_quantization", "EXT_texture_webp"});
  try {
    parse(b);
    FAIL() << "a required extension was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("requires the glTF extension EXT_texture_webp"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test.gltf"), std::string::npos) << e.what();
  }
}

// Cloth as pipelines author it (docs/design.md §1, "glTF materials as cloth"): the rule's cases
// are chosen far from its thresholds, and what each must give is read off the rule as written
// there, not off the code.
namespace {

// The quad's material replaced by `material`; its "name" is what the name rule reads.
GltfBuilder quad_with(const json& material) {
  GltfBuilder b = quad();
  b.j["materials"][0] = material;
  return b;
}

json sheen_material(const std::string& name, const std::vector<double>& base, double base_roughness,
                    const std::vector<double>& sheen, double sheen_roughness) {
  json m = {{"name", name},
            {"pbrMetallicRoughness", {{"roughnessFactor", base_roughness}}},
            {"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", sheen}, {"sheenRoughnessFactor", sheen_roughness}}}}}};
  if (!base.empty()) m["pbrMetallicRoughness"]["baseColorFactor"] = {base[0], base[1], base[2], 1.0};
  return m;
}

bool any_warning_has(const Scene& s, const std::vector<std::string>& words) {
  for (const std::string& w : s.warnings)
    if (std::all_of(words.begin(), words.end(), [&](const std::string& x) { return w.find(x) != std::string::npos; }))
      return true;
  return false;
}

std::string all_warnings(const Scene& s) {
  std::string out;
  for (const std::string& w : s.warnings) out += w + "\n";
  return out;
}

}  // namespace

TEST(GltfSheenCloth, NameWordsSplitAsExportersJoinThem) {
  using W = std::vector<std::string>;
  EXPECT_EQ(material_name_words("Fabric_Boucle.001"), (W{"fabric", "boucle"}));
  EXPECT_EQ(material_name_words("Sofa Velvet-2"), (W{"sofa", "velvet"}));
  EXPECT_EQ(material_name_words("sofaVelvet"), (W{"sofa", "velvet"}));
  EXPECT_EQ(material_name_words("SOFAVelvet"), (W{"sofa", "velvet"}));
  EXPECT_EQ(material_name_words("OAK_LEGS.012"), (W{"oak", "legs"}));
  EXPECT_EQ(material_name_words("Bouclé"), (W{"bouclé"}));
  EXPECT_EQ(material_name_words(".001"), W{});
}

TEST(GltfSheenCloth, ASheenMaterialIsClothInThePresetItsFactorsDescribe) {
  struct Case {
    const char* what;
    json material;
    std::string preset;
    dvec3 colour;
  };
  const std::vector<Case> cases = {
      // A dark base under a bright sheen on a matte base: a pile, coloured by its sheen (the sheen
      // is more than twice the base).
      {"velvet", sheen_material("Seat", {0.075, 0.06, 0.04}, 0.7, {0.9, 0.7, 0.6}, 0.6), "velvet", {0.9, 0.7, 0.6}},
      // A faint, soft sheen over a matte, lighter base: a plain weave in the base colour.
      {"linen", sheen_material("Seat", {0.6, 0.5, 0.4}, 0.9, {0.2, 0.2, 0.2}, 0.8), "linen_plain", {0.6, 0.5, 0.4}},
      // A glossy base: the satin's float highlight, the crêpe's softer one; the base colour.
      {"satin", sheen_material("Seat", {0.7, 0.2, 0.3}, 0.1, {0.3, 0.3, 0.3}, 0.3), "polyester_satin_charmeuse",
       {0.7, 0.2, 0.3}},
      {"crêpe", sheen_material("Seat", {0.2, 0.6, 0.3}, 0.32, {0.3, 0.3, 0.3}, 0.3), "silk_crepe_de_chine",
       {0.2, 0.6, 0.3}},
      // A strong, sharp sheen over a lighter base: the spec's own velvet example, whose base is
      // glTF's default white (not outshone: the threads take that white).
      {"spec's velvet", sheen_material("Seat", {}, 1.0, {0.9, 0.9, 0.9}, 0.0), "velvet", {1.0, 1.0, 1.0}},
      // The same base as the velvet but the sheen less than twice it: the base colour.
      {"pale velvet", sheen_material("Seat", {0.76, 0.53, 0.54}, 0.75, {1.0, 0.9, 0.9}, 0.85), "velvet",
       {0.76, 0.53, 0.54}},
  };
  for (const Case& c : cases) {
    GltfBuilder b = quad_with(c.material);
    b.j["extensionsUsed"] = json::array({"KHR_materials_sheen"});
    const Scene s = parse(b);
    ASSERT_EQ(s.objects.size(), 1u) << c.what;
    const SceneObject& o = s.objects[0];
    EXPECT_EQ(o.material, Material::cloth) << c.what;
    EXPECT_EQ(o.fabric, c.preset) << c.what;
    ASSERT_TRUE(o.colour.has_value()) << c.what;
    expect_near(*o.colour, c.colour);
    // Read, not ignored, and logged with the preset it chose.
    EXPECT_FALSE(any_warning_has(s, {"ignores"})) << all_warnings(s);
    EXPECT_TRUE(any_warning_has(s, {"test.gltf", "material 'Seat' taken as cloth (KHR_materials_sheen", "preset " + c.preset}))
        << c.what << ": " << all_warnings(s);
    // The threads carry the colour at the preset's own scales.
    const json file = preset_json(c.preset);
    const Fabric worn = object_base_fabric(o, load_fabric_preset(c.preset, kFabrics));
    for (int t = 0; t < 2; ++t)
      expect_near(worn.threads[t].albedo, file["threads"][t]["albedo_scale"].get<double>() * c.colour, 1e-12);
  }
}

TEST(GltfSheenCloth, AZeroOrAbsentSheenColourIsNoSheen) {
  for (const json& sheen : {json{{"sheenColorFactor", {0, 0, 0}}, {"sheenRoughnessFactor", 0.5}},
                            json{{"sheenRoughnessFactor", 0.3}}, json::object()}) {
    GltfBuilder b = quad_with({{"name", "Seat"},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {0.3, 0.4, 0.5, 1}}}},
                               {"extensions", {{"KHR_materials_sheen", sheen}}}});
    const Scene s = parse(b);
    EXPECT_EQ(s.objects[0].material, Material::lambertian) << sheen.dump();
    expect_near(s.objects[0].albedo, {0.3, 0.4, 0.5});
    EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
    // Nothing is cloth, so the fallback still dresses everything.
    EXPECT_EQ(parse(b, options("silk_shot")).objects[0].fabric, "silk_shot");
  }
}

TEST(GltfSheenCloth, ExtrasFabricAndAPresetsNameOverrideTheSheen) {
  json m = sheen_material("Seat", {0.05, 0.05, 0.3}, 0.8, {0.9, 0.9, 0.9}, 0.2);  // velvet by its sheen
  m["extras"]["weft"]["fabric"] = "linen_plain";
  const Scene s = parse(quad_with(m));
  EXPECT_EQ(s.objects[0].fabric, "linen_plain");
  ASSERT_TRUE(s.objects[0].colour.has_value());
  expect_near(*s.objects[0].colour, {0.05, 0.05, 0.3});  // the base colour, as any cloth's
  EXPECT_FALSE(any_warning_has(s, {"taken as cloth"})) << all_warnings(s);
  m.erase("extras");
  m["name"] = "silk_shot.002";
  EXPECT_EQ(parse(quad_with(m)).objects[0].fabric, "silk_shot");
}

TEST(GltfSheenCloth, ExportNamesOfFabricsAreClothByName) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"Velvet.001", "velvet"},          {"SOFA-velvet 2", "velvet"},       {"sofaVelvets", "velvet"},
      {"Fabric_Boucle.001", "linen_plain"}, {"Cotton Linen", "linen_plain"}, {"Wool_Throw", "linen_plain"},
      {"Satin.003", "polyester_satin_charmeuse"}, {"Silk cushion", "silk_crepe_de_chine"},
      {"Textile", "linen_plain"},        {"Upholstery.002", "linen_plain"}, {"Cloth", "linen_plain"},
  };
  for (const auto& [name, preset] : cases) {
    const Scene s = parse(quad_with({{"name", name}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.4, 0.2, 0.1, 1}}}}}));
    EXPECT_EQ(s.objects[0].material, Material::cloth) << name;
    EXPECT_EQ(s.objects[0].fabric, preset) << name;
    ASSERT_TRUE(s.objects[0].colour.has_value()) << name;
    expect_near(*s.objects[0].colour, {0.4, 0.2, 0.1});
    EXPECT_TRUE(any_warning_has(s, {"material '" + name + "' taken as cloth (name", "preset " + preset})) << all_warnings(s);
  }
  // Without a colour a name keeps the preset's own, as a preset's name does.
  EXPECT_FALSE(parse(quad_with({{"name", "Velvet.001"}})).objects[0].colour.has_value());
  // A velvet named so, as Khronos' GlamVelvetSofa's: the name gives the weave, the sheen that
  // outshines its near-black ground the colour.
  const Scene navy =
      parse(quad_with(sheen_material("GlamVelvetSofa_fabric_navy", {0.01, 0.01, 0.01}, 0.7, {0.05, 0.17, 0.5}, 0.6)));
  EXPECT_EQ(navy.objects[0].fabric, "velvet");
  ASSERT_TRUE(navy.objects[0].colour.has_value());
  expect_near(*navy.objects[0].colour, {0.05, 0.17, 0.5});
  // A fabric's own word outweighs the sheen; a generic word leaves the weave to the sheen.
  const json glossy_velvet_sheen = sheen_material("Linen.001", {0.05, 0.05, 0.05}, 0.8, {0.9, 0.9, 0.9}, 0.2);
  EXPECT_EQ(parse(quad_with(glossy_velvet_sheen)).objects[0].fabric, "linen_plain");
  EXPECT_EQ(parse(quad_with(sheen_material("Upholstery", {0.5, 0.5, 0.5}, 0.1, {0.2, 0.2, 0.2}, 0.5))).objects[0].fabric,
            "polyester_satin_charmeuse");
}

TEST(GltfSheenCloth, HardAmbiguousAndUnknownNamesStayLambertian) {
  for (const std::string name : {"Oak_Legs", "Wood", "Chrome.001", "Steel feet", "Plastic", "Leather_Seat", "Wood_Fabric",
                                 "Velvet_Satin", "Velvety", "Cottonwood", "Sofa"}) {
    const Scene s = parse(quad_with({{"name", name}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.4, 0.3, 0.2, 1}}}}}));
    EXPECT_EQ(s.objects[0].material, Material::lambertian) << name;
    expect_near(s.objects[0].albedo, {0.4, 0.3, 0.2});
  }
  EXPECT_TRUE(any_warning_has(parse(quad_with({{"name", "Velvet_Satin"}})), {"'Velvet_Satin'", "velvet, satin"}));
  // A sheen on a part named as wood or metal does not make it cloth, and the log says why.
  const Scene oak = parse(quad_with(sheen_material("Oak_Legs", {0.4, 0.3, 0.2}, 0.8, {0.9, 0.9, 0.9}, 0.3)));
  EXPECT_EQ(oak.objects[0].material, Material::lambertian);
  EXPECT_TRUE(any_warning_has(oak, {"'Oak_Legs' not taken as cloth", "oak, legs"})) << all_warnings(oak);
  // Cloth and wood words together are no verdict: the sheen decides.
  EXPECT_EQ(parse(quad_with(sheen_material("Wood_Fabric", {0.6, 0.5, 0.4}, 0.9, {0.2, 0.2, 0.2}, 0.8))).objects[0].fabric,
            "linen_plain");
}

TEST(GltfSheenCloth, AProductFileAsExportedHasClothSeatAndWoodenLegs) {
  GltfBuilder b = quad_with(sheen_material("Fabric_Boucle.001", {0.55, 0.5, 0.45}, 0.9, {0.3, 0.3, 0.3}, 0.7));
  b.j["materials"].push_back({{"name", "Oak_Legs"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.35, 0.2, 1}}}}});
  json legs = b.j["meshes"][0];
  legs["primitives"][0]["material"] = 1;
  b.j["meshes"].push_back(legs);
  b.j["nodes"].push_back({{"mesh", 1}, {"translation", {0, -1, 0}}});
  b.j["scenes"][0]["nodes"].push_back(2);
  b.j["extensionsUsed"] = json::array({"KHR_materials_sheen"});
  const Scene s = parse(b, options("silk_shot"));  // the fallback is for files with no cloth at all
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].name, "Fabric_Boucle.001");
  EXPECT_EQ(s.objects[0].fabric, "linen_plain");
  expect_near(*s.objects[0].colour, {0.55, 0.5, 0.45});
  EXPECT_EQ(s.objects[1].name, "Oak_Legs");
  EXPECT_EQ(s.objects[1].material, Material::lambertian);
  expect_near(s.objects[1].albedo, {0.5, 0.35, 0.2});
  EXPECT_TRUE(any_warning_has(s, {"material 'Fabric_Boucle.001' taken as cloth (name: fabric, boucle), preset linen_plain"}))
      << all_warnings(s);
}

TEST(GltfSheenCloth, ASceneFilesFabricOverridesTheSheen) {
  const fs::path dir = fs::temp_directory_path() / "weft_gltf_sheen_scene_file_test";
  fs::create_directories(dir);
  std::ofstream(dir / "sofa.gltf") << quad_with(sheen_material("Seat", {0.1, 0.1, 0.4}, 0.8, {0.8, 0.8, 0.9}, 0.3)).text();
  std::ofstream(dir / "room.json") << R"({"gltf": "sofa.gltf", "fabrics": {"Seat": "silk_shot"}})";
  SceneLoadOptions o;
  o.fabrics_dir = kFabrics;
  EXPECT_EQ(load_scene(dir / "sofa.gltf", o).objects.at(0).fabric, "velvet");  // by its sheen alone
  const Scene s = load_scene(dir / "room.json", o);
  EXPECT_EQ(s.objects.at(0).fabric, "silk_shot");
  ASSERT_TRUE(s.objects.at(0).colour.has_value());
  expect_near(*s.objects.at(0).colour, {0.1, 0.1, 0.4});  // the base colour, as any cloth's
}

TEST(GltfSheenCloth, BadSheenFactorsAreRefusedOrClampedWithANote) {
  const auto with_sheen = [](const json& sheen) {
    return quad_with({{"name", "Seat"}, {"extensions", {{"KHR_materials_sheen", sheen}}}});
  };
  for (const auto& [sheen, field] : std::vector<std::pair<json, std::string>>{
           {json{{"sheenColorFactor", "red"}}, "sheenColorFactor"},
           {json{{"sheenColorFactor", {0.5, 0.5}}}, "sheenColorFactor"},
           {json{{"sheenColorFactor", {0.5, "x", 0.5}}}, "sheenColorFactor[1]"},
           {json{{"sheenColorFactor", {0.5, 0.5, 0.5}}, {"sheenRoughnessFactor", "rough"}}, "sheenRoughnessFactor"}}) {
    const std::string why = refusal([&] { parse(with_sheen(sheen)); });
    EXPECT_NE(why.find("test.gltf"), std::string::npos) << sheen.dump() << ": " << why;
    EXPECT_NE(why.find("materials[0] ('Seat').extensions.KHR_materials_sheen"), std::string::npos) << why;
    EXPECT_NE(why.find(field), std::string::npos) << sheen.dump() << ": " << why;
  }
  // An extension that is no object is no sheen (tinygltf drops it).
  EXPECT_EQ(parse(with_sheen(json(3))).objects[0].material, Material::lambertian);
  // Out of range: clamped into [0, 1] and noted. The colour's 2 is 1 and its -0.5 is 0, the
  // roughness 1.5 is 1: a sheen of 1 is not below glTF's default white base, a pile.
  const Scene s = parse(with_sheen({{"sheenColorFactor", {2.0, 0.5, -0.5}}, {"sheenRoughnessFactor", 1.5}}));
  EXPECT_EQ(s.objects[0].material, Material::cloth);
  EXPECT_EQ(s.objects[0].fabric, "velvet");  // the sheen (1) is not below the base (1)
  EXPECT_TRUE(any_warning_has(s, {"sheenRoughnessFactor", "1.5", "clamped to 1"})) << all_warnings(s);
  EXPECT_TRUE(any_warning_has(s, {"sheenColorFactor[0]", "clamped to 1"})) << all_warnings(s);
  EXPECT_TRUE(any_warning_has(s, {"sheenColorFactor[2]", "clamped to 0"})) << all_warnings(s);
  // A number JSON cannot hold is refused whole or named, never taken.
  const std::string huge = refusal([&] {
    std::string text = with_sheen({{"sheenColorFactor", {0.5, 0.5, 0.5}}}).text();
    text.replace(text.find("0.5"), 3, "1e999");
    parse_gltf_scene(text, "test.gltf", fs::temp_directory_path(), options());
  });
  EXPECT_NE(huge.find("test.gltf"), std::string::npos) << huge;
}
