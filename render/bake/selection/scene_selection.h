#pragma once
// "Model no more than the scene needs" (docs/design.md §4) for a whole scene: the setting of every
// cost knob of the weighting-table method (SG count of the map's fit, tangent samples per thread, λ
// levels, SVD error, SDF resolution, PCA error, the cloth mesh's density for per-vertex shading,
// per-vertex or per-pixel shading) is chosen so
// that the image error — relative RMSE over the cloth pixels (measure/image_metrics.h) of the GPU
// frame against the reference, the worst of the scene's views (measure/selection_views.h) — stays
// ≤ the target at the least cost: frame time first, then bundle bytes. Frame time is modelled,
// not timed (timings on a shared machine are noise at these differences): the shading work at
// the kiosk's 640×480, on one scale for per-pixel and per-vertex settings (measure/frame_work.h,
// calibrated on the bench's frame times), so a per-vertex setting whose refined cloth has more
// vertices to shade than the kiosk frame has cloth pixels loses to per-pixel shading; the
// measured ms is reported beside it. Every method is searched; the cheapest that holds the
// target is taken.
//
// Mesh density: the cloth meshes refined by midpoint subdivision (scene/mesh_subdivision.h),
// searched for per-vertex shading only (per-pixel shading interpolates only the visibility
// between vertices). A refined mesh is measured against the references of the scene as given
// (the same surface: refinement keeps it), its visibility baked on the refined vertices; its
// bytes add the mesh sections it adds to the bundle.
//
// The search measures, it does not model: from the paper's setting it steps up the knob whose
// next value lowers the error most per byte it adds while the target is missed, then steps
// down the knob that saves the most bytes while the target still holds, until none does (the
// error is not monotone in each knob at cheap settings, so the search starts where the paper
// calibrated the method). Tables are baked once per tangent-sample pair (at the
// richest λ levels and SVD error) and visibility once per SDF resolution (at the richest PCA
// error); the cheaper values of the other knobs are cut from those bakes
// (bake/selection/setting_truncation.h), so the bundle written is the one measured. When no setting of
// any method reaches the target, the setting with the least error is taken and `reached` is
// false.
#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bake/visibility/scene_visibility.h"
#include "measure/selection_views.h"
#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "runtime/shading_data.h"
#include "scene/scene.h"

