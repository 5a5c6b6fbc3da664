// The label's parts the kiosk owns, without a display: the fade over time, the text a fabric
// gives, and the check of the label's settings (each bad value names its flag).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/fabric.h"
#include "kiosk/kiosk_config.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_label.h"

namespace weft {
namespace {

TEST(KioskLabel, ShownWhileIdleThenFadesOutOverASecond) {
  EXPECT_EQ(label_opacity(0.0, 8.0), 1.0);
  EXPECT_EQ(label_opacity(8.0, 8.0), 1.0);
  EXPECT_NEAR(label_opacity(8.5, 8.0), 0.5, 1e-12);
  EXPECT_GT(label_opacity(8.25, 8.0), label_opacity(8.75, 8.0));
  EXPECT_EQ(label_opacity(8.0 + kLabelFadeSeconds, 8.0), 0.0);
  EXPECT_EQ(label_opacity(1e6, 8.0), 0.0);
  EXPECT_EQ(label_opacity(1e6, 0.0), 1.0);  // 0: never fades
}

TEST(KioskLabel, TheFabricsDisplayNameElseItsName) {
  Fabric f;
  f.name = "linen_plain";
  EXPECT_EQ(label_text(f).title, "linen_plain");
  f.display_name = "Linen, plain weave";
  f.composition = "100 % linen";
  const LabelText t = label_text(f, "Sea green");
  EXPECT_EQ(t.title, "Linen, plain weave");
  EXPECT_EQ(t.colourway, "Sea green");
  EXPECT_EQ(t.composition, "100 % linen");
}

TEST(KioskLabel, TheGltfsTextForTheDressedObjectWhileItWearsItsOwnFabric) {
  SceneBundle sb;
  Fabric linen, velvet;
  linen.name = "linen_plain", linen.display_name = "Linen, plain weave", linen.composition = "100 % linen";
  velvet.name = "velvet";
  sb.fabrics = {{"linen_plain", linen}, {"velvet", velvet}};
  SceneObject chair;
  chair.name = "chair", chair.material = Material::cloth, chair.fabric = "linen_plain", chair.display_name = "Showroom linen";
  sb.scene.objects.push_back(chair);
  const LabelText own = label_text(sb, 0);
  EXPECT_EQ(own.title, "Showroom linen");
  EXPECT_EQ(own.composition, "100 % linen");  // the glTF gave no composition: the fabric's
  EXPECT_EQ(label_text(sb, 1).title, "velvet");  // the knobs put another fabric on it
  EXPECT_EQ(label_text(sb, 7).title, "velvet");  // as the knobs clamp it
  EXPECT_EQ(label_text(SceneBundle{}, 0).title, "");
}

TEST(KioskLabel, AFabricFileGivesItsDisplayNameAndComposition) {
  const Fabric f = load_fabric_preset("linen_plain", std::string(WEFT_SOURCE_ASSETS) + "/fabrics");
  EXPECT_EQ(f.display_name, "Linen, plain weave");
  EXPECT_EQ(f.composition, "100 % linen");
  const std::string base = R"({"name": "x", "threads": [)"
                           R"({"eta": 1.46, "albedo": [0.2, 0.8, 1.0], "albedo_scale": 0.3, "kd": 0.3, "gamma_s_deg": 12, "gamma_v_deg": 24, "coverage": 0.33, "tangent_offsets_deg": [-25, 25], "segment_lengths": [1]},)"
                           R"({"eta": 1.46, "albedo": [0.2, 0.8, 1.0], "albedo_scale": 0.3, "kd": 0.3, "gamma_s_deg": 12, "gamma_v_deg": 24, "coverage": 0.33, "tangent_offsets_deg": [-25, 25], "segment_lengths": [1]}])";
  EXPECT_EQ(parse_fabric(base + "}", "t").display_name, "");
  EXPECT_EQ(parse_fabric(base + R"(, "display_name": "Crêpe de chine"})", "t").display_name, "Crêpe de chine");
  EXPECT_THROW(parse_fabric(base + R"(, "composition": 100})", "t"), FabricError);
  EXPECT_THROW(parse_fabric(base + R"(, "display_name": "two\nlines"})", "t"), FabricError);
  EXPECT_THROW(parse_fabric(base + R"(, "display_name": ")" + std::string(121, 'x') + "\"}", "t"), FabricError);
}

}  // namespace
}  // namespace weft
