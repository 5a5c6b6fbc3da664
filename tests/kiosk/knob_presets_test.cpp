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

TEST(KnobPresets, TheKnobsStartFromTheProductColourAndAKnobEditStillChangesIt) {
  SceneBundle sb = bundle({{"linen_plain", 0.3f}, {"velvet", 0.5f}}, {"linen_plain", "linen_plain"});
  sb.fabrics["linen_plain"] = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  const glm::dvec3 red(0.7, 0.2, 0.1), blue(0.1, 0.2, 0.7);
  sb.scene.objects[0].colour = blue;
  sb.scene.objects[1].colour = red;  // the last cloth object: the knobs dress it
  const std::vector<Fabric> presets = preset_list(sb);
  const std::uint32_t start = default_preset(sb);
  ASSERT_EQ(presets.at(start).name, "linen_plain");
  for (int t = 0; t < 2; ++t)  // linen_plain's albedo_scale is 0.3 on both threads
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(presets[start].threads[t].albedo[k], 0.3 * red[k], 1e-12);
  EXPECT_TRUE(knobs_dress(sb, sb.scene.objects[1]));
  EXPECT_FALSE(knobs_dress(sb, sb.scene.objects[0]));  // the same fabric in another colour keeps its own

  input::KnobMapper mapper(preset_looks(presets));
  input::KnobPositions p;
  p.preset = start;
  mapper.set_positions(p);
  const Fabric unedited = apply_knobs(presets[start], mapper.appearance());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(unedited.threads[0].albedo[k], 0.3 * red[k], 1e-6);
  input::KnobEvent hue;
  hue.dial[0] = 40;  // 120 degrees round the colour wheel: red becomes green
  ASSERT_TRUE(mapper.apply(hue));
  const Fabric edited = apply_knobs(presets[start], mapper.appearance());
  EXPECT_GT(edited.threads[0].albedo.g, edited.threads[0].albedo.r);
  // What the renderer draws for a knob edit (object_fabric) keeps the knob's colour, not the product's.
  const Fabric drawn = object_fabric(sb.scene.objects[1], edited);
  for (int t = 0; t < 2; ++t) EXPECT_EQ(drawn.threads[t].albedo, edited.threads[t].albedo);
}

TEST(KnobPresets, CyclingTheColourwayDressesTheClothInTheNextOnesFabricAndColour) {
  const std::string dir = WEFT_SOURCE_ASSETS "/fabrics";
  SceneBundle sb;
  for (const char* name : {"linen_plain", "velvet", "silk_shot"}) sb.fabrics.emplace(name, load_fabric_preset(name, dir));
  SceneObject body, cushion;
  body.name = "body";
  cushion.name = "cushion";
  body.material = cushion.material = Material::cloth;
  body.fabric = "silk_shot";
  cushion.fabric = "linen_plain";
  sb.scene.objects = {body, cushion};
  const glm::dvec3 ocean(0.1, 0.3, 0.6), moss(0.2, 0.5, 0.1);
  sb.scene.colourways = {{"Ocean", {{"cushion", {"linen_plain", ocean}}}}, {"Moss", {{"cushion", {"velvet", moss}}}}};
  const auto looks = colourway_presets(sb);
  ASSERT_EQ(looks.size(), 2u);

  input::KnobMapper mapper(preset_looks(preset_list(sb)));
  mapper.set_colourways(looks);
  const auto drawn = [&] {  // the dressed cloth's fabric as the kiosk draws it for the knob state
    const input::AppearanceState s = mapper.appearance();
    return apply_knobs(colourway_preset_list(sb, s.colourway).at(s.preset_index), s);
  };
  Fabric f = drawn();
  EXPECT_EQ(f.name, "linen_plain");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f.threads[0].albedo[k], 0.3 * ocean[k], 1e-6);  // linen: albedo_scale 0.3
  input::KnobEvent next;
  next.colourway = 1;
  ASSERT_TRUE(mapper.apply(next));
  f = drawn();
  EXPECT_EQ(f.name, "velvet");
  const Fabric velvet = load_fabric_preset("velvet", dir);
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f.threads[t].albedo[k], velvet.albedo_scale[t] * moss[k], 1e-6);

  // The scene worn in Moss: its base fabrics (what the renderer gets) and the objects the knobs dress.
  SceneBundle worn = sb;
  wear_looks(worn.scene, colourway_looks(sb.scene, cloth_looks(sb.scene), 1));
  EXPECT_EQ(worn.scene.objects[1].fabric, "velvet");
  EXPECT_EQ(worn.scene.objects[0].fabric, "silk_shot");  // not named by the colourway: its own look
  EXPECT_TRUE(knobs_dress(worn, worn.scene.objects[1]));
  EXPECT_EQ(knob_reset_reason(preset_looks(preset_list(sb)), default_preset(sb), sb, {"Ocean", "Moss"}), "");
  EXPECT_EQ(knob_reset_reason(preset_looks(preset_list(sb)), default_preset(sb), sb, {"Ocean"}), "the colourways differ");
}

}  // namespace
}  // namespace weft
