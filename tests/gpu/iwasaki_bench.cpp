// Benchmark (label bench, not run in CI): iwasaki on the GPU against the reference.
//  - accuracy: relative RMSE sqrt(mean((x−r)²))/mean(r) over the cloth pixels (docs/design.md §6) of
//    `weft render --method iwasaki` (in-process: same SG fit, GPU frame read back) against
//    `weft render --method reference --lighting sg` at 320×240, same 10 SGs fitted to the map.
//    References are slow (minutes): they are cached as EXR under $WEFT_BENCH_REFS (default
//    ./iwasaki_bench_refs) and rendered with the weft binary when missing. WEFT_BENCH_CASES
//    (e.g. "pillow:linen_plain:studio,drape:polyester_satin_charmeuse:city") picks the cases.
//  - speed: median ms/frame at 640×480 over ≥ 20 frames after warm-up, glFinish included, for
//    pillow/linen_plain/10 SGs, with and without visibility, iwasaki_vertex and sgpoint beside it (one run, so
//    the ratio holds on any machine); boot to first frame from a bundle (`weft run`).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include "frame/frame_render.h"
#include "runtime/shading_data.h"
#include "bundle/bundle_reader.h"
#include "core/fabric.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "reference/ray_scene.h"
#include "scene/scene_file.h"

using namespace weft;
namespace fs = std::filesystem;

namespace {

struct Case {
  std::string scene, fabric, env;
};

std::vector<Case> cases() {
  const char* env = std::getenv("WEFT_BENCH_CASES");
  std::string list = env ? env : "pillow:linen_plain:studio,pillow:linen_plain:courtyard";
  std::vector<Case> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    Case c;
    std::stringstream is(item);
    std::getline(is, c.scene, ':');
    std::getline(is, c.fabric, ':');
    std::getline(is, c.env, ':');
    out.push_back(c);
  }
  return out;
}

Scene scene_with(const Case& c) {
  Scene s = load_scene_preset(c.scene, WEFT_SOURCE_ASSETS "/scenes");
  for (auto& o : s.objects)
    if (o.material == Material::cloth) o.fabric = c.fabric;
  return s;
}

fs::path refs_dir() {
  const fs::path d = std::getenv("WEFT_BENCH_REFS") ? std::getenv("WEFT_BENCH_REFS") : "iwasaki_bench_refs";
  fs::create_directories(d);
  return d;
}

// The case's bundle (`weft bake`, paper settings), cached beside the references.
fs::path bundle_for(const Case& c) {
  const fs::path b = refs_dir() / (c.scene + "_" + c.fabric + ".weft");
  if (!fs::exists(b)) {
    const std::string cmd = std::string(WEFT_BINARY) + " bake --scene " + c.scene + " --fabric " + c.fabric + " --out " +
                            b.string() + " 2> " + b.string() + ".log";
    std::printf("baking: %s\n", cmd.c_str());
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("bake failed: " + cmd);
  }
  return b;
}

std::shared_ptr<ShadingData> tables(const Case& c, const Scene& scene, bool visibility) {
  const auto reader = bundle::BundleReader::open(bundle_for(c));
  std::map<size_t, size_t> vertices;
  for (size_t i = 0; i < scene.objects.size(); ++i) vertices[i] = scene.objects[i].mesh.positions.size();
  auto d = std::make_shared<ShadingData>(read_shading_data(reader, vertices));
  if (!visibility) d->visibility.clear();
  return d;
}

