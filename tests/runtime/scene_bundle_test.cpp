// The scene part of a bundle: what `weft bake` writes reads back as the same scene, and a bundle
// whose scene sections are wrong is refused naming the section.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "bake/writers/scene_bundle_writer.h"
#include "bundle/bundle_error.h"
#include "scene/scene_file.h"
#include "scene/vertex_pass_mesh.h"
#include "support/file_text.h"

using namespace weft;
namespace fs = std::filesystem;

namespace {

using weft::test::read_all;

SceneBundleInput pillow_input() {
  SceneBundleInput in;
  in.scene = load_scene_preset("pillow", fs::path(WEFT_SOURCE_ASSETS) / "scenes");
  for (const auto& o : in.scene.objects)
    if (o.material == Material::cloth)
      in.fabrics[o.fabric] = read_all(fs::path(WEFT_SOURCE_ASSETS) / "fabrics" / (o.fabric + ".json"));
  in.fabrics["silk_crepe_de_chine"] = read_all(fs::path(WEFT_SOURCE_ASSETS) / "fabrics" / "silk_crepe_de_chine.json");
  in.sgs = {SphericalGaussian{glm::normalize(glm::dvec3(0.3, -0.2, 1)), 12.0, glm::dvec3(2, 1.5, 1)},
            SphericalGaussian{glm::dvec3(0, 0, 1), 0.5, glm::dvec3(0.2, 0.25, 0.3)}};
  return in;
}

}  // namespace

TEST(SceneBundle, RoundTripsTheScene) {
  SceneBundleInput in = pillow_input();
  for (auto& o : in.scene.objects)
    if (o.material == Material::cloth) o.display_name = "Pillow linen", o.composition = "100 % linen";
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const SceneBundle out = read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));

  EXPECT_EQ(out.scene.name, in.scene.name);
  EXPECT_EQ(out.scene.environment, in.scene.environment);
  EXPECT_EQ(out.scene.camera.position, in.scene.camera.position);
  EXPECT_EQ(out.scene.camera.fov_deg, in.scene.camera.fov_deg);
  ASSERT_EQ(out.scene.objects.size(), in.scene.objects.size());
  for (size_t i = 0; i < in.scene.objects.size(); ++i) {
    const auto& a = in.scene.objects[i];
    const auto& b = out.scene.objects[i];
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.material, a.material);
    EXPECT_EQ(b.fabric, a.fabric);
    EXPECT_EQ(b.display_name, a.display_name);
    EXPECT_EQ(b.composition, a.composition);
    ASSERT_EQ(b.mesh.positions.size(), a.mesh.positions.size());
    ASSERT_EQ(b.mesh.triangles, a.mesh.triangles);
    for (size_t v = 0; v < a.mesh.positions.size(); ++v) {
      // Stored as f32: equal to float rounding.
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(b.mesh.positions[v][k], double(float(a.mesh.positions[v][k])));
        EXPECT_EQ(b.mesh.normals[v][k], double(float(a.mesh.normals[v][k])));
      }
      if (a.material == Material::cloth) {  // EXPECT_EQ is an if/else inside: braces keep it ours
        for (int k = 0; k < 3; ++k) EXPECT_EQ(b.mesh.warps[v][k], double(float(a.mesh.warps[v][k])));
      }
    }
  }
  // Every stored fabric parses to what the preset loader gives.
  ASSERT_EQ(out.fabrics.size(), 2u);
  for (const auto& [name, f] : out.fabrics) {
    const Fabric expected = load_fabric_preset(name, fs::path(WEFT_SOURCE_ASSETS) / "fabrics");
    EXPECT_EQ(f.name, expected.name);
    for (int t = 0; t < 2; ++t) {
      EXPECT_EQ(f.threads[t].albedo, expected.threads[t].albedo);
      EXPECT_EQ(f.threads[t].gamma_s, expected.threads[t].gamma_s);
    }
  }
  ASSERT_EQ(out.sgs.size(), 2u);
  EXPECT_NEAR(out.sgs[0].sharpness, 12.0, 1e-12);
  EXPECT_NEAR(glm::length(out.sgs[0].axis - in.sgs[0].axis), 0.0, 1e-12);
  EXPECT_EQ(out.sgs[1].amplitude, in.sgs[1].amplitude);
}

