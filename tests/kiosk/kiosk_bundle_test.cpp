// Which method `weft run --method auto` shows for a bundle: the bake's searched or measured choice,
// a sheer, or the per-vertex default; and the bake/selection text it reads that choice from.
#include <gtest/gtest.h>

#include "core/fabric.h"
#include "kiosk/kiosk_bundle.h"
#include "kiosk/kiosk_config_error.h"

namespace weft {
namespace {

KioskBundle cloth_bundle(const std::string& preset, bool tables) {
  KioskBundle b;
  b.scene.fabrics.emplace(preset, load_fabric_preset(preset, WEFT_SOURCE_ASSETS "/fabrics"));
  SceneObject o;
  o.name = "cloth";
  o.material = Material::cloth;
  o.fabric = preset;
  b.scene.scene.objects.push_back(o);
  b.baked.tables = tables;
  return b;
}

// Occluded cloth without masks: the quadrature rungs would light it unoccluded, so the search's choice stands.
KioskBundle occluded_without_masks(const std::string& preset) {
  KioskBundle b = cloth_bundle(preset, true);
  b.baked.visibility.insert(0);
  return b;
}

TEST(KioskMethod, AutoTakesTheQuadratureRungWhereMasksCoverTheOccludedCloth) {
  KioskBundle open = cloth_bundle("linen_plain", true);  // nothing occluded: every cell is open
  EXPECT_EQ(kiosk_method("auto", open, "x.weft").name, "iwasaki_vertex_quadrature");
  open.baked_for = "iwasaki";
  EXPECT_EQ(kiosk_method("auto", open, "x.weft").name, "iwasaki_quadrature");
  KioskBundle masked = occluded_without_masks("linen_plain");
  masked.baked.masks.insert(0);
  EXPECT_EQ(kiosk_method("auto", masked, "x.weft").name, "iwasaki_vertex_quadrature");
  EXPECT_EQ(kiosk_method("iwasaki_vertex", masked, "x.weft").name, "iwasaki_vertex");  // --method wins
}

TEST(KioskMethod, AutoTakesTheMethodTheBakeSearchChose) {
  KioskBundle b = occluded_without_masks("linen_plain");
  EXPECT_EQ(kiosk_method("auto", b, "x.weft").name, "iwasaki_vertex");
  b.baked_for = "iwasaki";
  EXPECT_EQ(kiosk_method("auto", b, "x.weft").name, "iwasaki");
  b.baked_for = "iwasaki_vertex";
  EXPECT_EQ(kiosk_method("auto", b, "x.weft").name, "iwasaki_vertex");
  b.baked_for = "mizutani";  // not a choice the search makes: ignored
  EXPECT_EQ(kiosk_method("auto", b, "x.weft").name, "iwasaki_vertex");
  b.baked_for = "iwasaki";
  EXPECT_EQ(kiosk_method("sgpoint", b, "x.weft").name, "sgpoint");  // --method wins
}

TEST(KioskMethod, AutoTakesTheRungTheBakeChoseWhereMasksCoverTheOccludedCloth) {
  KioskBundle masked = occluded_without_masks("linen_plain");
  masked.baked.masks.insert(0);
  masked.baked_for = "iwasaki_vertex_mask_quadrature";  // weft bake --choose-rung
  EXPECT_EQ(kiosk_method("auto", masked, "x.weft").name, "iwasaki_vertex_mask_quadrature");
  masked.baked_for = "iwasaki_mask_quadrature";
  EXPECT_EQ(kiosk_method("auto", masked, "x.weft").name, "iwasaki_mask_quadrature");
  masked.baked_for = "sheer_vertex";  // reads no masks, see-through: not a rung choice
  EXPECT_EQ(kiosk_method("auto", masked, "x.weft").name, "iwasaki_vertex_quadrature");
  // Without a mask for the occluded cloth the masks' rung cannot draw: the default without masks.
  KioskBundle bare = occluded_without_masks("linen_plain");
  bare.baked_for = "iwasaki_vertex_mask_quadrature";
  EXPECT_EQ(kiosk_method("auto", bare, "x.weft").name, "iwasaki_vertex");
  EXPECT_EQ(kiosk_method("iwasaki_vertex", masked, "x.weft").name, "iwasaki_vertex");  // --method wins
}

TEST(KioskMethod, ASheerOrNoTablesDecideBeforeTheSearchedChoice) {
  KioskBundle sheer = cloth_bundle("polyester_voile", true);
  sheer.baked_for = "iwasaki";
  EXPECT_EQ(kiosk_method("auto", sheer, "x.weft").name, "sheer_vertex");
  KioskBundle bare = cloth_bundle("linen_plain", false);
  bare.baked_for = "iwasaki";
  EXPECT_EQ(kiosk_method("auto", bare, "x.weft").name, "sgpoint");
  EXPECT_THROW(kiosk_method("iwasaki", bare, "x.weft"), KioskConfigError);
}

TEST(KioskMethod, AMethodReadingTheMasksNeedsOneForEveryOccludedClothObject) {
  const KioskBundle bare = occluded_without_masks("linen_plain");  // weft bake --no-masks
  for (const char* m : {"iwasaki_mask", "iwasaki_vertex_mask", "iwasaki_mask_quadrature", "iwasaki_vertex_mask_quadrature"})
    EXPECT_THROW(kiosk_method(m, bare, "x.weft"), KioskConfigError) << m;
  // The broad lobes' quadrature draws without a mask (those lobes unoccluded), as does the SDF's rung.
  EXPECT_EQ(kiosk_method("iwasaki_vertex_quadrature", bare, "x.weft").name, "iwasaki_vertex_quadrature");
  EXPECT_EQ(kiosk_method("iwasaki_vertex", bare, "x.weft").name, "iwasaki_vertex");
  KioskBundle open = cloth_bundle("linen_plain", true);  // nothing occluded: nothing to mask
  EXPECT_EQ(kiosk_method("iwasaki_vertex_mask", open, "x.weft").name, "iwasaki_vertex_mask");
}

TEST(KioskMethod, SelectedMethodReadsTheSelectionSection) {
  EXPECT_EQ(selected_method(R"({"target_error": 0.05, "method": "iwasaki", "reached": true})"), "iwasaki");
  EXPECT_EQ(selected_method(R"({"target_error": 0.05})"), "");
  EXPECT_EQ(selected_method(R"({"method": 3})"), "");
  EXPECT_EQ(selected_method("[\"method\"]"), "");
  EXPECT_EQ(selected_method("{\"method\": \"iwa"), "");  // cut off
  EXPECT_EQ(selected_method(""), "");
}

}  // namespace
}  // namespace weft
