// The scene-level setting search on the swatch at a small size: a reachable target is held
// when measured independently (the chosen bundle drawn by the GPU frame of render/frame against a
// reference rendered here, not the search's cached one); an unreachable one says so and takes
// the least error it measured; a second search reads its references from the cache. With the
// SG count of the map's fit searched too: a target fewer SGs reach holds on an independent
// render under the richer lighting, and an unreachable one still takes the closest. With the
// cloth mesh's subdivision searched, a refined setting costs its added vertices in work and its
// added mesh sections in bytes, and draws as measured on the refined mesh. With both shadings
// searched, per-pixel wins where the cloth has more vertices than the kiosk frame has cloth
// pixels (measure/frame_work.h) and per-vertex wins on the scene's own coarse mesh.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "measure/frame_work.h"
#include "bake/selection/scene_selection.h"
#include "measure/image_metrics.h"
#include "frame/frame_render.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "bake/writers/scene_bundle_writer.h"
#include "reference/scene_render.h"
#include "scene/mesh_subdivision.h"
#include "scene/mesh_vertex_order.h"
#include "scene/scene_file.h"
#include "support/sg_reference.h"

using namespace weft;

namespace {

struct Swatch {
  Scene scene;
  std::map<std::string, Fabric> fabrics;
  std::map<std::string, std::string> texts;
  SgLighting sgs;
  EnvMap map;
};

SgLighting fit_count(const EnvMap& map, int count) {
  SgFitOptions fit;
  fit.count = count;
  return fit_sgs(map, fit);
}

const Swatch& swatch() {
  static const Swatch s = [] {
    Swatch w;
    w.scene = load_scene_named("swatch", WEFT_SOURCE_ASSETS);
    for (const auto& o : w.scene.objects)
      if (o.material == Material::cloth && !w.fabrics.count(o.fabric)) {
        const auto file = fabric_file(o.fabric, WEFT_SOURCE_ASSETS "/fabrics");
        std::ifstream in(file);
        std::ostringstream text;
        text << in.rdbuf();
        w.texts[o.fabric] = text.str();
        w.fabrics.emplace(o.fabric, parse_fabric(text.str(), o.fabric));
      }
    w.map = load_env_map(env_map_file(w.scene.environment, WEFT_SOURCE_ASSETS "/envmaps"), NonFinitePolicy::clamp);
    w.sgs = fit_count(w.map, 6);
    return w;
  }();
  return s;
}

SceneSelectionOptions small_options(const std::filesystem::path& cache, double target) {
  SceneSelectionOptions o;
  o.target_error = target;
  o.cache = cache;
  o.grid = 12;
  o.views.width = 64, o.views.height = 48;
  o.views.sg_grid = 6, o.views.tangent_samples = 16;
  o.knobs.tangent_samples = {1, 2, 3, 4};
  o.timed_frames = 1;
  return o;
}

std::filesystem::path fresh_cache(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("weft_selection_test_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

// The scene camera's view of a selection's bundle under its own SGs, rendered here, against a
// reference rendered here under `lighting_sgs`.
double independent_error(const Swatch& w, const SceneSelection& s, const SgLighting& lighting_sgs) {
  const ReferenceRenderResult ref = test::sg_reference(w.scene, w.fabrics, lighting_sgs, 64, 48, 6, 16);
  const GpuFrame f = render_gpu_frame(refine_and_order_meshes(w.scene, s.subdivision), w.fabrics, s.sgs, s.method, 64,
                                      48, 0, std::make_shared<const ShadingData>(s.data));
  return bench::cloth_error(f.image, ref.image, ref.kinds).relative_rmse;
}

// SG counts searched, the references lit by a richer fit (16 SGs), few other knobs.
SceneSelectionOptions sg_options(const Swatch& w, const std::filesystem::path& cache, double target) {
  SceneSelectionOptions o = small_options(cache, target);
  o.knobs.tangent_samples = {2, 3};
  o.knobs.methods = {"iwasaki_vertex"};
  o.knobs.level_strides = {o.knobs.level_strides.back()};
  o.knobs.sg_counts = {2, 4, 8, 12};
  o.fit = [&w](int count) { return fit_count(w.map, count); };
  return o;
}

}  // namespace

TEST(SceneSelection, ReachableTargetHoldsOnAnIndependentRender) {
  const Swatch& w = swatch();
  const auto cache = fresh_cache("reach");
  const double target = 0.12;
  const SceneSelection s = select_scene_settings(w.scene, w.fabrics, w.texts, w.sgs, small_options(cache, target));
  ASSERT_TRUE(s.reached) << s.description << " error " << s.chosen.error;
  EXPECT_LE(s.chosen.error, target);
  EXPECT_EQ(s.chosen.view_errors.size(), 3u);
  EXPECT_TRUE(s.data.visibility.empty());  // the swatch is unoccluded: no visibility to pay for
  // The scene camera's view, rendered here, against a reference rendered here.
  const ReferenceRenderResult ref = test::sg_reference(w.scene, w.fabrics, w.sgs, 64, 48, 6, 16);
  const GpuFrame f = render_gpu_frame(refine_and_order_meshes(w.scene, s.subdivision), w.fabrics, w.sgs, s.method, 64,
                                      48, 0, std::make_shared<const ShadingData>(s.data));
  const double e = bench::cloth_error(f.image, ref.image, ref.kinds).relative_rmse;
  EXPECT_LE(e, target);
  EXPECT_NEAR(e, s.chosen.view_errors[0], 1e-3);
  EXPECT_EQ(s.sgs.size(), w.sgs.size());  // no SG count searched: the SGs given
  // Minimal: no single knob one step cheaper holds the target too.
  for (const auto& m : s.tried) {
    const SceneSetting& c = s.chosen.setting;
    const SceneSetting& t = m.setting;
    const int down = (c.samples[0] - t.samples[0]) + (c.samples[1] - t.samples[1]) + (c.levels - t.levels) +
                     (c.svd - t.svd) + (c.sdf - t.sdf) + (c.pca - t.pca) + (c.sgs - t.sgs) + (c.density - t.density);
    const bool one_step_down = t.method == c.method && down == 1 && t.samples[0] <= c.samples[0] &&
                               t.samples[1] <= c.samples[1] && t.levels <= c.levels && t.svd <= c.svd &&
                               t.density <= c.density;
    if (one_step_down) {
      EXPECT_GT(m.error, target) << describe(t, small_options(cache, target).knobs, false);
    }
  }
}

TEST(SceneSelection, UnreachableTargetTakesTheClosestAndCachedReferencesAreReused) {
  const Swatch& w = swatch();
  const auto cache = fresh_cache("unreach");
  SceneSelectionOptions o = small_options(cache, 1e-4);
  o.knobs.tangent_samples = {1, 2};
  o.knobs.methods = {"iwasaki_vertex"};
  const SceneSelection s = select_scene_settings(w.scene, w.fabrics, w.texts, w.sgs, o);
  EXPECT_FALSE(s.reached);
  EXPECT_EQ(s.references_rendered, 3);
  EXPECT_EQ(s.references_cached, 0);
  for (const auto& m : s.tried) EXPECT_GE(m.error, s.chosen.error);
  EXPECT_GT(s.chosen.error, o.target_error);
  // Again: every reference from the cache, the same measurements.
  const SceneSelection again = select_scene_settings(w.scene, w.fabrics, w.texts, w.sgs, o);
  EXPECT_EQ(again.references_rendered, 0);
  EXPECT_EQ(again.references_cached, 3);
  EXPECT_EQ(again.chosen.setting, s.chosen.setting);
  EXPECT_NEAR(again.chosen.error, s.chosen.error, 1e-9);
}

TEST(SceneSelection, FewerSgsHoldATargetOnAnIndependentRender) {
  const Swatch& w = swatch();
  const auto cache = fresh_cache("sgs");
  const SgLighting rich = fit_count(w.map, 16);
  const double target = 0.12;
  const SceneSelectionOptions o = sg_options(w, cache, target);
  const SceneSelection s = select_scene_settings(w.scene, w.fabrics, w.texts, rich, o);
  std::printf("%s: error %.4f\n", s.description.c_str(), s.chosen.error);
  for (const auto& m : s.tried) std::printf("  %s: %.4f, work %.3g\n", describe(m.setting, o.knobs, false).c_str(), m.error, m.work);
  ASSERT_TRUE(s.reached);
  EXPECT_EQ(int(s.sgs.size()), s.chosen.sg_count);
  EXPECT_LT(s.chosen.sg_count, 12);  // the paper's count (the card's 10, next offered: 12) is more than needed
  const double e = independent_error(w, s, rich);
  EXPECT_LE(e, target);
  EXPECT_NEAR(e, s.chosen.view_errors[0], 1e-3);
  // The one-step-fewer SG count, measured, missed the target (or the search would have taken it).
  for (const auto& m : s.tried)
    if (m.setting.method == s.chosen.setting.method && m.setting.samples == s.chosen.setting.samples &&
        m.setting.svd == s.chosen.setting.svd && m.setting.sgs + 1 == s.chosen.setting.sgs) {
      EXPECT_GT(m.error, target);
    }
}

TEST(SceneSelection, UnreachableWithSgCountsTakesTheClosest) {
  const Swatch& w = swatch();
  const auto cache = fresh_cache("sgs_unreach");
  const SgLighting rich = fit_count(w.map, 16);
  const SceneSelectionOptions o = sg_options(w, cache, 1e-4);
  const SceneSelection s = select_scene_settings(w.scene, w.fabrics, w.texts, rich, o);
  EXPECT_FALSE(s.reached);
  for (const auto& m : s.tried) EXPECT_GE(m.error, s.chosen.error);
  EXPECT_EQ(int(s.sgs.size()), s.chosen.sg_count);
  SceneSelectionOptions no_fit = o;
  no_fit.fit = nullptr;
  EXPECT_THROW(select_scene_settings(w.scene, w.fabrics, w.texts, rich, no_fit), std::invalid_argument);
}

TEST(SceneSelection, SubdivisionCostsItsVerticesAndDrawsAsMeasured) {
  const Swatch& w = swatch();
  const auto cache = fresh_cache("subdivision");
  SceneSelectionOptions o = small_options(cache, 1e-4);  // unreachable: the search tries every step up
  o.knobs.tangent_samples = {2, 3};
  o.knobs.level_strides = {o.knobs.level_strides.back()};
  o.knobs.svd_errors = {0.01};
  o.knobs.methods = {"iwasaki_vertex"};
  o.knobs.subdivisions = {0, 1};
  const SceneSelection s = select_scene_settings(w.scene, w.fabrics, w.texts, w.sgs, o);
  const Scene refined = refine_cloth_meshes(w.scene, 1);
  size_t added_bytes = 0;
  double vertices = 0, refined_vertices = 0;
  for (size_t i = 0; i < w.scene.objects.size(); ++i) {
    added_bytes += mesh_section_bytes(refined.objects[i].mesh) - mesh_section_bytes(w.scene.objects[i].mesh);
    if (w.scene.objects[i].material != Material::cloth) continue;
    vertices += double(w.scene.objects[i].mesh.positions.size());
    refined_vertices += double(refined.objects[i].mesh.positions.size());
  }
  ASSERT_GT(added_bytes, 0u);
  // Each refined setting measured beside its unrefined twin: the added mesh bytes, and the work
  // of its vertices (the same SGs and samples).
  int pairs = 0;
  for (const auto& a : s.tried) {
    if (a.setting.density != 1) continue;
    EXPECT_EQ(a.subdivision, 1);
    for (const auto& b : s.tried) {
      SceneSetting twin = a.setting;
      twin.density = 0;
      if (b.setting != twin) continue;
      ++pairs;
      EXPECT_EQ(a.bytes - b.bytes, added_bytes);
      // The linen swatch: both threads curved, each sample counted per vertex.
      const double samples = o.knobs.tangent_samples[a.setting.samples[0]] + o.knobs.tangent_samples[a.setting.samples[1]];
      EXPECT_NEAR(a.work - b.work, kVertexStepCost * a.sg_count * samples * (refined_vertices - vertices), 1e-6 * a.work);
    }
  }
  EXPECT_GE(pairs, 1);
  EXPECT_NE(describe(s.chosen.setting, o.knobs, false).find("subdivision"), std::string::npos);
  // The chosen setting, drawn on its mesh here, gives the error the search measured.
  const double e = independent_error(w, s, w.sgs);
  EXPECT_NEAR(e, s.chosen.view_errors[0], 1e-3);
  o.knobs.subdivisions = {kMaxSubdivision + 1};
  EXPECT_THROW(select_scene_settings(w.scene, w.fabrics, w.texts, w.sgs, o), std::invalid_argument);
}

namespace {

// Both shadings searched on the swatch with its cloth refined `given` levels as the scene's mesh
// and the search's subdivision fixed at `levels`, the camera pulled back `distance` times from its
// target (fewer cloth pixels against the same vertices), views `width`×`height`.
SceneSelection both_methods(const Swatch& w, const std::string& name, int given, int levels, double distance,
                            int width, int height) {
  Scene scene = refine_cloth_meshes(w.scene, given);
  scene.camera.position = scene.camera.target + distance * (scene.camera.position - scene.camera.target);
  SceneSelectionOptions o = small_options(fresh_cache(name), 0.12);
  o.views.width = width, o.views.height = height;
  o.knobs.tangent_samples = {2, 3};
  o.knobs.level_strides = {o.knobs.level_strides.back()};
  o.knobs.svd_errors = {0.01};
  o.knobs.subdivisions = {levels};
  o.knobs.sdf_resolutions = {32};  // the swatch is unoccluded: the coarsest probe tells so soonest
  return select_scene_settings(scene, w.fabrics, w.texts, w.sgs, o);
}

// The setting measured for the other method that holds the target at the least work.
std::optional<SettingMeasure> cheapest_other(const SceneSelection& s) {
  std::optional<SettingMeasure> best;
  for (const auto& m : s.tried)
    if (m.setting.method != s.chosen.setting.method && m.error <= s.target && (!best || m.work < best->work)) best = m;
  return best;
}

}  // namespace

TEST(SceneSelection, DensePerVertexLosesToPerPixelAtTheKioskResolution) {
  // Four levels put 66 049 vertices on the swatch; pulled back four times, it covers ~450 pixels
  // of a 160×120 view, ~7 300 of the kiosk's 640×480: shading every vertex (0.22 of a pixel's
  // step each, measure/frame_work.h) costs about twice what shading every pixel does.
  const SceneSelection s = both_methods(swatch(), "dense_vertex", 2, 2, 4.0, 160, 120);
  ASSERT_TRUE(s.reached);
  EXPECT_EQ(s.method, "iwasaki");
  const auto other = cheapest_other(s);
  ASSERT_TRUE(other.has_value()) << "per-vertex held the target too: it lost on cost, not on error";
  EXPECT_GT(other->work, s.chosen.work);
}

TEST(SceneSelection, SceneMeshPerVertexBeatsPerPixel) {
  // The swatch's own 289 vertices against its cloth pixels in a 640×480 frame (~180 000).
  const SceneSelection s = both_methods(swatch(), "mesh_vertex", 0, 0, 1.0, 64, 48);
  ASSERT_TRUE(s.reached);
  EXPECT_EQ(s.method, "iwasaki_vertex");
  EXPECT_EQ(s.subdivision, 0);
  const auto other = cheapest_other(s);
  ASSERT_TRUE(other.has_value()) << "per-pixel held the target too: it lost on cost, not on error";
  EXPECT_GT(other->work, s.chosen.work);
}
