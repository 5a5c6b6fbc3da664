#include "bake/selection/scene_selection.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "measure/frame_work.h"
#include "bake/writers/scene_bundle_writer.h"
#include "bake/selection/setting_truncation.h"
#include "bake/visibility/sigmoid_gain.h"
#include "bake/tables/weighting_bake.h"
#include "methods/registry.h"
#include "runtime/paper_tangent_samples.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "methods/sg_lighting_uniforms.h"
#include "scene/mesh_subdivision.h"
#include "scene/mesh_vertex_order.h"

namespace weft {

std::vector<int> level_strides_of(int levels) {
  std::vector<int> strides;
  for (int stride = std::max(levels - 1, 1); stride >= 1; --stride)
    if ((levels - 1) % stride == 0 && (levels - 1) / stride + 1 >= 3) strides.push_back(stride);
  if (strides.empty()) strides.push_back(1);
  return strides;
}

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool straight(const Fabric& f, int thread) {
  const auto& o = f.threads[thread].curve.offsets_deg();
  return std::all_of(o.begin(), o.end(), [&](double x) { return x == o.front(); });
}

// A method that shades per vertex and interpolates (the one mesh density matters to).
bool per_vertex(const std::string& method) { return method.find("vertex") != std::string::npos; }

size_t visibility_bytes(const ObjectVisibility& v) {
  return 4 * (v.mean.size() + v.basis.size() + v.coefficients.size());
}

// The search's state: bakes by what they depend on, measures by setting, one GLES context.
class Search {
public:
  Search(const Scene& scene, const std::map<std::string, Fabric>& fabrics, const SgLighting& sgs,
         const ViewReferences& refs, const SceneSelectionOptions& o)
      : scene_(scene), fabrics_(fabrics), sgs_(sgs), refs_(refs), o_(o), knobs_(o.knobs),
        ctx_(gpu::EglContext::headless()), target_(o.views.width, o.views.height) {
    for (int j = 0; j < 2; ++j)
      for (const auto& [name, f] : fabrics_) curved_[j] = curved_[j] || !straight(f, j);
    views_ = refs.cameras;
    for (const auto& o2 : scene_.cloth_objects()) cloth_.push_back(object_base_fabric(o2, fabrics_));
    for (PixelKind k : refs.images.at(0).kinds) cloth_pixels_ += k == PixelKind::cloth ? 1.0 : 0.0;
    // Occluded at all? The paper's SDF tells (an unoccluded scene stores no visibility).
    int paper_sdf = 0;
    while (paper_sdf + 1 < int(knobs_.sdf_resolutions.size()) && knobs_.sdf_resolutions[paper_sdf] < 128) ++paper_sdf;
    occluded_ = !visibility(paper_sdf, 0).empty();
    if (occluded_) {
      const auto t0 = std::chrono::steady_clock::now();
      kappa_ = fit_sigmoid_gain_table(SigmoidGainTableSpec{});
      say("kappa table fitted (" + number(std::round(since(t0) * 10) / 10) + " s)");
    }
  }

  bool occluded() const { return occluded_; }
  bool curved(int thread) const { return curved_[thread]; }

  // Index limits of the knobs that matter for this scene and method (1: fixed at the first value).
  int knob_count(int k, int method) const {
    switch (k) {
      case 0: return curved_[0] ? int(knobs_.tangent_samples.size()) : 1;
      case 1: return curved_[1] ? int(knobs_.tangent_samples.size()) : 1;
      case 2: return int(knobs_.level_strides.size());
      case 3: return int(knobs_.svd_errors.size());
      case 4: return occluded_ ? int(knobs_.sdf_resolutions.size()) : 1;
      case 5: return occluded_ ? int(knobs_.pca_errors.size()) : 1;
      case 6: return std::max<int>(knobs_.sg_counts.size(), 1);
      default: return per_vertex(knobs_.methods[method]) ? int(knobs_.subdivisions.size()) : 1;
    }
  }
  static int& knob(SceneSetting& s, int k) {
    switch (k) {
      case 0: return s.samples[0];
      case 1: return s.samples[1];
      case 2: return s.levels;
      case 3: return s.svd;
      case 4: return s.sdf;
      case 5: return s.pca;
      case 6: return s.sgs;
      default: return s.density;
    }
  }
  static constexpr int kKnobs = 8;