TEST(IwasakiBench, AccuracyAgainstReference) {
  const fs::path refs = refs_dir();
  for (const Case& c : cases()) {
    const Scene scene = scene_with(c);
    std::map<std::string, Fabric> fabrics;
    for (const auto& o : scene.objects)
      if (o.material == Material::cloth) fabrics.emplace(o.fabric, load_fabric_preset(o.fabric, WEFT_SOURCE_ASSETS "/fabrics"));
    const int w = 320, h = 240;
    const fs::path ref = refs / (c.scene + "_" + c.fabric + "_" + c.env + ".exr");
    if (!fs::exists(ref)) {
      const std::string cmd = std::string(WEFT_BINARY) + " render --method reference --lighting sg --scene " + c.scene +
                              " --fabric " + c.fabric + " --map " + c.env + " --width 320 --height 240 --no-convergence-check --out " +
                              ref.string() + " > /dev/null";
      std::printf("rendering the reference: %s\n", cmd.c_str());
      ASSERT_EQ(std::system(cmd.c_str()), 0);
    }
    const EnvMap r = load_env_map(ref);
    ASSERT_EQ(r.width, w);
    const EnvMap map = load_env_map(fs::path(WEFT_SOURCE_ASSETS) / "envmaps" / (c.env + ".exr"), NonFinitePolicy::clamp);
    const SgLighting sgs = fit_sgs(map, SgFitOptions{});  // as `weft render` fits them
    const RayScene rays(scene);
    std::vector<bool> cloth(size_t(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const auto hit = rays.intersect(scene.camera.position, camera_ray(scene.camera, w, h, x + 0.5, y + 0.5));
        cloth[size_t(y) * w + x] = hit && scene.objects[hit->object].material == Material::cloth;
      }
    for (bool visibility : {true, false}) {
      const auto data = tables(c, scene, visibility);
      const GpuFrame f = render_gpu_frame(scene, fabrics, sgs, "iwasaki", w, h, 0, data);
      double se = 0, sum = 0, sum_x = 0;
      size_t n = 0, non_finite = 0;
      Image ratio(w, h);  // x/r per cloth pixel
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          if (!cloth[size_t(y) * w + x]) continue;
          const glm::dvec3 a = f.image.at(x, y), b = glm::dvec3(r.at(x, y));
          if (!std::isfinite(a.r + a.g + a.b)) {  // counted and reported, not averaged
            ++non_finite;
            continue;
          }
          const glm::dvec3 e = a - b;
          se += glm::dot(e, e) / 3;
          sum += (b.r + b.g + b.b) / 3;
          sum_x += (a.r + a.g + a.b) / 3;
          ratio.at(x, y) = glm::dvec3((a.r + a.g + a.b) / std::max(1e-9, b.r + b.g + b.b));
          ++n;
        }
      const double rmse = std::sqrt(se / n) / (sum / n);
      std::printf("accuracy %s/%s/%s %s: relative RMSE %.4f over %zu cloth pixels, mean(iwasaki)/mean(reference) %.3f, "
                  "%zu non-finite pixels\n",
                  c.scene.c_str(), c.fabric.c_str(), c.env.c_str(), visibility ? "with visibility" : "no visibility", rmse, n,
                  sum_x / sum, non_finite);
      EXPECT_EQ(non_finite, 0u);
      // Red: too bright, blue: too dark, black: equal.
      for (auto& px : ratio.pixels) px = glm::dvec3(std::max(0.0, px.r - 1), 0.0, std::max(0.0, 1 - px.r) * (px.r > 0));
      write_png(ratio, refs / (c.scene + "_" + c.fabric + "_" + c.env + (visibility ? "_ratio.png" : "_ratio_novis.png")), 3.0);
      write_exr(f.image, refs / (c.scene + "_" + c.fabric + "_" + c.env + (visibility ? "_iwasaki.exr" : "_iwasaki_novis.exr")));
      EXPECT_GT(n, 100u);
    }
  }
}

TEST(IwasakiBench, SpeedPillowLinen) {
  const Case c{"pillow", "linen_plain", "studio"};
  const Scene scene = scene_with(c);
  std::map<std::string, Fabric> fabrics{{c.fabric, load_fabric_preset(c.fabric, WEFT_SOURCE_ASSETS "/fabrics")}};
  const SgLighting sgs =
      fit_sgs(load_env_map(fs::path(WEFT_SOURCE_ASSETS) / "envmaps/studio.exr", NonFinitePolicy::clamp), SgFitOptions{});
  const int frames = std::getenv("WEFT_BENCH_FRAMES") ? std::atoi(std::getenv("WEFT_BENCH_FRAMES")) : 20;
  const auto vis = tables(c, scene, true), novis = tables(c, scene, false);
  for (int size : {std::getenv("WEFT_BENCH_WIDTH") ? std::atoi(std::getenv("WEFT_BENCH_WIDTH")) : 640}) {
    const int w = size, h = size * 3 / 4;
    const GpuFrame sp = render_gpu_frame(scene, fabrics, sgs, "sgpoint", w, h, frames);
    const GpuFrame a = render_gpu_frame(scene, fabrics, sgs, "iwasaki", w, h, frames, vis);
    const GpuFrame b = render_gpu_frame(scene, fabrics, sgs, "iwasaki", w, h, frames, novis);
    const GpuFrame v = render_gpu_frame(scene, fabrics, sgs, "iwasaki_vertex", w, h, frames, vis);
    std::printf("speed %dx%d on %s, %d frames: iwasaki %.1f ms/frame, iwasaki without visibility %.1f ms/frame, "
                "iwasaki_vertex %.1f ms/frame, sgpoint (16 samples/thread) %.1f ms/frame\n",
                w, h, a.renderer.c_str(), frames, a.median_ms, b.median_ms, v.median_ms, sp.median_ms);
  }
  // Boot to first frame: `weft run` from the bundle, headless 640×480.
  const fs::path state = refs_dir() / "run_state";
  const std::string cmd = std::string(WEFT_BINARY) + " run --bundle " + bundle_for(c).string() + " --state-dir " +
                          state.string() + " --display headless --panel none --frames 1 --width 640 --height 480 2>&1 | grep 'first frame'";
  std::printf("boot: ");
  std::fflush(stdout);
  EXPECT_EQ(std::system(cmd.c_str()), 0);
}

}  // namespace
