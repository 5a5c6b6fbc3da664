// The knobs' presets from a bundle: where they start (the last cloth object's fabric), and when
// positions turned for one bundle may carry over to another.
#include <gtest/gtest.h>

#include "kiosk/knob_appearance.h"
#include "kiosk/knob_presets.h"

namespace weft {
namespace {

// A bundle with these presets (name → albedo grey) and cloth objects wearing `worn`, in order.
SceneBundle bundle(const std::vector<std::pair<std::string, float>>& presets, const std::vector<std::string>& worn) {
  SceneBundle sb;
  for (const auto& [name, grey] : presets) {
    Fabric f = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
    f.name = name;
    for (auto& t : f.threads) t.albedo = glm::dvec3(grey);
    sb.fabrics.emplace(name, f);
  }
  for (const auto& w : worn) {
    SceneObject o;
    o.name = "cloth " + w;
    o.material = Material::cloth;
    o.fabric = w;
    sb.scene.objects.push_back(o);
  }
  return sb;
}

TEST(KnobPresets, TheKnobsStartFromTheLastClothObjectsFabric) {
  const SceneBundle sb = bundle({{"a", 0.2f}, {"b", 0.4f}, {"c", 0.6f}}, {"c", "b"});
  EXPECT_EQ(preset_list(sb).size(), 3u);
  EXPECT_EQ(knob_fabric(sb), "b");
  EXPECT_EQ(default_preset(sb), 1u);
  EXPECT_EQ(default_preset(bundle({{"a", 0.2f}}, {})), 0u);  // no cloth: the first preset
}

TEST(KnobPresets, PositionsCarryOverOnlyToTheSamePresetsWornTheSameWay) {
  const SceneBundle shown = bundle({{"a", 0.2f}, {"b", 0.4f}}, {"a"});
  const auto looks = preset_looks(preset_list(shown));
  EXPECT_EQ(knob_reset_reason(looks, 0, bundle({{"a", 0.2f}, {"b", 0.4f}}, {"a"})), "");
  EXPECT_EQ(knob_reset_reason(looks, 0, bundle({{"a", 0.2f}, {"b", 0.4f}}, {"b"})),
            "the cloth wears 'b' instead of 'a'");
  EXPECT_EQ(knob_reset_reason(looks, 0, bundle({{"a", 0.2f}, {"c", 0.4f}}, {"a"})),
            "the fabric presets differ: [a, b] -> [a, c]");
  // The same names in another colour are other presets to the shopper.
  EXPECT_NE(knob_reset_reason(looks, 0, bundle({{"a", 0.2f}, {"b", 0.5f}}, {"a"})), "");
}

}  // namespace
}  // namespace weft
