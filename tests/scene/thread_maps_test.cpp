// Cloth textures in scenes: KHR_texture_transform against its definition (T·R·S as matrices), a
// real textured glTF (Khronos' BoxTextured from Debian's assimp-testmodels) imported with its
// image on the cloth's threads, the transform and a weft's own map read from a glTF, a scene
// file's "texture", and bad images refused naming the file, the material and the image.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <functional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/gltf_scene.h"
#include "scene/scene_file.h"
#include "scene/thread_maps.h"

using namespace weft;
namespace fs = std::filesystem;

namespace {

const fs::path kBox = "/usr/share/assimp/models/glTF2/BoxTextured-glTF";

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// BoxTextured with its buffer and image beside it in `dir`, the glTF edited by `edit`.
fs::path box_copy(const std::string& dir_name, const std::function<void(nlohmann::json&)>& edit) {
  const fs::path dir = fs::temp_directory_path() / ("weft_thread_maps_" + dir_name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& e : fs::directory_iterator(kBox)) fs::copy_file(e.path(), dir / e.path().filename());
  nlohmann::json j = nlohmann::json::parse(read_text(kBox / "BoxTextured.gltf"));
  edit(j);
  std::ofstream(dir / "BoxTextured.gltf") << j.dump(1);
  return dir / "BoxTextured.gltf";
}

GltfImportOptions linen() {
  GltfImportOptions o;
  o.fabrics_dir = WEFT_SOURCE_ASSETS "/fabrics";
  o.fallback_fabric = "linen_plain";
  return o;
}

}  // namespace

TEST(TextureTransform, IsTranslationTimesRotationTimesScale) {
  // KHR_texture_transform's definition, as its three matrices on (u, v, 1).
  const TextureTransform t{{0.5, -0.25}, {2.0, 3.0}, 0.7};
  const glm::dmat3 T(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(t.offset, 1));
  const glm::dmat3 R(glm::dvec3(std::cos(t.rotation), -std::sin(t.rotation), 0),
                     glm::dvec3(std::sin(t.rotation), std::cos(t.rotation), 0), glm::dvec3(0, 0, 1));
  const glm::dmat3 S(glm::dvec3(t.scale.x, 0, 0), glm::dvec3(0, t.scale.y, 0), glm::dvec3(0, 0, 1));
  for (const glm::dvec2 uv : {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0.3, 0.8), glm::dvec2(-2, 5)}) {
    const glm::dvec3 expected = T * R * S * glm::dvec3(uv, 1.0);
    const glm::dvec2 got = transformed_uv(t, uv);
    EXPECT_NEAR(got.x, expected.x, 1e-12);
    EXPECT_NEAR(got.y, expected.y, 1e-12);
    const glm::dvec3 m = texture_matrix(t) * glm::dvec3(uv, 1.0);
    EXPECT_NEAR(m.x, expected.x, 1e-12);
    EXPECT_NEAR(m.y, expected.y, 1e-12);
  }
  // The extension's own example: a quarter turn maps u to −v.
  const glm::dvec2 q = transformed_uv({{0, 0}, {1, 1}, std::numbers::pi / 2}, {1, 0});
  EXPECT_NEAR(q.x, 0.0, 1e-12);
  EXPECT_NEAR(q.y, -1.0, 1e-12);
}

TEST(GltfTextures, ARealTexturedFilePutsItsImageOnTheThreads) {
  if (!fs::exists(kBox)) GTEST_SKIP() << kBox << " absent (apt-get install assimp-testmodels)";
  const Scene s = load_gltf_scene(kBox / "BoxTextured.gltf", linen());
  ASSERT_EQ(s.objects.size(), 1u);
  const SceneObject& o = s.objects[0];
  ASSERT_TRUE(o.is_cloth());
  ASSERT_TRUE(o.thread_maps[0] && o.thread_maps[1]);
  EXPECT_EQ(o.thread_maps[0]->image, o.thread_maps[1]->image);  // one image, both threads
  EXPECT_EQ(o.thread_maps[0]->image->width, 211);                // CesiumLogoFlat.png's IHDR
  EXPECT_EQ(o.thread_maps[0]->image->height, 211);
  EXPECT_EQ(o.thread_maps[0]->name, "CesiumLogoFlat.png");
  EXPECT_EQ(o.thread_maps[0]->transform, TextureTransform{});
  EXPECT_EQ(o.mesh.uvs.size(), o.mesh.positions.size());
  // The tint at a UV is the image's texel there.
  const glm::dvec3 tint = thread_tint(o, 0, {0.5, 0.5});
  EXPECT_EQ(tint, sample_texture(*o.thread_maps[0]->image, {0.5, 0.5}));
  EXPECT_EQ(thread_tint(SceneObject{}, 0, {0.5, 0.5}), glm::dvec3(1.0));
}

