#pragma once
// "No more model than the scene needs", for which of the weighting-table rungs the kiosk draws: the SDF's
// linearised visibility or the masks' exact per-vertex share V_k for the sharper SGs. Neither wins
// everywhere (docs/bench/low_sun/narrow_by_mask/): the masks' V_k is exact at the vertices where the
// SDF's one linear boundary fails (thin occluders such as a teapot's spout, crevices, folds that
// occlude from many sides), the SDF places a sharp lobe's shadow edge inside a triangle. So the
// bake measures both on the scene's own views (measure/selection_views.h, the `--target-error`
// search's references, cached on disk) under the bundle's SGs and records the closer one for
// `weft run --method auto` (the bundle's `bake/selection` section, BUNDLE_FORMAT.md).
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "measure/selection_views.h"
#include "core/spherical_gaussian.h"
#include "runtime/shading_data.h"
#include "scene/scene.h"

namespace weft {

// The pairs measured: each rung that shades the sharper SGs with the SDF, then its twin with the
// masks' V_k. The per-vertex pair is the kiosk's (its default, iwasaki_vertex_quadrature).
inline const std::vector<std::string> kVertexRungCandidates{"iwasaki_vertex_quadrature", "iwasaki_vertex_mask_quadrature"};

struct RungMeasure {
  std::string method;
  double error = 0.0;               // the worst view's relative RMSE over the cloth pixels
  std::vector<double> view_errors;  // per view
};

struct RungChoice {
  std::string method;                // the candidate with the least worst-view error
  std::vector<RungMeasure> measured; // every candidate, in the order given
  int views = 0, references_rendered = 0, references_cached = 0;
  int width = 0, height = 0;
  double seconds = 0.0;
};

// Needs a headless GLES context (EGL; llvmpipe will do) and `data` with the tables, visibility
// and masks every candidate reads (throws GpuError from the renderer otherwise). `fabric_texts`
// (preset → fabric file text, as the bundle stores them) give the cloth's fabrics and key the
// reference cache. Throws std::invalid_argument without candidates or cloth.
RungChoice choose_rung(const Scene& scene, const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                       std::shared_ptr<const ShadingData> data, const std::vector<std::string>& candidates,
                       const SelectionViewOptions& views, const std::filesystem::path& cache,
                       const std::function<void(const std::string&)>& log = {});

// The `bake/selection` section's JSON for a choice (BUNDLE_FORMAT.md): {"method", "chosen_by":
// "views", "width", "height", "views", "candidates": [{"method", "error", "view_errors"}]}.
std::string rung_choice_json(const RungChoice& c);

}  // namespace weft
