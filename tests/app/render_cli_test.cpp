// `weft render` end to end on tiny images: files written, exit codes for bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

struct CliResult {
  int code;
  std::string out;
};

static CliResult weft(const std::string& args) {
  const std::string cmd = std::string(WEFT_BINARY) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

static fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("weft_render_cli_" + name); }

static bool is_png(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return std::string(sig + 1, 3) == "PNG";
}

TEST(RenderCli, SwatchWithSgsFileWritesExrAndPng) {
  const fs::path sgs = temp("sgs.json"), exr = temp("swatch.exr");
  std::ofstream(sgs) << R"({"sgs":[{"axis":[0,0,1],"sharpness":3,"amplitude":[1,1,1]}]})";
  const CliResult r = weft("render --scene swatch --sgs " + sgs.string() +
                     " --width 16 --height 12 --sg-grid 2 --tangent-samples 4 --check-stride 4 --out " + exr.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "swatch");
  EXPECT_TRUE(j.contains("convergence"));
  EXPECT_GT(fs::file_size(exr), 100u);
  EXPECT_TRUE(is_png(temp("swatch.png")));
  fs::remove(exr);
  fs::remove(temp("swatch.png"));
  fs::remove(sgs);
}

TEST(RenderCli, MapLighting) {
  const fs::path exr = temp("map.exr");
  const CliResult r = weft("render --scene swatch --lighting map --map-width 16 --width 12 --height 9 --tangent-samples 4 "
                     "--no-convergence-check --out " + exr.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["lighting"], "map");
  EXPECT_TRUE(is_png(temp("map.png")));
  fs::remove(exr);
  fs::remove(temp("map.png"));
}

