#include "reference/scene_render.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>

#include <omp.h>

#include "core/normal_map_frame.h"
#include "methods/thin/thin.h"
#include "reference/sg_quadrature.h"
#include "reference/thin_quadrature.h"
#include "scene/weave_scale.h"

namespace weft {

namespace {
using glm::dvec3;
double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

ReferenceRenderer::ReferenceRenderer(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                     ReferenceLighting lighting, const ReferenceRenderOptions& options)
    : scene_(scene), rays_(scene), lighting_(std::move(lighting)), options_(options) {
  if (options_.width < 1 || options_.height < 1 || options_.width > 16384 || options_.height > 16384)
    throw std::invalid_argument("image size must be within 1..16384 pixels per side");
  if (options_.sg_grid < 1) throw std::invalid_argument("sg_grid must be ≥ 1");
  if (lighting_.sgs.empty() && !lighting_.samples) throw std::invalid_argument("reference: no lighting given");
  if (options_.tangent_samples < 1) throw std::invalid_argument("tangent_samples must be ≥ 1");
  if (options_.supersample < 1 || options_.supersample > 16) throw std::invalid_argument("supersample must be within 1..16");
  if (options_.resolved_weave && options_.thin_cloth)
    throw std::invalid_argument("reference: the resolved weave is for opaque cloth, not the thin layer");
  for (const auto& obj : scene.objects) {
    std::optional<Fabric> fabric;
    if (obj.material == Material::cloth) {
      auto it = fabrics.find(obj.fabric);
      if (it == fabrics.end()) throw std::invalid_argument("reference: no fabric '" + obj.fabric + "' loaded");
      fabric = object_base_fabric(obj, it->second);
    }
    weaves_.emplace_back();
    // Cloth without UVs has no place for its threads: the fabric level, as the weave layer leaves it.
    if (fabric && options_.resolved_weave && !obj.mesh.uvs.empty()) {
      const Fabric f = object_fabric(obj, *fabric);
      weaves_.back() = Weave{WeaveLayout(f), weave_coordinates(obj, f)};
    }
    for (int level = 0; level < kLevels; ++level)
      bsdfs_[level].push_back(fabric ? std::make_unique<ClothBsdf>(object_fabric(obj, *fabric), options_.tangent_samples << level)
                                     : nullptr);
  }
}

const std::vector<DirectionalSample>& ReferenceRenderer::samples_at(int level) const {
  auto it = samples_.find(level);
  if (it == samples_.end()) it = samples_.emplace(level, lighting_.samples(level)).first;
  return it->second;
}

dvec3 ReferenceRenderer::shade(const RayHit& hit, const dvec3& wo, int level) const {
  SurfacePoint s = rays_.surface(hit);
  // Two-sided: shade the side the viewer is on.
  if (glm::dot(s.geometric_normal, wo) < 0.0) {
    s.geometric_normal = -s.geometric_normal;
    s.normal = -s.normal;
  }
  const dvec3 ng = s.geometric_normal;
  const dvec3 origin = s.position + ng * rays_.ray_epsilon();
  // Directions below the geometric surface are blocked by the surface itself.
  auto visible = [&](const dvec3& wi) {
    return glm::dot(wi, ng) > 0.0 && (!options_.occlusion || rays_.unoccluded(origin, wi));
  };

  if (level < 0 || level >= kLevels) throw std::invalid_argument("reference: level out of range");
  const SceneObject& obj = scene_.objects[hit.object];
  const ClothBsdf* bsdf = bsdfs_[level][hit.object].get();
  SurfaceFrame frame;
  if (bsdf) frame = SurfaceFrame::from_normal_warp(s.normal, s.warp);
  // A normal map turns the frame at this point, as the per-pixel GPU rungs do (on the side facing
  // the viewer); the geometric surface still blocks what lies below it.
  if (bsdf && obj.normal_map) frame = normal_mapped_frame(frame, normal_map_tangent(obj, s.uv));
  // The resolved weave: the thread sample at this point of the repeat; a gap reflects nothing.
  int thread = -1;
  double tilt = 0.0;
  const auto& weave = weaves_[hit.object];
  const auto* corners = weave ? &obj.mesh.triangles[hit.triangle] : nullptr;
  if (bsdf && weave && !weave_degenerate_uvs(weave->st[(*corners)[0]], weave->st[(*corners)[1]], weave->st[(*corners)[2]])) {
    const auto& t = *corners;
    const glm::dvec2 st = (1.0 - hit.b1 - hit.b2) * weave->st[t[0]] + hit.b1 * weave->st[t[1]] + hit.b2 * weave->st[t[2]];
    const WeaveSample w = weave->layout.at(st.x, st.y);
    if (w.thread < 0) return dvec3(0.0);
    thread = w.thread;
    tilt = weave_tilt(bsdf->fabric(), w);
  }

  // A textured cloth: each thread's albedo times its map's texel here (sample_texture, bilinear at
  // the finest level; the supersampled pixel averages it as the GPU's mip levels do).
  const std::array<dvec3, 2> tint = {thread_tint(obj, 0, s.uv), thread_tint(obj, 1, s.uv)};
  if (!lighting_.sgs.empty()) {
    SgQuadratureOptions opt;
    opt.fixed_polar = options_.sg_grid << level;
    opt.parallel = false;
    opt.visible = visible;
    if (bsdf && thread >= 0) return integrate_sg_resolved(*bsdf, frame, thread, tilt, wo, lighting_.sgs, opt).radiance;
    if (bsdf) return integrate_sg_lighting(*bsdf, frame, wo, lighting_.sgs, tint, opt).radiance;
    return integrate_sg_lambertian(s.normal, obj.albedo, lighting_.sgs, opt).radiance;
  }
  // Directional samples: Σ_k power_k · V · f(ω_k).
  const auto& samples = samples_at(level);
  dvec3 sum(0.0);
  if (bsdf) {
    if (glm::dot(frame.n, wo) <= 0.0) return sum;
    ClothBsdf::Point point = bsdf->at(frame);
    for (const auto& d : samples)
      if (glm::dot(d.direction, frame.n) > 0.0 && visible(d.direction))
        sum += d.power * (thread >= 0 ? point.resolved_integrand(thread, tilt, d.direction, wo) : point.integrand(d.direction, wo, tint));
  } else {
    const dvec3 brdf = obj.albedo / std::numbers::pi;
    for (const auto& d : samples) {
      const double c = glm::dot(d.direction, s.normal);
      if (c > 0.0 && visible(d.direction)) sum += d.power * brdf * c;
    }
  }
  return sum;
}

std::optional<RayHit> ReferenceRenderer::primary_hit(int x, int y, dvec3& dir) const {
  return primary_hit_at(x + 0.5, y + 0.5, dir);
}

std::optional<RayHit> ReferenceRenderer::primary_hit_at(double px, double py, dvec3& dir) const {
  dir = camera_ray(scene_.camera, options_.width, options_.height, px, py);
  return rays_.intersect(scene_.camera.position, dir);
}

PixelKind ReferenceRenderer::kind_of(const std::optional<RayHit>& hit) const {
  if (!hit) return PixelKind::background;
  return scene_.objects[hit->object].material == Material::cloth ? PixelKind::cloth : PixelKind::lambertian;
}

PixelKind ReferenceRenderer::kind(int x, int y) const {
  dvec3 dir;
  return kind_of(primary_hit(x, y, dir));
}

dvec3 ReferenceRenderer::pixel(int x, int y, int level, PixelKind* kind) const {
  const int n = options_.supersample;
  if (n == 1) return trace(x + 0.5, y + 0.5, level, kind);
  if (kind) *kind = this->kind(x, y);
  dvec3 sum(0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) sum += trace(x + (i + 0.5) / n, y + (j + 0.5) / n, level, nullptr);
  return sum / double(n * n);
}

dvec3 ReferenceRenderer::trace(double px, double py, int level, PixelKind* kind) const {
  dvec3 dir;
  const auto hit = primary_hit_at(px, py, dir);
  const PixelKind k = kind_of(hit);
  if (kind) *kind = k;
  if (!hit) return lighting_.background ? lighting_.background(dir) : dvec3(0.0);
  if (k == PixelKind::cloth && options_.thin_cloth) return shade_thin(*hit, dir, level, 0);
  return shade(*hit, -dir, level);
}

dvec3 ReferenceRenderer::shade_thin(const RayHit& hit, const dvec3& dir, int level, int depth) const {
  if (lighting_.sgs.empty()) throw std::invalid_argument("reference: thin cloth needs SG lighting");
  const dvec3 wo = -dir;
  SurfacePoint s = rays_.surface(hit);
  if (glm::dot(s.normal, wo) < 0.0) s.normal = -s.normal;  // the side facing the viewer, as the GPU does
  const dvec3 ng = glm::dot(s.geometric_normal, wo) < 0.0 ? -s.geometric_normal : s.geometric_normal;
  const double eps = rays_.ray_epsilon();
  const ThinParams p = thin_params(bsdfs_[level][hit.object]->fabric());
  const double alpha = thin_alpha(p, glm::dot(s.normal, wo));
  ThinQuadratureOptions opt;
  opt.fixed_polar = options_.sg_grid << level;
  // Light reaches the layer from either side; the layer itself does not block it.
  opt.visible = [&](const dvec3& wi) {
    return rays_.unoccluded(s.position + (glm::dot(wi, ng) > 0.0 ? eps : -eps) * ng, wi);
  };
  const dvec3 scatter = integrate_thin_scatter(p, s.normal, wo, lighting_.sgs, opt).radiance;
  dvec3 behind(0.0);
  const auto next = rays_.intersect(s.position - ng * eps, dir);
  if (!next) behind = lighting_.background ? lighting_.background(dir) : dvec3(0.0);
  else if (scene_.objects[next->object].material == Material::cloth)
    behind = depth < 4 ? shade_thin(*next, dir, level, depth + 1) : dvec3(0.0);
  else behind = shade(*next, wo, level);
  return (1.0 - alpha) * shade(hit, wo, level) + scatter + alpha * behind;
}

ReferenceRenderResult ReferenceRenderer::render(int level) const {
  const auto start = std::chrono::steady_clock::now();
  if (lighting_.sgs.empty()) samples_at(level);
  ReferenceRenderResult res;
  res.image = Image(options_.width, options_.height);
  res.kinds.assign(res.image.pixels.size(), PixelKind::background);
  std::atomic<int> rows_done{0};
  std::exception_ptr error;
  std::mutex error_mutex;
#pragma omp parallel for schedule(dynamic, 1)
  for (int y = 0; y < options_.height; ++y) {
    try {
      for (int x = 0; x < options_.width; ++x) {
        PixelKind k;
        res.image.at(x, y) = pixel(x, y, level, &k);
        res.kinds[static_cast<size_t>(y) * options_.width + x] = k;
      }
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
    }
    const int done = ++rows_done;
    if (options_.progress && omp_get_thread_num() == 0) options_.progress(double(done) / options_.height);
  }
  if (error) std::rethrow_exception(error);
  if (options_.progress) options_.progress(1.0);
  res.seconds = seconds_since(start);
  if (options_.check_convergence) res.convergence = convergence(res, level);
  return res;
}

double relative_change(std::span<const dvec3> coarse, std::span<const dvec3> fine) {
  if (coarse.size() != fine.size()) throw std::invalid_argument("relative_change: sizes differ");
  double se = 0, sum = 0;
  for (size_t i = 0; i < fine.size(); ++i) {
    const dvec3 d = coarse[i] - fine[i];
    se += glm::dot(d, d);
    sum += glm::length(fine[i]);
  }
  if (fine.empty() || !(sum > 0)) return 0.0;
  return std::sqrt(se / fine.size()) / (sum / fine.size());
}

std::vector<std::pair<int, int>> ReferenceRenderer::check_pixels() const {
  const int stride = std::max(1, options_.check_stride);
  std::vector<std::pair<int, int>> lattice;
  for (int y = stride / 2; y < options_.height; y += stride)
    for (int x = stride / 2; x < options_.width; x += stride) lattice.emplace_back(x, y);
  return lattice;
}

ConvergenceReport ReferenceRenderer::convergence(const ReferenceRenderResult& result, int level) const {
  const auto start = std::chrono::steady_clock::now();
  if (level + 1 >= kLevels) throw std::invalid_argument("reference: convergence level out of range");
  if (lighting_.sgs.empty()) samples_at(level + 1);
  struct Pair {
    int x, y;
    bool cloth;
  };
  std::vector<Pair> pixels;
  for (const auto& [x, y] : check_pixels()) {
    const PixelKind k = result.kinds[static_cast<size_t>(y) * options_.width + x];
    if (k != PixelKind::background) pixels.push_back({x, y, k == PixelKind::cloth});
  }
  std::vector<dvec3> fine(pixels.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t i = 0; i < pixels.size(); ++i) fine[i] = pixel(pixels[i].x, pixels[i].y, level + 1);

  ConvergenceReport r;
  r.level = level;
  r.pixels_checked = pixels.size();
  std::vector<dvec3> coarse(pixels.size()), coarse_cloth, fine_cloth;
  for (size_t i = 0; i < pixels.size(); ++i) {
    coarse[i] = result.image.at(pixels[i].x, pixels[i].y);
    if (pixels[i].cloth) coarse_cloth.push_back(coarse[i]), fine_cloth.push_back(fine[i]);
  }
  r.relative_rmse = relative_change(coarse, fine);
  r.cloth_relative_rmse = relative_change(coarse_cloth, fine_cloth);
  double sum = 0;
  for (const dvec3& f : fine) sum += glm::length(f);
  if (!pixels.empty() && sum > 0) {
    const double mean = sum / pixels.size();
    for (size_t i = 0; i < pixels.size(); ++i)
      r.max_pixel_change = std::max(r.max_pixel_change, glm::length(coarse[i] - fine[i]) / std::max(glm::length(fine[i]), mean));
  }
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace weft