  // The paper's setting (seed 000: its tangent samples, 9 levels, SVD 0.01, SDF 128², PCA
  // 0.01 rad; the product card's 10 SGs; the scene's own mesh), each knob at the nearest value it
  // offers (the next larger where none is equal).
  SceneSetting paper(int method) const {
    SceneSetting s;
    s.method = method;
    auto nearest = [](const auto& values, auto v) {
      int i = 0;
      while (i + 1 < int(values.size()) && values[i] < v) ++i;
      return i;
    };
    for (int j = 0; j < 2; ++j) {
      int n = 1;
      for (const auto& [name, f] : fabrics_) n = std::max(n, paper_tangent_samples(f)[j]);
      s.samples[j] = curved_[j] ? nearest(knobs_.tangent_samples, n) : 0;
    }
    int stride = 0;
    while (stride + 1 < int(knobs_.level_strides.size()) && knobs_.level_strides[stride] > 1) ++stride;
    s.levels = stride;
    s.svd = 0;
    while (s.svd + 1 < int(knobs_.svd_errors.size()) && knobs_.svd_errors[s.svd] > 0.01 + 1e-12) ++s.svd;
    if (occluded_) {
      s.sdf = nearest(knobs_.sdf_resolutions, 128);
      s.pca = 0;
      while (s.pca + 1 < int(knobs_.pca_errors.size()) && knobs_.pca_errors[s.pca] > 0.01 + 1e-12) ++s.pca;
    }
    if (!knobs_.sg_counts.empty()) s.sgs = nearest(knobs_.sg_counts, 10);
    if (per_vertex(knobs_.methods[method])) s.density = nearest(knobs_.subdivisions, 0);
    return s;
  }

  ShadingData data(const SceneSetting& s) {
    ShadingData d;
    for (const auto& [name, f] : fabrics_)
      d.tables.emplace(name, truncate_tables(tables(name, s.samples), knobs_.svd_errors[s.svd],
                                             knobs_.level_strides[s.levels]));
    if (occluded_) {
      for (const auto& [object, v] : visibility(s.sdf, s.density))
        d.visibility.emplace(object, truncate_visibility(v, knobs_.pca_errors[s.pca]));
      d.kappa = kappa_;
    }
    return d;
  }

  const SettingMeasure& measure(const SceneSetting& s) {
    if (auto it = measured_.find(s); it != measured_.end()) return it->second;
    auto bundle = std::make_shared<const ShadingData>(data(s));
    SettingMeasure m;
    m.setting = s;
    m.subdivision = knobs_.subdivisions[s.density];
    const Scene& drawn = scene(s.density);
    for (size_t i = 0; i < drawn.objects.size(); ++i)
      m.bytes += mesh_section_bytes(drawn.objects[i].mesh) - mesh_section_bytes(scene_.objects[i].mesh);
    for (const auto& [name, t] : bundle->tables) m.bytes += t.bytes();
    for (const auto& [object, v] : bundle->visibility) m.bytes += visibility_bytes(v);
    if (bundle->kappa) m.bytes += 4 * bundle->kappa->normalized_gains().size();
    const SgLighting& sgs = lighting(s.sgs);
    m.sg_count = int(sgs.size());
    m.work = work(s, *bundle, m.sg_count);
    ctx_.make_current();
    gpu::SceneRenderer renderer(drawn, cloth_, methods::method(knobs_.methods[s.method]), 16, bundle);
    renderer.set_lighting(sgs);
    target_.bind();
    const int w = o_.views.width, h = o_.views.height;
    if (o_.timed_frames > 0) {  // view 0, after a warm-up frame
      renderer.draw(views_[0], w, h);
      glFinish();
      std::vector<double> ms;
      for (int i = 0; i < o_.timed_frames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        renderer.draw(views_[0], w, h);
        glFinish();
        ms.push_back(1e3 * since(t0));
      }
      std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
      m.ms = ms[ms.size() / 2];
    }
    m.view_errors = view_errors(renderer, refs_, w, h);
    m.error = *std::max_element(m.view_errors.begin(), m.view_errors.end());
    char buf[160];
    std::snprintf(buf, sizeof buf, ": error %.4f, %.2f MB, %.1f ms", m.error, m.bytes / 1e6, m.ms);
    say(describe(s, knobs_, occluded_) + buf);
    tried_.push_back(m);
    return measured_.emplace(s, std::move(m)).first->second;
  }