TEST(RenderCli, BadInputExitsWithTwo) {
  const std::string out = " --out " + temp("bad.exr").string();
  EXPECT_EQ(weft("render --scene no_such_scene" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --fabric no_such_fabric" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --map no_such_map" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --lighting photons" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --method photonmap" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --width 0" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --sgs /nonexistent.json" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --out image.png").code, 2);
  EXPECT_EQ(weft("render --scene swatch").code, 2);  // --out is required
  EXPECT_FALSE(fs::exists(temp("bad.exr")));
}

// Scenes, fabrics and maps by path (docs/design.md §1): a glTF scene (the fuzz corpus's UV-mapped quad
// with a linen_plain material), a fabric file and an .exr file outside assets/.
TEST(RenderCli, GltfSceneFabricFileAndMapByPath) {
  const fs::path gltf = fs::path(WEFT_SOURCE_ASSETS) / "../tests/fuzz/corpus/gltf/quad.gltf";
  const fs::path fabric = temp("my_velvet.json"), map = temp("my_studio.exr"), exr = temp("gltf.exr");
  fs::copy_file(fs::path(WEFT_SOURCE_ASSETS) / "fabrics/velvet.json", fabric, fs::copy_options::overwrite_existing);
  fs::copy_file(fs::path(WEFT_SOURCE_ASSETS) / "envmaps/studio.exr", map, fs::copy_options::overwrite_existing);
  const CliResult r = weft("render --scene " + gltf.string() + " --fabric " + fabric.string() + " --map " +
                           map.string() + " --lighting map --map-width 16 --width 12 --height 9 --tangent-samples 4 "
                           "--no-convergence-check --out " + exr.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["scene"], "quad");
  EXPECT_TRUE(is_png(temp("gltf.png")));
  fs::remove(exr), fs::remove(temp("gltf.png")), fs::remove(fabric), fs::remove(map);
}

// A fabric file drawn by a rung of the weighting tables: the tables baked in memory are found under
// the name the scene gives the fabric (the file's path), whatever name the file gives itself.
TEST(RenderCli, AFabricFileDrawsWithTheTablesBakedForIt) {
  const fs::path fabric = temp("fitted_linen.json"), exr = temp("fabric_file.exr"), png = temp("fabric_file.png");
  const fs::path sgs = temp("fabric_file_sgs.json");
  fs::copy_file(fs::path(WEFT_SOURCE_ASSETS) / "fabrics/linen_plain.json", fabric, fs::copy_options::overwrite_existing);
  std::ofstream(sgs) << R"({"sgs":[{"axis":[0.3,-0.2,0.93],"sharpness":8,"amplitude":[1,1,1]}]})";
  const CliResult r = weft("render --scene swatch --fabric " + fabric.string() + " --method iwasaki_vertex --table-grid 8 --sgs " +
                           sgs.string() + " --width 24 --height 16 --frames 1 --out " + exr.string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(is_png(png));
  fs::remove(exr), fs::remove(png), fs::remove(fabric), fs::remove(sgs);
}

// A broken glTF is bad input for render and bake alike: exit 2, the file and the reason on
// stderr, no bundle written.
TEST(RenderCli, BrokenGltfExitsWithTwoNamingFileAndReason) {
  const fs::path broken = fs::path(WEFT_SOURCE_ASSETS) / "../tests/fuzz/corpus/gltf/index_out_of_range.glb";
  const fs::path exr = temp("broken.exr"), bundle = temp("broken.weft"), log = temp("broken.log");
  for (const std::string& cmd : {"render --scene " + broken.string() + " --out " + exr.string(),
                                 "bake --scene " + broken.string() + " --out " + bundle.string()}) {
    const int code = std::system((std::string(WEFT_BINARY) + " " + cmd + " >/dev/null 2>" + log.string()).c_str());
    EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 2) << cmd;
    std::ifstream in(log);
    const std::string err((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(err.find("index_out_of_range.glb"), std::string::npos) << err;
    EXPECT_NE(err.find("out of range"), std::string::npos) << err;
  }
  EXPECT_FALSE(fs::exists(exr));
  EXPECT_FALSE(fs::exists(bundle));
  fs::remove(log);
}

// Every GPU method of the ladder renders through the CLI (pixels are the parity tests' and the
// bench's business): exit 0, EXR and PNG written, the method named in the summary.
TEST(RenderCli, LadderMethodsRender) {
  const fs::path sgs = temp("ladder_sgs.json");
  std::ofstream(sgs) << R"({"sgs":[{"axis":[0.3,-0.2,0.93],"sharpness":8,"amplitude":[1,1,1]}]})";
  for (const std::string m : {"sgpoint", "sheen", "mdfrot", "thin"}) {
    const fs::path exr = temp("ladder_" + m + ".exr"), png = temp("ladder_" + m + ".png");
    const CliResult r = weft("render --scene curtain --method " + m + " --sgs " + sgs.string() +
                             " --width 24 --height 16 --frames 1 --out " + exr.string());
    ASSERT_EQ(r.code, 0) << m << ": " << r.out;
    EXPECT_EQ(nlohmann::json::parse(r.out)["method"], m);
    EXPECT_TRUE(fs::exists(exr)) << m;
    EXPECT_TRUE(is_png(png)) << m;
    fs::remove(exr), fs::remove(png);
  }
  fs::remove(sgs);
}

static std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// --camera EYE:TARGET[:FOV]: the scene's own camera given explicitly draws the scene's frame; another
// eye draws another; a camera that cannot be is refused.
TEST(RenderCli, ExplicitCamera) {
  const fs::path sgs = temp("camera_sgs.json");
  std::ofstream(sgs) << R"({"sgs":[{"axis":[0.3,-0.2,0.93],"sharpness":8,"amplitude":[1,1,1]}]})";
  auto render = [&](const std::string& name, const std::string& camera) {
    const fs::path exr = temp(name + ".exr");
    const CliResult r = weft("render --scene swatch --method sheen --sgs " + sgs.string() + " --width 32 --height 24 --frames 1" +
                             (camera.empty() ? "" : " --camera " + camera) + " --out " + exr.string());
    EXPECT_EQ(r.code, 0) << name << ": " << r.out;
    const std::string png = file_bytes(temp(name + ".png"));
    fs::remove(exr), fs::remove(temp(name + ".png"));
    return png;
  };
  const std::string scene = render("camera_scene", "");
  ASSERT_FALSE(scene.empty());
  // swatch.json's camera: position (0, -1.25, 1.05), target the origin, fov 40.
  EXPECT_EQ(render("camera_same", "0,-1.25,1.05:0,0,0:40"), scene);
  EXPECT_NE(render("camera_other", "0.4,-0.9,0.6:0,0,0"), scene);
  const std::string out = " --out " + temp("camera_bad.exr").string();
  EXPECT_EQ(weft("render --scene swatch --method sheen --camera 0,0:0,0,0" + out).code, 2);           // two numbers
  EXPECT_EQ(weft("render --scene swatch --method sheen --camera 1,1,1:1,1,1" + out).code, 2);         // eye = target
  EXPECT_EQ(weft("render --scene swatch --method sheen --camera 0,-1,1:0,0,0:0" + out).code, 2);      // no field of view
  EXPECT_EQ(weft("render --scene swatch --method sheen --camera 0,-1,1:0,0,0:nan" + out).code, 2);
  EXPECT_EQ(weft("render --scene swatch --method sheen --camera somewhere" + out).code, 2);
  fs::remove(sgs);
}

TEST(RenderCli, Help) {
  const CliResult r = weft("render --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--lighting"), std::string::npos);
}
