#include "measure/selection_views.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

#include "measure/image_metrics.h"
#include "reference/scene_render.h"

namespace weft {

namespace {

// The scene as the reference sees it: camera, objects, meshes, fabric texts.
void add_scene(InputHash& h, const Scene& s, const std::map<std::string, std::string>& fabric_texts) {
  h.add(s.name);
  for (const auto& o : s.objects) {
    h.add(o.name).add(o.fabric).add_number(o.is_cloth() ? 1 : 0);
    h.add_number(o.albedo.r).add_number(o.albedo.g).add_number(o.albedo.b);
    if (o.colour) h.add("colour").add_number(o.colour->r).add_number(o.colour->g).add_number(o.colour->b);  // only a coloured object's: other keys stay
    bench::add_mesh(h, o.mesh);
    if (o.is_cloth()) {
      const auto text = fabric_texts.find(o.fabric);
      h.add(text != fabric_texts.end() ? text->second : o.fabric);
    }
  }
}

void add_camera(InputHash& h, const Camera& c) {
  for (const glm::dvec3& v : {c.position, c.target, c.up}) h.add_number(v.x).add_number(v.y).add_number(v.z);
  h.add_number(c.fov_deg);
}

}  // namespace

std::filesystem::path default_reference_cache() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "weft/bake-references";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache/weft/bake-references";
  return std::filesystem::temp_directory_path() / "weft-bake-references";
}

std::vector<Camera> selection_views(const Camera& camera, const SelectionViewOptions& o) {
  std::vector<Camera> views{camera};
  const glm::dvec3 up = glm::normalize(camera.up);
  for (int i = 1; i < o.count; ++i) {
    const double turn = glm::radians(o.spread_deg) * double((i + 1) / 2) * (i % 2 ? 1.0 : -1.0);
    const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), turn, up);
    Camera c = camera;
    c.position = camera.target + glm::dvec3(r * glm::dvec4(camera.position - camera.target, 0.0));
    views.push_back(c);
  }
  return views;
}

ViewReferences view_references(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                               const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                               const SelectionViewOptions& o, const std::filesystem::path& cache,
                               const std::function<void(const std::string&)>& log) {
  ViewReferences out;
  out.cameras = selection_views(scene.camera, o);
  Scene view = scene;
  for (size_t i = 0; i < out.cameras.size(); ++i) {
    InputHash h;
    h.add(bench::kReferenceCodeVersion).add("selection view");
    add_scene(h, scene, fabric_texts);
    add_camera(h, out.cameras[i]);
    for (const auto& g : sgs) {
      h.add_number(g.axis.x).add_number(g.axis.y).add_number(g.axis.z).add_number(g.sharpness);
      h.add_number(g.amplitude.r).add_number(g.amplitude.g).add_number(g.amplitude.b);
    }
    h.add_number(o.width).add_number(o.height).add_number(o.sg_grid).add_number(o.tangent_samples);
    const auto file = cache / (scene.name + "_view" + std::to_string(i) + "_" + h.hex() + ".ref");
    if (auto ref = bench::load_reference(file)) {
      ++out.cached;
      if (log) log("reference view " + std::to_string(i) + ": cached " + file.string());
      out.images.push_back(std::move(*ref));
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    view.camera = out.cameras[i];
    ReferenceLighting lighting;
    lighting.sgs = sgs;
    lighting.background = [&sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
    ReferenceRenderOptions ro;
    ro.width = o.width, ro.height = o.height, ro.sg_grid = o.sg_grid, ro.tangent_samples = o.tangent_samples;
    ro.check_convergence = false;
    if (o.progress) ro.progress = o.progress("reference view " + std::to_string(i));
    const ReferenceRenderResult r = ReferenceRenderer(view, fabrics, lighting, ro).render(0);
    bench::CachedReference ref{r.image, r.kinds};
    bench::store_reference(file, ref);
    ++out.rendered;
    char buf[64];
    std::snprintf(buf, sizeof buf, " (%.1f s)", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (log) log("reference view " + std::to_string(i) + ": rendered " + file.string() + buf);
    out.images.push_back(std::move(ref));
  }
  return out;
}

std::vector<double> view_errors(gpu::SceneRenderer& renderer, const ViewReferences& refs, int width, int height) {
  std::vector<double> errors;
  for (size_t v = 0; v < refs.cameras.size(); ++v) {
    renderer.draw(refs.cameras[v], width, height);
    const Image img = gpu::read_linear_image(width, height);
    errors.push_back(bench::cloth_error(img, refs.images[v].image, refs.images[v].kinds).relative_rmse);
  }
  return errors;
}

}  // namespace weft