  const std::vector<SettingMeasure>& tried() const { return tried_; }

  // The SGs of a setting: the fit at its count, or the SGs given when the count is not searched.
  const SgLighting& lighting(int sg_index) {
    if (knobs_.sg_counts.empty()) return sgs_;
    const int count = knobs_.sg_counts[sg_index];
    if (auto it = fits_.find(count); it != fits_.end()) return it->second;
    const auto t0 = std::chrono::steady_clock::now();
    SgLighting fit = o_.fit(count);
    say(std::to_string(count) + " SGs fitted (" + number(std::round(since(t0) * 10) / 10) + " s)");
    return fits_.emplace(count, std::move(fit)).first->second;
  }
  void say(const std::string& line) const {
    if (o_.log) o_.log(line);
  }

  // The scene at a density (knob index): its cloth meshes refined that many levels, in the bake's
  // vertex order.
  const Scene& scene(int density) {
    const int levels = knobs_.subdivisions[density];
    if (levels == 0) return scene_;
    if (auto it = refined_.find(levels); it != refined_.end()) return it->second;
    return refined_.emplace(levels, refine_and_order_meshes(scene_, levels)).first->second;
  }

private:
  const Scene& scene_;
  const std::map<std::string, Fabric>& fabrics_;
  const SgLighting& sgs_;
  const ViewReferences& refs_;
  const SceneSelectionOptions& o_;
  const SelectionKnobs& knobs_;
  std::array<bool, 2> curved_{false, false};
  std::vector<Camera> views_;
  std::vector<Fabric> cloth_;
  bool occluded_ = false;
  std::optional<SigmoidGainTable> kappa_;
  std::map<std::pair<std::string, std::array<int, 2>>, WeightingTables> tables_;
  std::map<std::pair<int, int>, std::map<size_t, ObjectVisibility>> visibility_;  // by (SDF, density)
  std::map<SceneSetting, SettingMeasure> measured_;
  std::map<int, SgLighting> fits_;
  std::map<int, Scene> refined_;  // by subdivision level > 0
  double cloth_pixels_ = 0.0;                                   // of view 0's reference
  std::vector<SettingMeasure> tried_;
  gpu::EglContext ctx_;
  gpu::OffscreenTarget target_;

  // The modelled frame cost of view 0 at the kiosk's resolution (measure/frame_work.h): the cloth's
  // vertices and their fabrics' tangent samples, the reference's cloth pixels scaled to 640×480.
  double work(const SceneSetting& s, const ShadingData& d, int sg_count) {
    double vertices = 0.0, vertex_samples = 0.0;
    for (const auto& o : scene(s.density).cloth_objects()) {
      const auto& t = d.tables.at(o.fabric).tangent_samples;
      const double n = double(o.mesh.positions.size());
      vertices += n;
      vertex_samples += n * double(t[0] + t[1]);
    }
    if (vertices == 0.0) return 0.0;
    const double pixels = kiosk_cloth_pixels(cloth_pixels_, o_.views.width, o_.views.height);
    return per_vertex(knobs_.methods[s.method]) ? per_vertex_work(pixels, sg_count, vertex_samples)
                                                : per_pixel_work(pixels, sg_count, vertex_samples, vertices);
  }

  // Tables of one fabric at a tangent-sample pair (knob indices), at the richest levels and SVD error.
  const WeightingTables& tables(const std::string& fabric, std::array<int, 2> samples) {
    const Fabric& f = fabrics_.at(fabric);
    std::array<int, 2> n{};
    for (int j = 0; j < 2; ++j) n[j] = straight(f, j) ? 1 : knobs_.tangent_samples[samples[j]];
    const auto key = std::make_pair(fabric, n);
    if (auto it = tables_.find(key); it != tables_.end()) return it->second;
    BakeSettings b;
    b.tangent_samples = n;
    b.lambda_levels = knobs_.baked_levels;
    b.lambda_min = knobs_.baked_lambda_min;
    b.svd_error = *std::min_element(knobs_.svd_errors.begin(), knobs_.svd_errors.end());
    if (o_.grid > 0) b.xi_resolution = b.wo_resolution = b.wi_resolution = o_.grid;
    const auto t0 = std::chrono::steady_clock::now();
    WeightingTables t = bake_weighting_tables(f, b);
    say("tables " + fabric + " " + std::to_string(n[0]) + "+" + std::to_string(n[1]) + " samples baked (" +
        number(std::round(since(t0) * 10) / 10) + " s)");
    return tables_.emplace(key, std::move(t)).first->second;
  }

