// Fabric presets load with Table II's values, and bad files are rejected naming file, field, value.
#include <gtest/gtest.h>

#include <fstream>

#include "core/fabric.h"

using namespace weft;

static const std::string kDir = WEFT_SOURCE_ASSETS "/fabrics";

TEST(Fabric, AllPresetsLoad) {
  const auto names = list_fabric_presets(kDir);
  const std::vector<std::string> expect = {"linen_plain", "polyester_satin_charmeuse",
                                           "polyester_satin_charmeuse_back", "polyester_voile",
                                           "silk_crepe_de_chine", "silk_shot", "velvet"};
  EXPECT_EQ(names, expect);
  for (const auto& n : names) EXPECT_NO_THROW(load_fabric_preset(n, kDir)) << n;
}

TEST(Fabric, ValuesMatchTableII) {
  const Fabric s = load_fabric_preset("silk_shot", kDir);
  EXPECT_DOUBLE_EQ(s.threads[0].eta, 1.345);
  EXPECT_NEAR(s.threads[0].albedo.g, 0.2, 1e-15);
  EXPECT_NEAR(s.threads[1].albedo.r, 0.6, 1e-15);
  EXPECT_NEAR(s.threads[0].gamma_s, glm::radians(4.0), 1e-15);
  EXPECT_DOUBLE_EQ(s.threads[0].coverage, 0.86);
  EXPECT_NEAR(s.threads[0].curve.total_length(), 5.33, 1e-12);
  const Fabric v = load_fabric_preset("velvet", kDir);
  EXPECT_EQ(v.threads[1].curve.offsets_deg(), (std::vector<double>{-90, -55, 55, 90}));
}

static std::string linen_text() {
  std::ifstream in(kDir + "/linen_plain.json");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

static std::string error_of(const std::string& text) {
  try {
    parse_fabric(text, "test.json");
  } catch (const FabricError& e) {
    return e.what();
  }
  return "";
}

static std::string replace(std::string s, const std::string& from, const std::string& to, bool all = false) {
  size_t p = 0;
  while ((p = s.find(from, p)) != std::string::npos) {
    s.replace(p, from.size(), to);
    p += to.size();
    if (!all) break;
  }
  return s;
}

TEST(Fabric, OpticalThicknessMarksASheer) {
  EXPECT_EQ(load_fabric_preset("linen_plain", kDir).optical_thickness, 0.0);  // Table II: opaque
  EXPECT_DOUBLE_EQ(load_fabric_preset("polyester_voile", kDir).optical_thickness, 0.4);
  const std::string with = replace(linen_text(), "\"threads\"", "\"optical_thickness\": 1.5, \"threads\"");
  EXPECT_DOUBLE_EQ(parse_fabric(with, "t.json").optical_thickness, 1.5);
  for (const char* bad : {"0", "-1", "21", "\"thin\""}) {
    const std::string e =
        error_of(replace(linen_text(), "\"threads\"", std::string("\"optical_thickness\": ") + bad + ", \"threads\""));
    EXPECT_NE(e.find("test.json: field 'optical_thickness'"), std::string::npos) << bad << ": " << e;
  }
}

TEST(Fabric, MissingFieldIsNamed) {
  const std::string e = error_of(replace(linen_text(), "\"kd\": 0.3,", ""));
  EXPECT_NE(e.find("test.json"), std::string::npos) << e;
  EXPECT_NE(e.find("threads[0].kd"), std::string::npos) << e;
  EXPECT_NE(e.find("missing"), std::string::npos) << e;
}

TEST(Fabric, NegativeAlbedoIsNamedWithValue) {
  const std::string e = error_of(replace(linen_text(), "[0.2, 0.8, 1.0]", "[0.2, -0.8, 1.0]"));
  EXPECT_NE(e.find("threads[0].albedo[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("-0.8"), std::string::npos) << e;
}

TEST(Fabric, CoverageAboveOneIsRejected) {
  const std::string e = error_of(replace(linen_text(), "\"coverage\": 0.33", "\"coverage\": 0.6", true));
  EXPECT_NE(e.find("coverage"), std::string::npos) << e;
  EXPECT_NE(e.find("1.2"), std::string::npos) << e;
}

TEST(Fabric, LengthListMismatchIsNamed) {
  const std::string e = error_of(replace(linen_text(), "\"segment_lengths\": [1]", "\"segment_lengths\": [1, 2]"));
  EXPECT_NE(e.find("threads[0].segment_lengths"), std::string::npos) << e;
  EXPECT_NE(e.find("has 2 values"), std::string::npos) << e;
}

TEST(Fabric, GarbageAndAbsurdValuesAreRejected) {
  EXPECT_NE(error_of("{not json").find("not valid JSON"), std::string::npos);
  EXPECT_NE(error_of(replace(linen_text(), "\"eta\": 1.46", "\"eta\": \"glass\"")).find("threads[0].eta"),
            std::string::npos);
  EXPECT_NE(error_of(replace(linen_text(), "\"gamma_s_deg\": 12", "\"gamma_s_deg\": 0")).find("gamma_s_deg"),
            std::string::npos);
  EXPECT_NE(error_of(replace(linen_text(), "\"eta\": 1.46", "\"eta\": 1e400")).find("1e400"), std::string::npos);
  EXPECT_THROW(load_fabric_preset("../etc/passwd", kDir), FabricError);
  EXPECT_THROW(load_fabric_preset("no_such_fabric", kDir), FabricError);
}

TEST(Fabric, NamedByPresetOrByFilePath) {
  EXPECT_FALSE(names_fabric_file("velvet"));
  EXPECT_TRUE(names_fabric_file("my_velvet.json"));
  EXPECT_TRUE(names_fabric_file("fabrics/velvet"));
  const std::string file = (std::filesystem::temp_directory_path() / "weft_fabric_by_path.json").string();
  std::filesystem::copy_file(kDir + "/silk_shot.json", file, std::filesystem::copy_options::overwrite_existing);
  EXPECT_EQ(load_fabric_named(file, "/nonexistent").name, load_fabric_preset("silk_shot", kDir).name);
  EXPECT_EQ(load_fabric_named("silk_shot", kDir).name, load_fabric_preset("silk_shot", kDir).name);
  EXPECT_EQ(fabric_file("silk_shot", kDir), std::filesystem::path(kDir) / "silk_shot.json");
  EXPECT_THROW(load_fabric_named("/nonexistent/x.json", kDir), FabricError);
  std::filesystem::remove(file);
}
