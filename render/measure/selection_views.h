#pragma once
// The views `weft bake --target-error` measures a setting on: the scene's own camera and
// cameras turned about its target around the up axis, rendered small. Their reference renders
// (render/reference, under the bundle's default SGs) are cached on disk under a hash of every
// input (scene geometry and camera, fabric texts, SGs, view and render settings,
// bench::kReferenceCodeVersion), so a rerun of the same bake reads them back.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "measure/reference_cache.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "gpu/scene_renderer.h"
#include "scene/scene.h"

namespace weft {

struct SelectionViewOptions {
  int count = 3;               // the scene camera, then ±spread, ±2·spread, ...
  double spread_deg = 20.0;    // turn between views about the camera target, around camera.up
  int width = 160, height = 120;
  int sg_grid = 8, tangent_samples = 16;  // the reference's quadrature, fixed (the bench's converges from 32)
  // A progress callback per reference rendered (given its label; none: silent), e.g. a bar.
  std::function<std::function<void(double)>(const std::string& label)> progress;
};

// $XDG_CACHE_HOME/weft/bake-references, else ~/.cache/weft/bake-references, else under /tmp.
std::filesystem::path default_reference_cache();

// The scene camera first, then the turned ones.
std::vector<Camera> selection_views(const Camera& camera, const SelectionViewOptions& options);

struct ViewReferences {
  std::vector<Camera> cameras;
  std::vector<bench::CachedReference> images;  // one per camera
  int rendered = 0, cached = 0;
};

// `fabric_texts`: preset → the fabric file text each cloth object's fabric was parsed from.
// `cache`: the folder of cached renders (created when missing). `log` gets one line per view.
ViewReferences view_references(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                               const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                               const SelectionViewOptions& options, const std::filesystem::path& cache,
                               const std::function<void(const std::string&)>& log = {});

// Each view's error: relative RMSE over the cloth pixels (measure/image_metrics.h) of `renderer`'s frame
// against the view's reference. Draws into the bound framebuffer, `refs`' size (a current GLES context).
std::vector<double> view_errors(gpu::SceneRenderer& renderer, const ViewReferences& refs, int width, int height);

}  // namespace weft