TEST(SceneBundle, RefusesBadSceneSectionsNamingThem) {
  SceneBundleInput in = pillow_input();
  auto expect_refused = [](const SceneBundleInput& input, const std::string& section, const std::string& words,
                           bool replace_fabric_text = false) {
    bundle::BundleWriter w;
    SceneBundleInput copy = input;
    if (replace_fabric_text) copy.fabrics.begin()->second = "{\"name\": 3}";
    add_scene_sections(w, copy);
    const auto bytes = w.to_bytes();
    try {
      read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));
      FAIL() << "accepted a bundle with a bad " << section;
    } catch (const bundle::BundleError& e) {
      EXPECT_EQ(e.section(), section) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  // A triangle pointing past the vertices.
  SceneBundleInput bad_index = in;
  bad_index.scene.objects[0].mesh.triangles[0][1] = uint32_t(bad_index.scene.objects[0].mesh.positions.size());
  expect_refused(bad_index, "mesh/0/indices", "refers to vertex");
  // A fabric that does not parse.
  expect_refused(in, "fabrics", "", true);
  // Non-finite vertex data.
  SceneBundleInput nan = in;
  nan.scene.objects[0].mesh.normals[3].y = std::nan("");
  expect_refused(nan, "mesh/0/normals", "non-finite");
}

TEST(SceneBundle, MissingSectionsAreNamed) {
  bundle::BundleWriter w;
  w.add_json("fabrics", "{\"linen_plain\": " + read_all(fs::path(WEFT_SOURCE_ASSETS) / "fabrics" / "linen_plain.json") + "}");
  w.add_json("scene", R"({"format":"weft-scene-bundle","version":1,"name":"x","camera":{"position":[0,-3,1],
      "target":[0,0,0],"up":[0,0,1],"fov_deg":40},"objects":[{"name":"floor","material":"lambertian","albedo":[0.5,0.5,0.5]}]})");
  const auto bytes = w.to_bytes();
  try {
    read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));
    FAIL() << "accepted a bundle without meshes";
  } catch (const bundle::BundleError& e) {
    EXPECT_EQ(e.section(), "mesh/0/positions") << e.what();
  }
}

TEST(SceneBundle, CarriesASheersOpticalThickness) {
  // The voile's τ in its fabric text, and an object's own override in the scene section.
  SceneBundleInput in = pillow_input();
  in.scene.objects[0].fabric = "polyester_voile";
  in.scene.objects[0].optical_thickness = 1.25;
  in.fabrics["polyester_voile"] = read_all(fs::path(WEFT_SOURCE_ASSETS) / "fabrics" / "polyester_voile.json");
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const SceneBundle out = read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));
  EXPECT_DOUBLE_EQ(out.fabrics.at("polyester_voile").optical_thickness, 0.4);
  EXPECT_DOUBLE_EQ(out.scene.objects[0].optical_thickness, 1.25);
  EXPECT_EQ(out.scene.objects[1].optical_thickness, 0.0);
  EXPECT_EQ(out.fabrics.at("silk_crepe_de_chine").optical_thickness, 0.0);  // Table II: opaque
  // An out-of-range override is refused naming the scene section.
  in.scene.objects[0].optical_thickness = 40.0;
  bundle::BundleWriter bad;
  add_scene_sections(bad, in);
  const auto bad_bytes = bad.to_bytes();
  try {
    read_scene_bundle(bundle::BundleReader::view(bad_bytes, "memory"));
    FAIL() << "accepted optical_thickness 40";
  } catch (const bundle::BundleError& e) {
    EXPECT_EQ(e.section(), "scene") << e.what();
    EXPECT_NE(std::string(e.what()).find("optical_thickness"), std::string::npos) << e.what();
  }
}

TEST(SceneBundle, CarriesAClothObjectsProductColour) {
  SceneBundleInput in = pillow_input();
  ASSERT_TRUE(in.scene.objects[0].is_cloth());
  in.scene.objects[0].colour = glm::dvec3(0.25, 0.5, 0.75);
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const SceneBundle out = read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));
  ASSERT_TRUE(out.scene.objects[0].colour.has_value());
  EXPECT_EQ(*out.scene.objects[0].colour, glm::dvec3(0.25, 0.5, 0.75));
  EXPECT_FALSE(out.scene.objects[1].colour.has_value());
  in.scene.objects[0].colour = glm::dvec3(0.25, 1.5, 0.75);
  bundle::BundleWriter bad;
  add_scene_sections(bad, in);
  const auto bad_bytes = bad.to_bytes();
  try {
    read_scene_bundle(bundle::BundleReader::view(bad_bytes, "memory"));
    FAIL() << "accepted a colour outside [0, 1]";
  } catch (const bundle::BundleError& e) {
    EXPECT_EQ(e.section(), "scene") << e.what();
    EXPECT_NE(std::string(e.what()).find("colour"), std::string::npos) << e.what();
  }
}

