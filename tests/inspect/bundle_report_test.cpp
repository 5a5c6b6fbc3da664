// The report `weft bundle info` prints and the verdict of `weft bundle verify`, on bundles baked
// here: what the bundle holds, the methods the kiosk can draw it with, the bake's recorded errors,
// and the kiosk's reason for refusing a damaged copy.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <set>

#include <unistd.h>

#include "bundle/bundle_reader.h"
#include "inspect/bundle_report.h"
#include "inspect/bundle_report_json.h"
#include "inspect/bundle_report_text.h"
#include "methods/registry.h"
#include "support/small_bundle.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

std::set<std::string> presets() {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(WEFT_SOURCE_ASSETS) / "fabrics"))
    if (e.path().extension() == ".json") names.insert(e.path().stem().string());
  return names;
}

TEST(BundleReport, ListsWhatTheBakedPillowHolds) {
  const test::SmallBundle b("pillow");
  ASSERT_TRUE(b.baked());
  const BundleReport r = bundle_report(b.file());
  EXPECT_EQ(r.scene, "pillow");
  EXPECT_EQ(r.bytes, fs::file_size(b.file()));
  ASSERT_EQ(r.objects.size(), 2u);
  EXPECT_EQ(r.objects[0].name, "pillow");
  EXPECT_EQ(r.objects[0].material, "cloth");
  EXPECT_EQ(r.objects[0].fabric, "linen_plain");
  EXPECT_EQ(r.objects[1].name, "floor");
  EXPECT_EQ(r.objects[1].material, "lambertian");
  EXPECT_GT(r.objects[0].triangles, 0u);
  EXPECT_EQ(std::set<std::string>(r.fabrics.begin(), r.fabrics.end()), presets());
  EXPECT_TRUE(r.colourways.empty());
  EXPECT_EQ(r.sgs, 10u);
  // The sections as the reader lists them, in the file's order.
  const auto reader = bundle::BundleReader::open(b.file());
  ASSERT_EQ(r.sections.size(), reader.sections().size());
  for (size_t i = 0; i < r.sections.size(); ++i) {
    EXPECT_EQ(r.sections[i].name, reader.sections()[i].name);
    EXPECT_EQ(r.sections[i].size, reader.sections()[i].size);
  }
  // Masks cover the occluded pillow: every method draws it, auto by quadrature per vertex.
  EXPECT_EQ(r.auto_method, "iwasaki_vertex_quadrature");
  ASSERT_EQ(r.methods.size(), methods::registry().size());
  for (const auto& m : r.methods) EXPECT_TRUE(m.drawable) << m.name << ": " << m.refusal;
  // The bake's settings and measured errors, by stage.
  ASSERT_TRUE(r.bake.count("T") && r.bake.count("vis") && r.bake.count("kappa") && r.bake.count("mask"));
  EXPECT_EQ(r.bake.at("T").at("linen_plain").at("tangent_samples"), nlohmann::json({1, 1}));
  EXPECT_GT(r.bake.at("vis").at("0").at("rms_error").get<double>(), 0.0);
  EXPECT_TRUE(r.bake.at("kappa").contains("max_fit_error"));
  // The JSON form parses back with every key, and the text names the objects and the errors.
  const auto j = nlohmann::json::parse(to_json(r).dump());
  for (const char* k : {"file", "bytes", "format_version", "scene", "objects", "fabrics", "colourways", "sgs",
                        "auto_method", "methods", "sections", "bake"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["objects"][0]["fabric"], "linen_plain");
  EXPECT_TRUE(j["objects"][1]["fabric"].is_null());
  EXPECT_EQ(j["sections"].size(), r.sections.size());
  EXPECT_TRUE(j["colourways"].is_array() && j["colourways"].empty());
  std::ostringstream text;
  write_report_text(r, text);
  for (const char* s : {"0 pillow: cloth linen_plain", "1 floor: lambertian", "mesh/0/positions f32", "rms_error",
                        "svd_errors", "max_fit_error", "colourways (0): none"})
    EXPECT_NE(text.str().find(s), std::string::npos) << s << " in\n" << text.str();
}

TEST(BundleReport, ListsTheColourwaysOfABakeThatBakedEachFabricOnce) {
  // The pillow in a product colour with two colourways: Ocean recolours its linen, Wine dresses it
  // in velvet.
  const fs::path dir = fs::temp_directory_path() / ("weft_report_colourways_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ifstream in(fs::path(WEFT_SOURCE_ASSETS) / "scenes" / "pillow.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  ASSERT_EQ(scene["objects"][0]["name"], "pillow");
  scene["objects"][0]["colour"] = {0.7, 0.6, 0.4};
  scene["colourways"] = nlohmann::json::parse(R"([
      {"name": "Ocean", "objects": {"pillow": {"colour": [0.1, 0.3, 0.6]}}},
      {"name": "Wine", "objects": {"pillow": {"fabric": "velvet", "colour": [0.5, 0.1, 0.2]}}}])");
  std::ofstream(dir / "pillow_colourways.json") << scene.dump();
  const fs::path file = dir / "pillow.weft";
  const std::string cmd = "WEFT_ASSETS=" WEFT_SOURCE_ASSETS " " + std::string(WEFT_BINARY) + " bake --scene " +
                          (dir / "pillow_colourways.json").string() +
                          " --table-grid 4 --lambda-levels 2 --tangent-samples 1 1 --sdf-resolution 8 --floor-sdf-resolution 8 --out " +
                          file.string() + " >" + (dir / "bake.log").string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const BundleReport r = bundle_report(file);
  ASSERT_TRUE(r.objects[0].colour.has_value());
  EXPECT_EQ(*r.objects[0].colour, (std::array<double, 3>{0.7, 0.6, 0.4}));
  ASSERT_EQ(r.colourways.size(), 2u);
  EXPECT_EQ(r.colourways[0].name, "Ocean");
  ASSERT_EQ(r.colourways[0].looks.size(), 1u);
  EXPECT_EQ(r.colourways[0].looks[0].object, "pillow");
  EXPECT_EQ(r.colourways[0].looks[0].fabric, "linen_plain");
  EXPECT_EQ(r.colourways[0].looks[0].colour, (std::array<double, 3>{0.1, 0.3, 0.6}));
  EXPECT_EQ(r.colourways[1].looks[0].fabric, "velvet");
  // Tables per fabric: the pillow's linen (Ocean's too) and Wine's velvet, nothing per colour.
  ASSERT_TRUE(r.bake.count("T"));
  std::set<std::string> tabled;
  for (const auto& [fabric, t] : r.bake.at("T").items()) tabled.insert(fabric);
  EXPECT_EQ(tabled, (std::set<std::string>{"linen_plain", "velvet"}));
  const auto j = nlohmann::json::parse(to_json(r).dump());
  EXPECT_EQ(j["colourways"][1]["name"], "Wine");
  EXPECT_EQ(j["colourways"][1]["objects"]["pillow"]["fabric"], "velvet");
  std::ostringstream text;
  write_report_text(r, text);
  for (const char* s : {"0 pillow: cloth linen_plain in [0.7, 0.6, 0.4]", "colourways (2):",
                        "Ocean: pillow linen_plain in [0.1, 0.3, 0.6];", "Wine: pillow velvet in [0.5, 0.1, 0.2];"})
    EXPECT_NE(text.str().find(s), std::string::npos) << s << " in\n" << text.str();
  fs::remove_all(dir);
}

TEST(BundleReport, ABundleWithoutTablesDrawsOnlyWhatNeedsNone) {
  const test::SmallBundle b("swatch", "--no-tables");
  ASSERT_TRUE(b.baked());
  const BundleReport r = bundle_report(b.file());
  EXPECT_EQ(r.auto_method, "sgpoint");
  EXPECT_TRUE(r.bake.empty());
  for (const auto& m : r.methods) {
    EXPECT_EQ(m.drawable, !methods::method(m.name).needs_weighting_tables()) << m.name;
    if (!m.drawable) {
      EXPECT_NE(m.refusal.find("no weighting tables"), std::string::npos) << m.refusal;
    }
  }
  const BundleVerdict v = verify_bundle(b.file(), "iwasaki");
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.part, "method");
  EXPECT_NE(v.message.find(b.file().string()), std::string::npos) << v.message;
}

