// `weft bake --choose-rung` (bake/selection/rung_choice.h) on the pillow, which the floor occludes, at a small
// size: each candidate's recorded error matches the same bundle drawn here (render/frame) against a
// reference rendered here, so the rung chosen is the one an independent measure finds closer; a
// second choice reads its reference from the cache; the record names the choice for
// `weft run --method auto`; bad input gets a clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "bake/selection/rung_choice.h"
#include "bake/scene/scene_bake.h"
#include "measure/image_metrics.h"
#include "frame/frame_render.h"
#include "gl/gl_error.h"
#include "reference/scene_render.h"
#include "support/scene_case.h"
#include "support/sg_reference.h"

using namespace weft;

namespace {

// The pillow in linen under 10 SGs fitted to its map, baked small, with masks.
struct Pillow : test::SceneCase {
  std::shared_ptr<const ShadingData> data;
};

const Pillow& pillow() {
  static const Pillow p = [] {
    Pillow w;
    static_cast<test::SceneCase&>(w) = test::scene_in_fabric("pillow", "linen_plain");
    ShadingDataBakeOptions bake;
    bake.grid = 12, bake.lambda_levels = 5, bake.tangent_samples = {2, 3};
    bake.visibility.resolution = 16, bake.visibility.lambertian_resolution = 16;
    bake.mask_resolution = 16;
    bake.quiet = true;
    w.data = std::make_shared<const ShadingData>(bake_shading_data(w.scene, w.fabrics, bake));
    return w;
  }();
  return p;
}

SelectionViewOptions small_views() {
  SelectionViewOptions v;
  v.count = 2, v.width = 64, v.height = 48, v.sg_grid = 6, v.tangent_samples = 8;
  return v;
}

// One folder per test: ctest runs the tests of this file side by side.
std::filesystem::path fresh_cache(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("weft_rung_choice_test_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

}  // namespace

TEST(RungChoice, ChoosesTheRungAnIndependentRenderFindsCloser) {
  const Pillow& w = pillow();
  ASSERT_FALSE(w.data->masks.empty()) << "the pillow should be occluded (by its floor) and get a mask";
  const auto cache = fresh_cache("closer");
  const RungChoice c = choose_rung(w.scene, w.texts, w.sgs, w.data, kVertexRungCandidates, small_views(), cache);
  ASSERT_EQ(c.measured.size(), 2u);
  EXPECT_EQ(c.measured[0].method, "iwasaki_vertex_quadrature");
  EXPECT_EQ(c.measured[1].method, "iwasaki_vertex_mask_quadrature");
  EXPECT_EQ(c.views, 2);
  EXPECT_EQ(c.references_rendered, 2);
  // The scene camera's view, rendered here, against a reference rendered here.
  const ReferenceRenderResult ref = test::sg_reference(w.scene, w.fabrics, w.sgs, 64, 48, 6, 8);
  std::vector<double> independent;
  for (const auto& m : c.measured) {
    ASSERT_EQ(m.view_errors.size(), 2u);
    EXPECT_GT(m.error, 0.0) << m.method;
    EXPECT_LT(m.error, 0.5) << m.method;
    EXPECT_GE(m.error, m.view_errors[0]);
    const GpuFrame f = render_gpu_frame(w.scene, w.fabrics, w.sgs, m.method, 64, 48, 0, w.data);
    independent.push_back(bench::cloth_error(f.image, ref.image, ref.kinds).relative_rmse);
    EXPECT_NEAR(independent.back(), m.view_errors[0], 1e-3) << m.method;
  }
  // The two visibilities differ on this cloth: the choice is a real one.
  EXPECT_GT(std::abs(c.measured[0].error - c.measured[1].error), 1e-4);
  const size_t chosen = c.measured[0].error <= c.measured[1].error ? 0 : 1;
  EXPECT_EQ(c.method, c.measured[chosen].method);
  std::printf("SDF %.4f, masks %.4f (worst of 2 views): %s\n", c.measured[0].error, c.measured[1].error, c.method.c_str());

  // The record: what the kiosk reads back.
  const auto j = nlohmann::json::parse(rung_choice_json(c));
  EXPECT_EQ(j.at("method"), c.method);
  EXPECT_EQ(j.at("candidates").size(), 2u);
  EXPECT_NEAR(j.at("candidates")[1].at("error").get<double>(), c.measured[1].error, 1e-12);

  // Again: the references come from the cache, the measures are the same.
  const RungChoice again = choose_rung(w.scene, w.texts, w.sgs, w.data, kVertexRungCandidates, small_views(), cache);
  EXPECT_EQ(again.references_rendered, 0);
  EXPECT_EQ(again.references_cached, 2);
  EXPECT_EQ(again.method, c.method);
  EXPECT_NEAR(again.measured[1].error, c.measured[1].error, 1e-9);
  std::filesystem::remove_all(cache);
}

TEST(RungChoice, BadInputGetsAClearError) {
  const Pillow& w = pillow();
  const auto cache = fresh_cache("bad_input");
  EXPECT_THROW(choose_rung(w.scene, w.texts, w.sgs, w.data, {}, small_views(), cache), std::invalid_argument);
  Scene bare = w.scene;  // no cloth: nothing to choose for
  for (auto& o : bare.objects) o.material = Material::lambertian;
  EXPECT_THROW(choose_rung(bare, w.texts, w.sgs, w.data, kVertexRungCandidates, small_views(), cache),
               std::invalid_argument);
  // A bundle without masks cannot draw the masks' rung: the renderer says which object lacks one.
  auto no_masks = std::make_shared<ShadingData>(*w.data);
  no_masks->masks.clear();
  try {
    choose_rung(w.scene, w.texts, w.sgs, no_masks, {"iwasaki_vertex_mask_quadrature"}, small_views(), cache);
    ADD_FAILURE() << "expected an error for a bundle without masks";
  } catch (const gpu::GpuError& e) {
    EXPECT_NE(std::string(e.what()).find("no visibility mask"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(cache);
}