namespace weft {

// The strides that cut `levels` baked λ levels exactly (both ends kept) to 3 levels or more,
// coarsest first: every divisor of the intervals, e.g. 15 levels → 7, 2, 1 (3, 8, 15 levels).
std::vector<int> level_strides_of(int levels);

// The finest mesh subdivision the search and `weft bake --subdivide` take (a level multiplies the
// cloth's vertices by ~4: level 3 puts the pillow at ~215 k).
inline constexpr int kMaxSubdivision = 3;

// The values each knob may take, cheapest first.
struct SelectionKnobs {
  std::vector<int> tangent_samples{1, 2, 3, 4, 6, 8, 12, 16};  // per thread (a straight thread keeps 1)
  int baked_levels = BakeSettings{}.lambda_levels;               // λ levels the tables are baked with,
  double baked_lambda_min = BakeSettings{}.lambda_min;           // log-spaced from this to BakeSettings' λ max
  std::vector<int> level_strides = level_strides_of(baked_levels);  // cuts of the baked levels
  std::vector<double> svd_errors{0.1, 0.05, 0.03, 0.02, 0.01};  // the richest is the paper's: its bake
  std::vector<int> sdf_resolutions{32, 64, 128};
  std::vector<double> pca_errors{0.08, 0.04, 0.02, 0.01};     // radians, RMS
  std::vector<std::string> methods{"iwasaki_vertex", "iwasaki"};  // each searched; the cheapest holding the target wins
  // Midpoint subdivision levels of the cloth meshes for a per-vertex method (each ×4 the
  // triangles); a per-pixel method takes the first.
  std::vector<int> subdivisions{0, 1, 2};
  // SG counts of the scene map's fit (SceneSelectionOptions::fit); empty: the SGs given only.
  // At most methods/sg_lighting_uniforms.h's kMaxSgs (40).
  std::vector<int> sg_counts;
};

struct SceneSelectionOptions {
  double target_error = 0.0;   // must be > 0 (unless paper_margin is set)
  // ≥ 0: the target is instead the paper setting's own measured error plus this margin, per
  // method (the cheapest setting as good as the paper's: how the default bake was derived).
  double paper_margin = -1.0;
  SelectionViewOptions views;
  std::filesystem::path cache;  // reference renders
  SelectionKnobs knobs;
  int grid = 0;                 // > 0: T tables' direction grids n×n instead of the paper's 48 (tests)
  SceneVisibilityOptions visibility;  // resolution and PCA target are the knobs'; the rest is kept
  int timed_frames = 3;         // frames timed per setting (view 0, after a warm-up)
  // SGs fitted to the scene's map for a count: needed when knobs.sg_counts is set. The views'
  // references are then still rendered under the SGs given to select_scene_settings, which
  // should be richer than any count searched (weft bake gives a 24-SG fit).
  std::function<SgLighting(int count)> fit;
  std::function<void(const std::string&)> log;  // progress lines
};

// One point of the search: an index into each knob's list.
struct SceneSetting {
  int method = 0;
  std::array<int, 2> samples{0, 0};
  int levels = 0, svd = 0, sdf = 0, pca = 0;
  int sgs = 0;  // index into knobs.sg_counts (0 when it is empty)
  int density = 0;  // index into knobs.subdivisions
  auto operator<=>(const SceneSetting&) const = default;
};

struct SettingMeasure {
  SceneSetting setting;
  double error = 0.0;               // the worst view's
  std::vector<double> view_errors;  // per view
  double ms = 0.0;                  // median frame time of view 0 at the views' size
  double work = 0.0;                // modelled frame cost of view 0 at 640×480 (measure/frame_work.h)
  int sg_count = 0;                 // SGs it was drawn with
  size_t bytes = 0;                 // tables + visibility (+ κ when there is visibility) + the mesh
                                    // sections refinement adds
  int subdivision = 0;              // levels the cloth meshes were refined
};

struct SceneSelection {
  SettingMeasure chosen;
  double target = 0.0;                 // the target held (target_error, or paper's error + margin)
  std::optional<SettingMeasure> paper; // the paper setting's measure (of the chosen method) when measured
  bool reached = false;
  std::string method;                  // the chosen setting's runtime method
  std::string description;             // the chosen setting in words
  std::vector<SettingMeasure> tried;   // in the order measured
  ShadingData data;              // the chosen setting's tables, visibility and κ
  SgLighting sgs;                      // the chosen setting's SGs (its fit when the SG count was searched)
  int subdivision = 0;                 // the chosen setting's refinement of the cloth meshes: its
                                       // `data` is for refine_and_order_meshes(scene, subdivision)
  int references_rendered = 0, references_cached = 0;
  double seconds = 0.0;
};

// Describes a setting ("iwasaki_vertex, 3+3 samples per curved thread, 5 levels, SVD 0.02, SDF 64, PCA 0.02 rad",
// then ", subdivision 1" for a per-vertex method when more than one level is searched or the
// level is not 0, then ", 8 SGs" when the SG count is searched).
std::string describe(const SceneSetting& s, const SelectionKnobs& knobs, bool visibility);

// `fabric_texts` (preset → fabric file text) key the reference cache. Needs a headless GLES
// context (EGL; llvmpipe will do). Throws std::invalid_argument for a target ≤ 0, or SG counts
// without a fit or outside 1..kMaxSgs.
SceneSelection select_scene_settings(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                     const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                                     const SceneSelectionOptions& options);

}  // namespace weft
