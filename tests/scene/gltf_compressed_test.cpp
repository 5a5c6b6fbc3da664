// Compressed and quantized glTF geometry: Debian's Draco engine sample imports with the counts and
// bounds its accessors declare; a cushion encoded here with libdraco, libmeshoptimizer and
// KHR_mesh_quantization imports as the same mesh as its plain glTF within the encoders'
// quantization; broken variants are refused with a SceneError that names the file and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <functional>

#include <nlohmann/json.hpp>
// As render/scene/gltf_scene.cpp builds tinygltf (which holds its implementation).
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "scene/gltf_draco.h"
#include "scene/gltf_encode.h"
#include "scene/gltf_loadable.h"
#include "scene/gltf_scene.h"
#include "scene/mesh.h"
#include "scene/procedural_meshes.h"
#include "scene/scene.h"
#include "support/scene_refusal.h"

using namespace weft;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const fs::path kDracoEngine = "/usr/share/assimp/models/glTF2/draco/2CylinderEngine.gltf";
using test::GltfFile;
using test::SourceMesh;
using test::kByte, test::kFloat, test::kShort, test::kUnsignedInt, test::kUnsignedShort;

// The cushion every encoding below starts from.
SourceMesh cushion() {
  TriangleMesh m = pillow_mesh(0.5, 0.4, 0.12, 0.01, 6);
  if (m.normals.empty()) compute_vertex_normals(m);
  SourceMesh s;
  for (size_t v = 0; v < m.positions.size(); ++v) {
    for (int k = 0; k < 3; ++k) s.positions.push_back(float(m.positions[v][k]));
    const glm::dvec3 n = glm::normalize(m.normals[v]);
    for (int k = 0; k < 3; ++k) s.normals.push_back(float(n[k]));
    for (int k = 0; k < 2; ++k) s.uvs.push_back(float(m.uvs[v][k]));
  }
  for (const auto& t : m.triangles) s.indices.insert(s.indices.end(), t.begin(), t.end());
  return s;
}

// A glTF with one mesh of one primitive (material 'Cushion').
struct File : GltfFile {
  void mesh(json primitive, json node = json::object()) {
    primitive["material"] = 0;
    j["meshes"] = json::array({{{"primitives", json::array({primitive})}}});
    j["materials"] = json::array({{{"name", "Cushion"}}});
    node["mesh"] = 0;
    j["nodes"] = json::array({node});
    j["scenes"] = json::array({{{"nodes", {0}}}});
  }
};

std::string plain_file(const SourceMesh& m) {
  File f;
  f.mesh(test::plain_primitive(f, m));
  return f.text();
}

// KHR_mesh_quantization as gltfpack writes it: positions as unsigned shorts in the mesh's box (the
// node scales them back, uniformly), normals as normalized shorts, UVs as normalized unsigned shorts.
std::string quantized_file(const SourceMesh& m, int normal_component = kShort, bool normals_normalized = true) {
  File f;
  const size_t n = m.vertices();
  glm::dvec3 lo(1e9), hi(-1e9);
  for (size_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(m.positions[3 * v + k]));
      hi[k] = std::max(hi[k], double(m.positions[3 * v + k]));
    }
  // One step on every axis, as gltfpack: a non-uniform node scale would bend the normals.
  const glm::dvec3 step(std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) / 65535.0);
  std::vector<uint16_t> positions(4 * n, 0), uvs(2 * n);  // positions padded to 8 bytes (4-byte aligned)
  std::vector<int16_t> normals(4 * n, 0);
  for (size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      positions[4 * v + k] = uint16_t(std::lround((m.positions[3 * v + k] - lo[k]) / step[k]));
      normals[4 * v + k] = int16_t(std::lround(m.normals[3 * v + k] * 32767.0));
    }
    for (int k = 0; k < 2; ++k) uvs[2 * v + k] = uint16_t(std::lround(std::clamp(m.uvs[2 * v + k], 0.f, 1.f) * 65535.0));
  }
  f.mesh({{"attributes",
           {{"POSITION", f.accessor(f.view(positions.data(), n * 8, 8), kUnsignedShort, n, "VEC3")},
            {"NORMAL", f.accessor(f.view(normals.data(), n * 8, 8), normal_component, n, "VEC3", normals_normalized)},
            {"TEXCOORD_0", f.accessor(f.view(uvs.data(), n * 4), kUnsignedShort, n, "VEC2", true)}}},
          {"indices", f.accessor(f.view(m.indices.data(), m.indices.size() * 4), kUnsignedInt, m.indices.size(), "SCALAR")}},
         {{"translation", {lo.x, lo.y, lo.z}}, {"scale", {step.x, step.y, step.z}}});
  f.require({"KHR_mesh_quantization"});
  return f.text();
}

