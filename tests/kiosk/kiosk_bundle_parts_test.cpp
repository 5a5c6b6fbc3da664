// The kiosk loads of a bundle's baked shading data the parts its method reads (RuntimeMethod's
// declarations, with the floors' and the weave layer's shadows), on a bundle the `weft` under test
// bakes: what it loads equals what a full read gives for those parts, and nothing else.
#include <gtest/gtest.h>

#include "bundle/bundle_reader.h"
#include "kiosk/kiosk_bundle.h"
#include "support/small_bundle.h"

namespace weft {
namespace {

TEST(KioskBundleParts, EachMethodLoadsThePartsItReads) {
  const test::SmallBundle small("pillow");
  ASSERT_TRUE(small.baked()) << "bake failed; see " << small.dir() / "bake.log";
  const bundle::BundleReader reader = bundle::BundleReader::open(small.file());
  const SceneBundle scene = read_scene_bundle(reader);
  const ShadingData full = read_scene_shading_data(reader, scene.scene);
  ASSERT_FALSE(full.tables.empty());
  ASSERT_FALSE(full.visibility.empty());
  ASSERT_FALSE(full.masks.empty());

  // The tables' rungs get everything; a rung without tables gets the shadows alone.
  const KioskBundle tables = read_kiosk_bundle(reader, "iwasaki_vertex");
  ASSERT_TRUE(tables.shading);
  EXPECT_EQ(tables.shading->tables.size(), full.tables.size());
  EXPECT_EQ(tables.shading->masks.size(), full.masks.size());
  const KioskBundle shadows = read_kiosk_bundle(reader, "sheen");
  ASSERT_TRUE(shadows.shading);
  EXPECT_TRUE(shadows.shading->tables.empty());
  ASSERT_EQ(shadows.shading->visibility.size(), full.visibility.size());
  for (const auto& [object, v] : full.visibility) EXPECT_EQ(shadows.shading->visibility.at(object).coefficients, v.coefficients);
  for (const auto& [object, m] : full.masks) EXPECT_EQ(shadows.shading->masks.at(object).words, m.words);
  EXPECT_TRUE(shadows.shading->kappa);

  // The indices tell what the bake holds, whatever was loaded.
  EXPECT_TRUE(shadows.baked.tables);
  EXPECT_EQ(shadows.baked.visibility.size(), full.visibility.size());
  EXPECT_EQ(shadows.baked.masks.size(), full.masks.size());
  EXPECT_EQ(kiosk_method("auto", shadows, small.file()).name, kiosk_method("auto", tables, small.file()).name);
}

TEST(KioskBundleParts, ABundleWithoutTablesLoadsNothing) {
  const test::SmallBundle small("pillow", "--no-tables");
  ASSERT_TRUE(small.baked()) << "bake failed; see " << small.dir() / "bake.log";
  const bundle::BundleReader reader = bundle::BundleReader::open(small.file());
  const KioskBundle b = read_kiosk_bundle(reader, "auto");
  EXPECT_FALSE(b.baked.tables);
  EXPECT_FALSE(b.shading);
  EXPECT_EQ(kiosk_method("auto", b, small.file()).name, "sgpoint");
}

}  // namespace
}  // namespace weft