  // Every occluded object's visibility at an SDF resolution and a mesh density (knob indices), at
  // the richest PCA error. Refinement leaves floors and occluders as they are: theirs is the
  // unrefined scene's.
  const std::map<size_t, ObjectVisibility>& visibility(int sdf, int density) {
    const auto key = std::make_pair(sdf, density);
    if (auto it = visibility_.find(key); it != visibility_.end()) return it->second;
    const int levels = knobs_.subdivisions[density];
    const auto level0 = std::find(knobs_.subdivisions.begin(), knobs_.subdivisions.end(), 0);
    const bool reuse = levels != 0 && level0 != knobs_.subdivisions.end();
    std::map<size_t, ObjectVisibility> out;
    if (reuse)
      for (const auto& [i, v] : visibility(sdf, int(level0 - knobs_.subdivisions.begin())))
        if (!scene_.objects[i].is_cloth()) out.emplace(i, v);
    const Scene& drawn = scene(density);
    const auto t0 = std::chrono::steady_clock::now();
    size_t baked = 0;
    for (size_t i = 0; i < drawn.objects.size(); ++i) {
      const bool cloth = drawn.objects[i].is_cloth();
      if (reuse && !cloth) continue;
      SceneVisibilityOptions vo = o_.visibility;
      vo.resolution = knobs_.sdf_resolutions[sdf];
      vo.pca.target_rms_error = *std::min_element(knobs_.pca_errors.begin(), knobs_.pca_errors.end());
      if (!cloth) vo.resolution = std::min(vo.resolution, vo.lambertian_resolution);
      ++baked;
      if (auto v = bake_object_visibility(drawn, i, vo)) out.emplace(i, std::move(*v));
    }
    say("visibility at SDF " + std::to_string(knobs_.sdf_resolutions[sdf]) +
        (levels ? ", subdivision " + std::to_string(levels) : std::string()) + " baked for " +
        std::to_string(baked) + " object(s) (" + number(std::round(since(t0) * 10) / 10) + " s)");
    return visibility_.emplace(key, std::move(out)).first->second;
  }
};

// The cheaper of two settings, of either method: the modelled frame cost, then bytes.
bool cheaper(const SettingMeasure& a, const SettingMeasure& b) {
  if (a.work != b.work) return a.work < b.work;
  return a.bytes < b.bytes;
}

// One method's search from the paper's setting: up while the error is above the target (the
// step that lowers it most per byte added), then down while it holds (the step to the cheapest
// setting: frame cost, then bytes). Returns its end point; above the target when the method
// cannot reach it.
SettingMeasure search_method(Search& search, int method, double& target, double paper_margin) {
  SceneSetting s = search.paper(method);
  SettingMeasure cur = search.measure(s);
  if (paper_margin >= 0.0) target = cur.error + paper_margin;
  while (cur.error > target) {
    std::optional<SettingMeasure> best;
    double best_gain = 0.0;
    for (int k = 0; k < Search::kKnobs; ++k) {
      SceneSetting n = s;
      if (++Search::knob(n, k) >= search.knob_count(k, method)) continue;
      const SettingMeasure m = search.measure(n);
      const double drop = cur.error - m.error;
      if (drop <= 0.0) continue;
      const double gain = drop / std::max(double(m.bytes) - double(cur.bytes), 1024.0);
      if (gain > best_gain) best_gain = gain, best = m;
    }
    if (!best) break;  // no knob lowers the error any more: the method's floor
    s = best->setting;
    cur = *best;
  }
  if (cur.error > target) {
    for (const SettingMeasure& m : search.tried())
      if (m.setting.method == method && m.error < cur.error) cur = m;
    return cur;
  }
  while (true) {
    std::optional<SettingMeasure> best;
    for (int k = 0; k < Search::kKnobs; ++k) {
      SceneSetting n = s;
      if (--Search::knob(n, k) < 0) continue;
      const SettingMeasure m = search.measure(n);
      if (m.error > target || cheaper(cur, m)) continue;
      if (!best || cheaper(m, *best) || (!cheaper(*best, m) && m.error < best->error)) best = m;
    }
    if (!best) break;
    s = best->setting;
    cur = *best;
  }
  return cur;
}

}  // namespace