// EXT_meshopt_compression as gltfpack writes it: compressed views in buffer 0, their decoded
// bytes declared in a fallback buffer 1 that holds no data.
File meshopt_file(const SourceMesh& m) {
  File f;
  f.mesh(test::meshopt_primitive(f, m));
  return f;
}

// KHR_draco_mesh_compression as Blender writes it: the Draco bitstream in a buffer view, the
// accessors with counts only.
File draco_file(const SourceMesh& m) {
  File f;
  f.mesh(test::draco_primitive(f, m));
  return f;
}

Scene parse(const std::string& bytes, const std::string& origin = "test.gltf") {
  return parse_gltf_scene(bytes, origin, fs::temp_directory_path(), GltfImportOptions{});
}

using test::refusal;

struct Tolerance {
  double position, normal, uv;
};

// A triangle's corners rotated to start at its smallest index (the facing is kept).
std::vector<std::array<uint32_t, 3>> rotated_to_smallest(std::vector<std::array<uint32_t, 3>> triangles) {
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return triangles;
}

// Vertex by vertex, in the same order (meshopt and quantization keep it; meshopt's index codec
// may rotate a triangle's corners).
void expect_same_vertices(const TriangleMesh& a, const TriangleMesh& b, Tolerance tol) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  ASSERT_EQ(a.uvs.size(), b.uvs.size());
  ASSERT_EQ(rotated_to_smallest(a.triangles), rotated_to_smallest(b.triangles));
  double dp = 0, dn = 0, du = 0;
  for (size_t v = 0; v < a.positions.size(); ++v) {
    dp = std::max(dp, glm::length(a.positions[v] - b.positions[v]));
    dn = std::max(dn, glm::length(a.normals[v] - b.normals[v]));
    du = std::max(du, glm::length(a.uvs[v] - b.uvs[v]));
  }
  EXPECT_LE(dp, tol.position);
  EXPECT_LE(dn, tol.normal);
  EXPECT_LE(du, tol.uv);
}

// Triangle by triangle (Draco renumbers points): each triangle of `b` is one of `a`'s, its
// corners in the same cyclic order (same facing), within the tolerances.
void expect_same_triangles(const TriangleMesh& a, const TriangleMesh& b, Tolerance tol) {
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  std::vector<bool> used(a.triangles.size(), false);
  auto centroid = [](const TriangleMesh& m, const std::array<uint32_t, 3>& t) {
    return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0;
  };
  size_t unmatched = 0;
  for (const auto& tb : b.triangles) {
    const glm::dvec3 cb = centroid(b, tb);
    bool found = false;
    for (size_t i = 0; i < a.triangles.size() && !found; ++i) {
      if (used[i] || glm::length(centroid(a, a.triangles[i]) - cb) > tol.position) continue;
      for (int r = 0; r < 3 && !found; ++r) {
        bool same = true;
        for (int k = 0; k < 3; ++k) {
          const uint32_t va = a.triangles[i][(k + r) % 3], vb = tb[k];
          same = same && glm::length(a.positions[va] - b.positions[vb]) <= tol.position &&
                 glm::length(a.normals[va] - b.normals[vb]) <= tol.normal && glm::length(a.uvs[va] - b.uvs[vb]) <= tol.uv;
        }
        if (same) found = used[i] = true;
      }
    }
    if (!found) ++unmatched;
  }
  EXPECT_EQ(unmatched, 0u);
}

const TriangleMesh& only_mesh(const Scene& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0).mesh;
}

// The small files the glTF fuzz target starts from (tests/fuzz/corpus/gltf), written when
// WEFT_GLTF_SEED_DIR names a folder.
void write_seed(const std::string& name, const std::string& bytes) {
  const char* dir = std::getenv("WEFT_GLTF_SEED_DIR");
  if (!dir) return;
  std::ofstream(fs::path(dir) / name, std::ios::binary) << bytes;
}

}  // namespace