TEST(BundleVerdict, NamesThePartOfADamagedCopy) {
  const test::SmallBundle b("swatch");
  ASSERT_TRUE(b.baked());
  const BundleVerdict good = verify_bundle(b.file());
  EXPECT_TRUE(good.ok) << good.message;
  EXPECT_EQ(good.method, "iwasaki_vertex_quadrature");
  std::string bytes;
  {
    std::ifstream in(b.file(), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto write = [&](const std::string& name, const std::string& content) {
    const fs::path p = b.dir() / name;
    std::ofstream(p, std::ios::binary) << content;
    return verify_bundle(p);
  };
  const auto section = bundle::BundleReader::open(b.file()).section("mesh/0/positions");
  std::string flipped = bytes;
  flipped[section.offset + 5] = char(flipped[section.offset + 5] ^ 0x10);
  const BundleVerdict f = write("flipped.weft", flipped);
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.section, "mesh/0/positions");
  EXPECT_NE(f.message.find("checksum mismatch"), std::string::npos) << f.message;
  const BundleVerdict t = write("truncated.weft", bytes.substr(0, bytes.size() - 100));
  EXPECT_FALSE(t.ok);
  EXPECT_NE(t.message.find("truncated"), std::string::npos) << t.message;
  const BundleVerdict n = write("notes.weft", "not a bundle at all\n");
  EXPECT_FALSE(n.ok);
  EXPECT_EQ(n.part, "header");
  EXPECT_NE(n.message.find("not a Weft bundle"), std::string::npos) << n.message;
  EXPECT_THROW(verify_bundle(b.file(), "no_such_method"), std::invalid_argument);
}

}  // namespace
}  // namespace weft