std::string describe(const SceneSetting& s, const SelectionKnobs& k, bool visibility) {
  std::string d = k.methods[s.method] + ", " + std::to_string(k.tangent_samples[s.samples[0]]) + "+" +
                  std::to_string(k.tangent_samples[s.samples[1]]) + " samples per curved thread, " +
                  std::to_string((k.baked_levels - 1) / k.level_strides[s.levels] + 1) + " levels, SVD " + number(k.svd_errors[s.svd]);
  if (visibility)
    d += ", SDF " + std::to_string(k.sdf_resolutions[s.sdf]) + ", PCA " + number(k.pca_errors[s.pca]) + " rad";
  if (per_vertex(k.methods[s.method]) && (k.subdivisions.size() > 1 || k.subdivisions[s.density] != 0))
    d += ", subdivision " + std::to_string(k.subdivisions[s.density]);
  if (!k.sg_counts.empty()) d += ", " + std::to_string(k.sg_counts[s.sgs]) + " SGs";
  return d;
}

SceneSelection select_scene_settings(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                     const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                                     const SceneSelectionOptions& o) {
  if (!(o.target_error > 0.0) && !(o.paper_margin >= 0.0)) throw std::invalid_argument("target error must be > 0");
  if (!o.knobs.sg_counts.empty() && !o.fit) throw std::invalid_argument("SG counts to search need a fit");
  if (o.knobs.subdivisions.empty()) throw std::invalid_argument("no mesh subdivision level to search");
  for (int l : o.knobs.subdivisions)
    if (l < 0 || l > kMaxSubdivision)
      throw std::invalid_argument("subdivision level " + std::to_string(l) + " outside 0.." + std::to_string(kMaxSubdivision));
  for (int k : o.knobs.sg_counts)
    if (k < 1 || k > gpu::kMaxSgs)
      throw std::invalid_argument("SG count " + std::to_string(k) + " outside 1.." + std::to_string(gpu::kMaxSgs));
  const auto t0 = std::chrono::steady_clock::now();
  SceneSelection out;
  const ViewReferences refs = view_references(scene, fabrics, fabric_texts, sgs, o.views, o.cache, o.log);
  out.references_rendered = refs.rendered, out.references_cached = refs.cached;
  Search search(scene, fabrics, sgs, refs, o);
  std::optional<SettingMeasure> chosen;
  double target = o.target_error;
  for (int m = 0; m < int(o.knobs.methods.size()); ++m) {
    double method_target = o.target_error;
    const SettingMeasure end = search_method(search, m, method_target, o.paper_margin);
    if (!chosen) target = method_target;
    if (end.error <= method_target && (!chosen || cheaper(end, *chosen))) {
      chosen = end;
      target = method_target;
    }
  }
  out.target = target;
  out.reached = chosen.has_value();
  if (!chosen) {
    // Below what the method can reach: the least error measured, the cheaper on a tie.
    for (const SettingMeasure& m : search.tried())
      if (!chosen || m.error < chosen->error || (m.error == chosen->error && cheaper(m, *chosen))) chosen = m;
  }
  out.chosen = *chosen;
  out.method = o.knobs.methods[chosen->setting.method];
  out.description = describe(chosen->setting, o.knobs, search.occluded());
  out.data = search.data(chosen->setting);
  out.sgs = search.lighting(chosen->setting.sgs);
  out.subdivision = chosen->subdivision;
  for (const SettingMeasure& m : search.tried())
    if (m.setting == search.paper(chosen->setting.method)) out.paper = m;
  out.tried = search.tried();
  out.seconds = since(t0);
  return out;
}

}  // namespace weft