TEST(GltfCompressed, DracoEngineImportsWithItsDeclaredCountsAndBounds) {
  if (!fs::exists(kDracoEngine)) GTEST_SKIP() << kDracoEngine << " absent (apt-get install assimp-testmodels)";
  std::ifstream in(kDracoEngine);
  const json j = json::parse(in);
  size_t vertices = 0, triangles = 0;
  std::vector<int> stack = j["scenes"][j.value("scene", 0)]["nodes"].get<std::vector<int>>();
  while (!stack.empty()) {
    const json& node = j["nodes"][stack.back()];
    stack.pop_back();
    if (node.contains("mesh"))
      for (const json& p : j["meshes"][node["mesh"].get<int>()]["primitives"]) {
        vertices += j["accessors"][p["attributes"]["POSITION"].get<int>()]["count"].get<size_t>();
        triangles += j["accessors"][p["indices"].get<int>()]["count"].get<size_t>() / 3;
      }
    for (int k : node.value("children", std::vector<int>())) stack.push_back(k);
  }
  const auto start = std::chrono::steady_clock::now();
  const Scene s = load_gltf_scene(kDracoEngine, GltfImportOptions{});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "Draco 2CylinderEngine: loaded in " << seconds * 1e3 << " ms\n";
  size_t got_vertices = 0, got_triangles = 0, dropped = 0;
  for (const auto& o : s.objects) {
    got_vertices += o.mesh.positions.size();
    got_triangles += o.mesh.triangles.size();
    dropped += o.repair.degenerate_triangles_dropped;
    for (const auto& p : o.mesh.positions) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }
  EXPECT_EQ(got_vertices, vertices);
  EXPECT_EQ(got_triangles + dropped, triangles);

  // The same engine uncompressed (assimp's .glb of it): the same box in Weft's frame, within a
  // step of 10 bits over the whole engine.
  const fs::path plain_engine = kDracoEngine.parent_path().parent_path() / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  if (fs::exists(plain_engine)) {
    auto bounds = [](const Scene& scene) {
      glm::dvec3 lo(1e300), hi(-1e300);
      for (const auto& o : scene.objects)
        for (const auto& p : o.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
      return std::pair{lo, hi};
    };
    const auto [draco_lo, draco_hi] = bounds(s);
    const auto [plain_lo, plain_hi] = bounds(load_gltf_scene(plain_engine, GltfImportOptions{}));
    const double step = glm::length(plain_hi - plain_lo) / 1024.0;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(draco_lo[k], plain_lo[k], step) << "axis " << k;
      EXPECT_NEAR(draco_hi[k], plain_hi[k], step) << "axis " << k;
    }
  }

  // Per primitive, before any transform: the decoded positions' box is the accessor's min/max
  // within Draco's quantization (the exporter's box may round outward by a step).
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  std::ifstream file(kDracoEngine);
  const std::string text = loadable_by_tinygltf({std::istreambuf_iterator<char>(file), {}});
  ASSERT_TRUE(loader.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()),
                                         kDracoEngine.parent_path().string()))
      << err;
  const std::vector<tinygltf::Accessor> declared = model.accessors;
  decode_draco_primitives(model, kDracoEngine.string());
  size_t checked = 0;
  for (size_t mi = 0; mi < model.meshes.size(); ++mi)
    for (const auto& p : model.meshes[mi].primitives) {
      const int old_index = j["meshes"][mi]["primitives"][&p - model.meshes[mi].primitives.data()]["attributes"]["POSITION"];
      const tinygltf::Accessor& want = declared[size_t(old_index)];
      const tinygltf::Accessor& got = model.accessors[size_t(p.attributes.at("POSITION"))];
      ASSERT_EQ(got.count, want.count);
      ASSERT_EQ(got.componentType, kFloat);
      const tinygltf::BufferView& v = model.bufferViews[size_t(got.bufferView)];
      const float* xyz = reinterpret_cast<const float*>(model.buffers[size_t(v.buffer)].data.data() + v.byteOffset);
      for (int k = 0; k < 3; ++k) {
        double lo = 1e300, hi = -1e300;
        for (size_t i = 0; i < got.count; ++i) {
          lo = std::min(lo, double(xyz[3 * i + k]));
          hi = std::max(hi, double(xyz[3 * i + k]));
        }
        // Draco quantizes in a cube over the largest extent; the file does not say its bits: one
        // step of 10 bits.
        const double step = std::max({want.maxValues[0] - want.minValues[0], want.maxValues[1] - want.minValues[1],
                                      want.maxValues[2] - want.minValues[2]}) / 1024.0;
        EXPECT_NEAR(lo, want.minValues[k], step) << "mesh " << mi;
        EXPECT_NEAR(hi, want.maxValues[k], step) << "mesh " << mi;
      }
      ++checked;
    }
  EXPECT_EQ(checked, 34u);
}

TEST(GltfCompressed, DracoEncodedCushionMatchesThePlainFilesTriangles) {
  const SourceMesh m = cushion();
  const Scene plain = parse(plain_file(m));
  File f = draco_file(m);
  const std::string text = f.text();
  write_seed("draco_cushion.gltf", text);
  const Scene draco = parse(text);
  // 14 bits over 0.5 m, 10 bits of normal, 12 bits of UV; a step or two of each.
  expect_same_triangles(only_mesh(plain), only_mesh(draco), {2e-4, 2e-2, 1e-3});
  EXPECT_TRUE(draco.warnings.empty()) << draco.warnings.at(0);
}

