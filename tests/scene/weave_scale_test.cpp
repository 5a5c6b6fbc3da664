// Each vertex's weave coordinates (scene/weave_scale.h): every UV island of an atlas shows the
// fabric's own repeat, whatever its texel density; authored repeats per UV unit hold everywhere.
#include "scene/weave_scale.h"

#include <gtest/gtest.h>

#include "core/weave_layout.h"

using namespace weft;
using glm::dvec2;
using glm::dvec3;

static const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

namespace {
// A flat square of side `side` metres at x offset `x0`, its UVs the square of side `uv_side` at `uv0`:
// side / uv_side metres per UV unit. Appended as its own island (no shared vertex).
void add_panel(TriangleMesh& m, double x0, double side, dvec2 uv0, double uv_side) {
  const uint32_t base = uint32_t(m.positions.size());
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      m.positions.push_back(dvec3(x0 + i * side, j * side, 0.0));
      m.normals.push_back(dvec3(0, 0, 1));
      m.uvs.push_back(uv0 + dvec2(i, j) * uv_side);
    }
  m.triangles.push_back({base, base + 1, base + 3});
  m.triangles.push_back({base, base + 3, base + 2});
}

SceneObject cloth(TriangleMesh mesh) {
  SceneObject o;
  o.name = "seat";
  o.material = Material::cloth;
  o.fabric = "linen_plain";
  o.mesh = std::move(mesh);
  return o;
}

// Weave coordinates per metre along x and y on the panel whose first vertex is `base`.
dvec2 per_metre(const std::vector<dvec2>& st, const TriangleMesh& m, uint32_t base) {
  const double dx = m.positions[base + 1].x - m.positions[base].x, dy = m.positions[base + 2].y - m.positions[base].y;
  return {(st[base + 1].x - st[base].x) / dx, (st[base + 2].y - st[base].y) / dy};
}
}  // namespace

TEST(WeaveCoordinates, EachAtlasPanelShowsTheFabricsRepeat) {
  const Fabric f = load_fabric_preset("linen_plain", kAssets / "fabrics");
  const dvec2 per_repeat = 100.0 / weave_repeat_cm(f);  // repeats per metre
  // Two panels of 0.5 m: one at 1 m per UV unit, one packed at 4 m per UV unit (a quarter of the texels).
  TriangleMesh m;
  add_panel(m, 0.0, 0.5, {0.0, 0.0}, 0.5);
  add_panel(m, 1.0, 0.5, {0.6, 0.0}, 0.125);
  const SceneObject o = cloth(m);
  const std::vector<dvec2> st = weave_coordinates(o, f);
  ASSERT_EQ(st.size(), m.positions.size());
  for (uint32_t base : {0u, 4u}) {
    const dvec2 d = per_metre(st, m, base);
    EXPECT_NEAR(d.x, per_repeat.x, 1e-9 * per_repeat.x) << "panel at vertex " << base;
    EXPECT_NEAR(d.y, per_repeat.y, 1e-9 * per_repeat.y) << "panel at vertex " << base;
  }
  // One scale for the whole object (its UV-area mean, 1.18 m per UV unit) would show the packed
  // panel's threads at over twice their size, and the other's 18 % too small.
  const dvec2 mean = weave_tiles_per_uv(o, f);
  EXPECT_LT(mean.x * 0.125 / 0.5, 0.5 * per_repeat.x);
  EXPECT_GT(mean.x * 0.5 / 0.5, 1.1 * per_repeat.x);
}

TEST(WeaveCoordinates, AuthoredRepeatsPerUvHoldOnEveryIsland) {
  const Fabric f = load_fabric_preset("linen_plain", kAssets / "fabrics");
  TriangleMesh m;
  add_panel(m, 0.0, 0.5, {0.0, 0.0}, 0.5);
  add_panel(m, 1.0, 0.5, {0.6, 0.0}, 0.125);
  SceneObject o = cloth(m);
  o.weave_repeats_per_uv = {30.0, 12.0};
  const std::vector<dvec2> st = weave_coordinates(o, f);
  ASSERT_EQ(st.size(), m.uvs.size());
  for (size_t v = 0; v < st.size(); ++v) {
    EXPECT_DOUBLE_EQ(st[v].x, 30.0 * m.uvs[v].x);
    EXPECT_DOUBLE_EQ(st[v].y, 12.0 * m.uvs[v].y);
  }
}

TEST(WeaveCoordinates, ACollapsedIslandTakesTheObjectsMeanAndNoUvsGiveNone) {
  const Fabric f = load_fabric_preset("linen_plain", kAssets / "fabrics");
  TriangleMesh m;
  add_panel(m, 0.0, 0.5, {0.0, 0.0}, 0.5);
  add_panel(m, 1.0, 0.5, {0.7, 0.7}, 0.0);  // every UV at one point: no UV area
  const SceneObject o = cloth(m);
  const std::vector<dvec2> st = weave_coordinates(o, f);
  const dvec2 mean = weave_tiles_per_uv(o, f);
  for (uint32_t v = 4; v < 8; ++v) {
    EXPECT_DOUBLE_EQ(st[v].x, 0.7 * mean.x);
    EXPECT_DOUBLE_EQ(st[v].y, 0.7 * mean.y);
  }
  TriangleMesh bare = m;
  bare.uvs.clear();
  EXPECT_TRUE(weave_coordinates(cloth(bare), f).empty());
}

TEST(WeaveDegenerateUvs, APointOrALineIsDegenerateAThinTriangleIsNot) {
  EXPECT_TRUE(weave_degenerate_uvs({0.3, 0.3}, {0.3, 0.3}, {0.3, 0.3}));
  EXPECT_TRUE(weave_degenerate_uvs({0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}));  // collinear
  EXPECT_TRUE(weave_degenerate_uvs({0.0, 0.0}, {0.0, 0.0}, {5.0, 1.0}));  // two corners at one point
  EXPECT_FALSE(weave_degenerate_uvs({0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}));
  EXPECT_FALSE(weave_degenerate_uvs({0.0, 0.0}, {1.0, 0.0}, {0.5, 0.01}));  // 1 : 100, still a place for threads
  EXPECT_FALSE(weave_degenerate_uvs({0.0, 0.0}, {1e-6, 0.0}, {0.0, 1e-6}));  // tiny in tile units, not collapsed
}