TEST(GltfTextures, ReadsKhrTextureTransformAndAWeftsOwnMap) {
  if (!fs::exists(kBox)) GTEST_SKIP() << kBox << " absent";
  const fs::path file = box_copy("transform", [](nlohmann::json& j) {
    j["extensionsUsed"] = {"KHR_texture_transform"};
    j["extensionsRequired"] = {"KHR_texture_transform"};
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
        {"offset", {0.25, 0.5}}, {"rotation", 0.3}, {"scale", {4.0, 2.0}}};
    j["materials"][0]["extras"]["weft"]["weft_texture"] = {
        {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {8.0, 8.0}}}}}}};
  });
  const Scene s = load_gltf_scene(file, linen());
  const SceneObject& o = s.objects.at(0);
  ASSERT_TRUE(o.thread_maps[0] && o.thread_maps[1]);
  EXPECT_EQ(o.thread_maps[0]->transform, (TextureTransform{{0.25, 0.5}, {4.0, 2.0}, 0.3}));
  EXPECT_EQ(o.thread_maps[1]->transform, (TextureTransform{{0.0, 0.0}, {8.0, 8.0}, 0.0}));
  EXPECT_EQ(o.thread_maps[0]->image, o.thread_maps[1]->image);  // the same image, decoded once
  for (const auto& w : s.warnings) EXPECT_EQ(w.find("KHR_texture_transform"), std::string::npos) << w;
}

// normalTexture: its image, scale and transform on the cloth, the colour maps untouched; no
// normal map gives the surface's own normal.
TEST(GltfTextures, ReadsANormalTextureWithItsScaleAndTransform) {
  if (!fs::exists(kBox)) GTEST_SKIP() << kBox << " absent";
  const fs::path file = box_copy("normal", [](nlohmann::json& j) {
    j["extensionsUsed"] = {"KHR_texture_transform"};
    j["materials"][0]["normalTexture"] = {
        {"index", 0}, {"scale", 0.5}, {"extensions", {{"KHR_texture_transform", {{"scale", {3.0, 3.0}}}}}}};
  });
  const Scene s = load_gltf_scene(file, linen());
  const SceneObject& o = s.objects.at(0);
  ASSERT_TRUE(o.normal_map);
  EXPECT_DOUBLE_EQ(o.normal_map->scale, 0.5);
  EXPECT_EQ(o.normal_map->map.transform, (TextureTransform{{0.0, 0.0}, {3.0, 3.0}, 0.0}));
  ASSERT_TRUE(o.normal_map->map.image);
  EXPECT_EQ(o.normal_map->map.image->width, 211);
  EXPECT_EQ(o.thread_maps[0]->transform, TextureTransform{});  // the base colour keeps its own
  const glm::dvec3 n = normal_map_tangent(o, {0.37, 0.61});
  EXPECT_NEAR(glm::length(n), 1.0, 1e-9);
  EXPECT_GT(n.z, 0.0);  // a tangent-space normal points out of the surface
  EXPECT_EQ(normal_map_tangent(SceneObject{}, {0.37, 0.61}), glm::dvec3(0.0, 0.0, 1.0));
}