TEST(GltfCompressed, MeshoptCushionDecodesToThePlainFilesVertices) {
  const SourceMesh m = cushion();
  const Scene plain = parse(plain_file(m));
  File f = meshopt_file(m);
  File g = f;
  const std::string text = f.text();
  write_seed("meshopt_cushion.gltf", text);
  // Positions are lossless, normals 8-bit octahedral, UVs a 15-bit shared mantissa.
  const Tolerance tol{1e-7, 2e-2, 1e-4};
  expect_same_vertices(only_mesh(plain), only_mesh(parse(text)), tol);
  expect_same_vertices(only_mesh(plain), only_mesh(parse(g.glb(), "test.glb")), tol);
}

TEST(GltfCompressed, QuantizedCushionReadsAsThePlainFile) {
  const SourceMesh m = cushion();
  const Scene plain = parse(plain_file(m));
  const Scene quantized = parse(quantized_file(m));
  // 16 bits over ≤ 0.5 m; normals 15 bits; UVs 16 bits.
  expect_same_vertices(only_mesh(plain), only_mesh(quantized), {1e-5, 1e-4, 1e-4});
  const std::string why = refusal([&] { parse(quantized_file(m, kShort, false)); });
  EXPECT_NE(why.find("test.gltf"), std::string::npos) << why;
  EXPECT_NE(why.find("NORMAL"), std::string::npos) << why;
  EXPECT_NE(why.find("SHORT (5122) without normalized"), std::string::npos) << why;
  const std::string floats = refusal([&] { parse(quantized_file(m, kUnsignedInt)); });
  EXPECT_NE(floats.find("wrong component type UNSIGNED_INT (5125) (expected FLOAT (5126), BYTE (5120), SHORT (5122))"),
            std::string::npos)
      << floats;
}

TEST(GltfCompressed, BrokenCompressedFilesAreRefusedWithAReason) {
  const SourceMesh m = cushion();
  struct Case {
    const char* what;
    std::string bytes;
    std::vector<std::string> reasons;
  };
  std::vector<Case> cases;
  {
    File f = draco_file(m);
    f.j["bufferViews"][0]["byteLength"] = f.j["bufferViews"][0]["byteLength"].get<size_t>() / 2;
    cases.push_back({"truncated Draco", f.text(), {"KHR_draco_mesh_compression", "does not decode"}});
  }
  {
    File f = draco_file(m);
    f.j["accessors"][0]["count"] = f.j["accessors"][0]["count"].get<size_t>() + 1;
    cases.push_back({"Draco count", f.text(), {"attributes.POSITION", "Draco data holds"}});
  }
  {
    File f = draco_file(m);
    f.j["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 77;
    cases.push_back({"Draco attribute id", f.text(), {"attributes.NORMAL", "no attribute with that id"}});
  }
  {
    File f = meshopt_file(m);
    f.j["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteStride"] = 16;
    cases.push_back({"meshopt byteStride", f.text(), {"bufferViews[0].extensions.EXT_meshopt_compression", "byteLength"}});
  }
  {
    File f = meshopt_file(m);
    json& e = f.j["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
    e["byteStride"] = 8;  // consistent with the view's length, not with the encoding
    e["count"] = m.vertices() * 12 / 8;
    cases.push_back({"meshopt stride and count", f.text(), {"bufferViews[0]", "does not decode"}});
  }
  {
    File f = meshopt_file(m);
    json& e = f.j["bufferViews"][3]["extensions"]["EXT_meshopt_compression"];
    e["byteLength"] = e["byteLength"].get<size_t>() / 2;
    cases.push_back({"truncated meshopt indices", f.text(), {"bufferViews[3]", "TRIANGLES data does not decode"}});
  }
  {
    File f = meshopt_file(m);
    f.j["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["filter"] = "QUATERNION";
    cases.push_back({"meshopt filter stride", f.text(), {"bufferViews[1]", "QUATERNION: must be 8"}});
  }
  {
    File f = meshopt_file(m);
    f.j["bufferViews"][0].erase("extensions");
    cases.push_back({"view into the fallback", f.text(), {"bufferViews[0]", "fallback that holds no data"}});
  }
  {
    File f = draco_file(m);
    f.require({"KHR_draco_mesh_compression", "KHR_unheard_of_compression"});
    cases.push_back({"unknown required extension", f.text(), {"requires the glTF extension KHR_unheard_of_compression"}});
  }
  for (const auto& c : cases) {
    const std::string why = refusal([&] { parse(c.bytes); });
    EXPECT_NE(why.find("test.gltf"), std::string::npos) << c.what << ": " << why;
    for (const auto& r : c.reasons) EXPECT_NE(why.find(r), std::string::npos) << c.what << ": " << why;
  }
}