TEST(SceneBundle, RoundTripsTheColourwaysAndRefusesBadOnes) {
  SceneBundleInput in = pillow_input();
  in.scene.colourways = {{"Ocean", {{"pillow", {"linen_plain", glm::dvec3(0.1, 0.3, 0.6)}}}},
                         {"Crepe", {{"pillow", {"silk_crepe_de_chine", std::nullopt}}}}};
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const SceneBundle out = read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));
  ASSERT_EQ(out.scene.colourways.size(), 2u);
  EXPECT_EQ(out.scene.colourways[0].name, "Ocean");
  EXPECT_EQ(out.scene.colourways[0].objects, in.scene.colourways[0].objects);
  EXPECT_EQ(out.scene.colourways[1].objects, in.scene.colourways[1].objects);

  // A colourway dressing the floor (not cloth), and one naming a fabric the bundle lacks.
  const auto refused = [&](const SceneBundleInput& bad_in, const std::string& section, const std::string& words) {
    bundle::BundleWriter bad;
    add_scene_sections(bad, bad_in);
    const auto bad_bytes = bad.to_bytes();
    try {
      read_scene_bundle(bundle::BundleReader::view(bad_bytes, "memory"));
      ADD_FAILURE() << "accepted: " << words;
    } catch (const bundle::BundleError& e) {
      EXPECT_EQ(e.section(), section) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  SceneBundleInput floor = in;
  floor.scene.colourways[1].objects = {{"floor", {"linen_plain", std::nullopt}}};
  refused(floor, "scene", "'floor' is not a cloth object");
  SceneBundleInput missing = in;
  missing.fabrics.erase("silk_crepe_de_chine");
  bundle::BundleWriter w2;
  EXPECT_THROW(add_scene_sections(w2, missing), std::invalid_argument);  // the writer refuses it first
}

TEST(SceneBundle, CarriesTexturesAsVerifiedPngSections) {
  SceneBundleInput in = pillow_input();
  in.scene = load_scene_preset("plaid_pillow", fs::path(WEFT_SOURCE_ASSETS) / "scenes");
  ThreadMap weft = *in.scene.objects[0].thread_maps[0];
  weft.transform = {{0.1, 0.2}, {3.0, 5.0}, 0.4};
  in.scene.objects[0].thread_maps[1] = weft;  // the same image, its own transform
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const auto reader = bundle::BundleReader::view(bytes, "memory");
  ASSERT_TRUE(reader.has("texture/0"));
  EXPECT_FALSE(reader.has("texture/1"));  // one image, stored once
  EXPECT_GT(reader.section("texture/0").size, 0u);
  const SceneBundle out = read_scene_bundle(reader);
  const SceneObject& a = in.scene.objects[0];
  const SceneObject& b = out.scene.objects[0];
  for (int j = 0; j < 2; ++j) {
    ASSERT_TRUE(b.thread_maps[j]);
    EXPECT_EQ(b.thread_maps[j]->image->rgba, a.thread_maps[j]->image->rgba);  // lossless
    EXPECT_EQ(b.thread_maps[j]->transform, a.thread_maps[j]->transform);
    EXPECT_EQ(b.thread_maps[j]->name, "plaid.png");
  }
  EXPECT_EQ(b.thread_maps[0]->image, b.thread_maps[1]->image);
  EXPECT_FALSE(out.scene.objects[1].textured());
  // A flipped bit in the texture fails its checksum, named.
  auto flipped = bytes;
  flipped[reader.section("texture/0").offset + 20] ^= std::byte{4};
  try {
    read_scene_bundle(bundle::BundleReader::view(flipped, "memory"));
    FAIL() << "accepted a flipped bit";
  } catch (const bundle::BundleError& e) {
    EXPECT_EQ(e.section(), "texture/0") << e.what();
  }
}

TEST(SceneBundle, CarriesANormalMapAsAVerifiedSection) {
  SceneBundleInput in = pillow_input();
  in.scene = load_scene_preset("plaid_pillow", fs::path(WEFT_SOURCE_ASSETS) / "scenes");
  // Bumps of every code (x, y the tilt, z near the top), so that a lossy or colour-converted store
  // would show.
  auto bumps = std::make_shared<TextureImage>();
  bumps->width = 8, bumps->height = 4;
  for (int i = 0; i < 32; ++i)
    bumps->rgba.insert(bumps->rgba.end(), {std::uint8_t(37 * i % 256), std::uint8_t(255 - 11 * i), std::uint8_t(200 + i), 255});
  const NormalMap map{ThreadMap{bumps, "bumps.png", {{0.25, -0.5}, {3.0, 2.0}, 0.3}}, 0.6};
  in.scene.objects[0].normal_map = map;
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const auto reader = bundle::BundleReader::view(bytes, "memory");
  ASSERT_TRUE(reader.has("texture/0"));  // the plaid
  ASSERT_TRUE(reader.has("texture/1"));  // the normal map's own image
  EXPECT_FALSE(reader.has("texture/2"));
  const SceneBundle out = read_scene_bundle(reader);
  const SceneObject& b = out.scene.objects[0];
  ASSERT_TRUE(b.normal_map);
  EXPECT_EQ(b.normal_map->map.image->width, 8);
  EXPECT_EQ(b.normal_map->map.image->height, 4);
  EXPECT_EQ(b.normal_map->map.image->rgba, bumps->rgba);  // the codes as they were: no sRGB step
  EXPECT_EQ(b.normal_map->map.transform, map.map.transform);
  EXPECT_EQ(b.normal_map->map.name, "bumps.png");
  EXPECT_EQ(b.normal_map->scale, 0.6);
  EXPECT_NE(b.normal_map->map.image, b.thread_maps[0]->image);
  EXPECT_FALSE(out.scene.objects[1].normal_map);  // the floor
  // A flipped bit in the normal map's image fails its checksum, named.
  auto flipped = bytes;
  flipped[reader.section("texture/1").offset + 20] ^= std::byte{4};
  try {
    read_scene_bundle(bundle::BundleReader::view(flipped, "memory"));
    FAIL() << "accepted a flipped bit";
  } catch (const bundle::BundleError& e) {
    EXPECT_EQ(e.section(), "texture/1") << e.what();
  }
  // A normal map on the colour's own image stores it once.
  in.scene.objects[0].normal_map->map.image = in.scene.objects[0].thread_maps[0]->image;
  bundle::BundleWriter shared;
  add_scene_sections(shared, in);
  const auto shared_bytes = shared.to_bytes();
  EXPECT_FALSE(bundle::BundleReader::view(shared_bytes, "memory").has("texture/1"));
}

TEST(SceneBundle, CarriesTheVertexPassMeshAndRefusesABadOne) {
  // A hand-made pass (three pass vertices blended everywhere) on the pillow's cloth: the format
  // carries it exactly, and a blend that is not one, or a corner past the pass, is refused.
  SceneBundleInput in = pillow_input();
  TriangleMesh& m = in.scene.objects[0].mesh;
  ASSERT_EQ(in.scene.objects[0].material, Material::cloth);
  const size_t n = m.positions.size();
  auto pass = std::make_shared<VertexPassMesh>();
  pass->vertices = {0, 5, uint32_t(n - 1)};
  pass->corners.assign(n, {0, 1, 2});
  pass->weights.assign(n, glm::vec3(0.25f, 0.25f, 0.5f));
  pass->corners[5] = {1, 1, 1};
  pass->weights[5] = glm::vec3(1, 0, 0);
  m.pass = pass;
  bundle::BundleWriter w;
  add_scene_sections(w, in);
  const auto bytes = w.to_bytes();
  const SceneBundle out = read_scene_bundle(bundle::BundleReader::view(bytes, "memory"));
  const auto& got = out.scene.objects[0].mesh.pass;
  ASSERT_TRUE(got);
  EXPECT_EQ(got->vertices, pass->vertices);
  EXPECT_EQ(got->corners, pass->corners);
  EXPECT_EQ(got->weights, pass->weights);
  EXPECT_FALSE(out.scene.objects[1].mesh.pass);  // the floor: every vertex
  auto refused = [&](const VertexPassMesh& bad, const std::string& section) {
    SceneBundleInput b = in;
    b.scene.objects[0].mesh.pass = std::make_shared<VertexPassMesh>(bad);
    bundle::BundleWriter bw;
    add_scene_sections(bw, b);
    const auto bb = bw.to_bytes();
    try {
      read_scene_bundle(bundle::BundleReader::view(bb, "memory"));
      ADD_FAILURE() << "accepted a bad " << section;
    } catch (const bundle::BundleError& e) {
      EXPECT_EQ(e.section(), "mesh/0/" + section) << e.what();
    }
  };
  VertexPassMesh not_a_blend = *pass;
  not_a_blend.weights[3] = glm::vec3(0.5f, 0.2f, 0.2f);
  refused(not_a_blend, "pass_weights");
  VertexPassMesh past = *pass;
  past.corners[7] = {0, 1, 3};
  refused(past, "pass_corners");
  VertexPassMesh unordered = *pass;
  unordered.vertices = {5, 0, uint32_t(n - 1)};
  refused(unordered, "pass_vertices");
}