TEST(GltfTextures, RefusesBadImagesNamingTheFileMaterialAndImage) {
  if (!fs::exists(kBox)) GTEST_SKIP() << kBox << " absent";
  auto expect_refused = [](const fs::path& file, const std::vector<std::string>& parts) {
    try {
      load_gltf_scene(file, linen());
      FAIL() << "accepted " << file;
    } catch (const SceneError& e) {
      for (const auto& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
  };
  // A missing image file.
  const fs::path missing = box_copy("missing", [](nlohmann::json& j) { j["images"][0]["uri"] = "gone.png"; });
  expect_refused(missing, {"BoxTextured.gltf", "materials[0] ('Texture')", "images[0]", "gone.png"});
  // A corrupt PNG.
  const fs::path corrupt = box_copy("corrupt", [](nlohmann::json&) {});
  {
    std::fstream f(corrupt.parent_path() / "CesiumLogoFlat.png", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(60);
    f.write("garbage!garbage!garbage!", 24);
  }
  expect_refused(corrupt, {"materials[0] ('Texture')", "images[0]", "CesiumLogoFlat.png", "PNG"});
  // A texture that does not exist, another TEXCOORD set, a bad transform.
  expect_refused(box_copy("index", [](nlohmann::json& j) { j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 7; }),
                 {"baseColorTexture", "texture 7"});
  expect_refused(box_copy("texcoord", [](nlohmann::json& j) { j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1; }),
                 {"TEXCOORD_1"});
  expect_refused(box_copy("scale", [](nlohmann::json& j) {
                   j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {{"scale", {0.0, 1.0}}};
                 }),
                 {"KHR_texture_transform", "scale of 0"});
}

TEST(SceneTextures, TheShippedPlaidPillowCarriesItsTexture) {
  const Scene s = load_scene_preset("plaid_pillow", WEFT_SOURCE_ASSETS "/scenes");
  const SceneObject& o = s.objects.at(0);
  ASSERT_TRUE(o.thread_maps[0] && o.thread_maps[1]);
  EXPECT_EQ(o.thread_maps[0]->name, "plaid.png");
  EXPECT_EQ(o.thread_maps[0]->image->width, 64);
  EXPECT_EQ(o.thread_maps[0]->transform.scale, glm::dvec2(4.0, 4.0));
  EXPECT_FALSE(s.objects.at(1).textured());  // the floor
  // A scene naming a missing image is refused naming the object's field and the file.
  nlohmann::json j = nlohmann::json::parse(read_text(WEFT_SOURCE_ASSETS "/scenes/plaid_pillow.json"));
  j["objects"][0]["texture"]["image"] = "../textures/none.png";
  try {
    parse_scene(j.dump(), "plaid_pillow.json", WEFT_SOURCE_ASSETS "/scenes");
    FAIL() << "accepted a missing image";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("objects[0].texture.image"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("none.png"), std::string::npos) << e.what();
  }
}

TEST(SceneTextures, ASceneObjectsNormalMapIsReadWithItsScaleAndTransform) {
  nlohmann::json j = nlohmann::json::parse(read_text(WEFT_SOURCE_ASSETS "/scenes/plaid_pillow.json"));
  j["objects"][0]["normal_map"] = {{"image", "../textures/plaid.png"}, {"scale", {2.0, 3.0}}, {"rotation", 0.5},
                                   {"normal_scale", 0.7}};
  const Scene s = parse_scene(j.dump(), "plaid_pillow.json", WEFT_SOURCE_ASSETS "/scenes");
  const SceneObject& o = s.objects.at(0);
  ASSERT_TRUE(o.normal_map);
  EXPECT_EQ(o.normal_map->map.name, "plaid.png");
  EXPECT_EQ(o.normal_map->map.transform.scale, glm::dvec2(2.0, 3.0));
  EXPECT_EQ(o.normal_map->map.transform.offset, glm::dvec2(0.0, 0.0));
  EXPECT_EQ(o.normal_map->map.transform.rotation, 0.5);
  EXPECT_EQ(o.normal_map->scale, 0.7);
  EXPECT_EQ(o.normal_map->map.image, o.thread_maps[0]->image);  // one file, read once
  EXPECT_FALSE(s.objects.at(1).normal_map);
  // Without normal_scale: 1, as glTF's default.
  j["objects"][0]["normal_map"].erase("normal_scale");
  EXPECT_EQ(parse_scene(j.dump(), "plaid_pillow.json", WEFT_SOURCE_ASSETS "/scenes").objects.at(0).normal_map->scale, 1.0);
  // Refusals name the field.
  auto refused = [&](const nlohmann::json& map, const std::string& field) {
    nlohmann::json bad = j;
    bad["objects"][0]["normal_map"] = map;
    try {
      parse_scene(bad.dump(), "plaid_pillow.json", WEFT_SOURCE_ASSETS "/scenes");
      ADD_FAILURE() << "accepted " << map.dump();
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("objects[0].normal_map" + field), std::string::npos) << e.what();
    }
  };
  refused({{"image", "../textures/plaid.png"}, {"normal_scale", "strong"}}, ".normal_scale");
  refused({{"image", "../textures/plaid.png"}, {"normal_scale", 1e9}}, ".normal_scale");
  refused({{"image", "../textures/plaid.png"}, {"strength", 1.0}}, ".strength");
  refused({{"image", "../textures/none.png"}}, ".image");
  refused({{"image", "../textures/plaid.png"}, {"scale", {0.0, 1.0}}}, "");
}
