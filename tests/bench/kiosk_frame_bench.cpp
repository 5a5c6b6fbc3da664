// Benchmark (label bench, not run in CI but for its smoke case): the kiosk's frame on baked
// bundles, the way `weft run` draws it (kiosk renderer: showroom backdrop, weave layer armed), on
// a turntable at 6°/s sampled at 15 frames per second (0.4° a frame), 640×480 headless.
//  - per rung: the median frame and its stages (gl/frame_profile.h, CPU clock on llvmpipe), and
//    the mean CPU time a frame takes (all threads: on llvmpipe the GPU's work too);
//  - per rung with per-vertex passes: the same with the passes' temporal reuse over R frames
//    (gpu::SceneRenderer::set_vertex_refresh; "bR": the broad lobes' quadrature alone,
//    set_broad_lobe_refresh), and what reuse costs in accuracy: each frame
//    against a frame with every vertex recomputed at the same angle, relative RMSE over the
//    cloth pixels (mean and worst over the timed frames); with the passes for the visible
//    vertices only, every frame is held to that frame (culling must change nothing);
//  - the first frame (renderer made, lighting set, drawn) and a still scene's cost (nothing moved:
//    the kiosk draws nothing; here the cost of a frame with no pass work left is not measured).
// WEFT_KIOSK_BUNDLES: "name=FILE,name=FILE" (default: the showroom and the pillow, baked here with
// the showroom's coarse grids);
// WEFT_KIOSK_METHODS: rungs ("auto,iwasaki_vertex,sheen"); WEFT_KIOSK_REFRESH: shares ("1,4,8,16,b4,b8,b16");
// WEFT_KIOSK_VERTICES: "visible" (the default: the passes only for the vertices the frame shows,
// the cloth's depth first), "all" (every vertex, no depth pass: as before either), or "all,visible";
// WEFT_KIOSK_NO_ERROR: time only, no error columns;
// WEFT_KIOSK_SHOTS: a folder for each case's last frame and the same view with every vertex
// computed (EXR, linear, NaN kept), and a line per case counting the cloth pixels that are not
// finite or black in each (a driver's NaN shows as black cloth on screen);
// WEFT_KIOSK_PLAIN_REUSE: no clock for the renderer, so kept values are not extrapolated;
// WEFT_KIOSK_ZOOMS: zoom positions ("0,0.25,0.5,0.75,1"; default "0": the scene's view), each the
// camera dollied that far toward the kiosk's close-up as `weft run --zoom` places it;
// WEFT_KIOSK_WEAVE: the weave layer, a list of "on" (the default, as the kiosk arms it: up close
// over a per-vertex rung each float lit per pixel), "table" (the per-vertex table instead: the
// kiosk's choice where those frames exceed --weave-budget) and "off";
// WEFT_KIOSK_FRAMES: timed frames (24); WEFT_KIOSK_DEG_PER_FRAME: the turn a frame (0.4); WEFT_KIOSK_SIZE: "640x480"; WEFT_KIOSK_OUT: the table file.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <sys/resource.h>
#include <unistd.h>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bundle/bundle_reader.h"
#include "image/image.h"
#include "runtime/scene_bundle.h"
#include "gl/frame_profile.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk_bundle.h"
#include "kiosk/kiosk_renderer.h"
#include "kiosk/turntable.h"

using namespace weft;

namespace {
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}
std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

// Relative RMSE of `a` against `b` over the pixels both drew cloth on (alpha > 0).
double cloth_rmse(const std::vector<float>& a, const std::vector<float>& b) {
  double d2 = 0.0, sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i + 3 < a.size(); i += 4)
    if (gpu::is_cloth_alpha(a[i + 3]) && gpu::is_cloth_alpha(b[i + 3])) {
      for (int c = 0; c < 3; ++c) {
        const double d = double(a[i + c]) - double(b[i + c]);
        d2 += d * d / 3.0;
        sum += double(b[i + c]) / 3.0;
      }
      ++n;
    }
  return n && sum > 0.0 ? std::sqrt(d2 / double(n)) / (sum / double(n)) : 0.0;
}

// CPU time of this process and its threads (llvmpipe's), in ms: on a shared machine it moves far
// less with the load than the wall clock does.
double cpu_ms() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return 1e3 * (double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec));
}

// "cloth pixels, of them not finite, of them black" of a readback.
std::string cloth_census(const std::vector<float>& rgba) {
  size_t cloth = 0, bad = 0, black = 0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (!gpu::is_cloth_alpha(rgba[i + 3])) continue;
    ++cloth;
    const bool finite = std::isfinite(rgba[i]) && std::isfinite(rgba[i + 1]) && std::isfinite(rgba[i + 2]);
    if (!finite) ++bad;
    else if (rgba[i] <= 0.0f && rgba[i + 1] <= 0.0f && rgba[i + 2] <= 0.0f) ++black;
  }
  return std::to_string(cloth) + " cloth px, " + std::to_string(bad) + " not finite, " + std::to_string(black) + " black";
}

// Per cloth object and value block (an SG, or a quadrature part) of the renderer's last draw: the
// vertices whose per-vertex value is not finite, the first of them with its normal and warp.
void print_non_finite_vertices(const SceneBundle& sb, const gpu::SceneRenderer& r) {
  size_t cloth_index = 0;
  for (const SceneObject& o : sb.scene.objects) {
    if (!o.is_cloth()) continue;
    int texels = 0;
    const std::vector<float> values = r.cloth_vertex_values(cloth_index++, &texels);
    for (size_t b = 0; texels > 0 && b * size_t(texels) * 4 < values.size(); ++b) {
      size_t bad = 0, first = 0;
      for (size_t i = 0; i < size_t(texels) && i < o.mesh.positions.size(); ++i) {
        const float* v = &values[(b * size_t(texels) + i) * 4];
        if (std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) continue;
        if (bad++ == 0) first = i;
      }
      if (bad == 0) continue;
      const glm::dvec3 n = o.mesh.normals[first], u = o.mesh.warps[first];
      std::printf("  %s block %zu: %zu of %zu vertices not finite; first %zu, normal (%.6f %.6f %.6f), warp (%.6f %.6f %.6f)\n",
                  o.name.c_str(), b, bad, o.mesh.positions.size(), first, n.x, n.y, n.z, u.x, u.y, u.z);
      if (b < sb.sgs.size()) {
        const SphericalGaussian& g = sb.sgs[b];
        std::printf("    SG %zu: axis (%.6f %.6f %.6f), sharpness %.4f, cos to the normal %.6f\n", b, g.axis.x, g.axis.y, g.axis.z,
                    g.sharpness, glm::dot(glm::normalize(g.axis), glm::normalize(n)));
      }
    }
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}
}  // namespace

// The showroom's coarse grids, as ./setup.sh run bakes it.
constexpr const char* kShowroomGrids = "--table-grid 32 --sdf-resolution 64 --floor-sdf-resolution 32";

// Bakes `scene` with `weft bake` and `flags` into `dir`; "name=FILE".
std::string baked(const std::string& scene, const std::filesystem::path& dir, const std::string& flags) {
  const std::filesystem::path out = dir / (scene + ".weft");
  const std::string cmd = std::string(WEFT_BINARY) + " bake --scene " + scene + " " + flags + " --out " + out.string() + " > " +
                          (dir / (scene + ".log")).string() + " 2>&1";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("bake failed: " + cmd);
  return scene + "=" + out.string();
}

TEST(KioskFrameBench, StagesReuseAndFirstFrame) {
  // WEFT_KIOSK_SMOKE: CI's small version (a swatch on coarse tables, 64×48, a few frames, the
// camera still: the reused frame must equal the full one).
  const bool smoke = std::getenv("WEFT_KIOSK_SMOKE") != nullptr;
  std::string bundles = env_or("WEFT_KIOSK_BUNDLES", "");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("weft_kiosk_bench_" + std::to_string(getpid()));
  if (bundles.empty()) {
    std::filesystem::create_directories(dir);
    bundles = smoke ? baked("swatch", dir, "--table-grid 8 --lambda-levels 4 --sdf-resolution 16")
                    : baked("showroom", dir, kShowroomGrids) + "," + baked("pillow", dir, kShowroomGrids);
  }
  const std::vector<std::string> methods = split(env_or("WEFT_KIOSK_METHODS", smoke ? "auto" : "auto,iwasaki_vertex,sheen"), ',');
  struct Reuse {
    int all = 1, broad = 1;
    int longest() const { return std::max(all, broad); }
    std::string name() const { return broad > 1 ? "broad " + std::to_string(broad) : std::to_string(all); }
  };
  const std::vector<std::string> vertex_sets = split(env_or("WEFT_KIOSK_VERTICES", "visible"), ',');
  std::vector<double> zooms;
  for (const std::string& z : split(env_or("WEFT_KIOSK_ZOOMS", "0"), ',')) zooms.push_back(std::stod(z));
  const std::vector<std::string> weaves = split(env_or("WEFT_KIOSK_WEAVE", "on"), ',');
  std::vector<Reuse> shares;
  for (const std::string& s : split(env_or("WEFT_KIOSK_REFRESH", smoke ? "1,4,b4" : "1,4,8,16,b4,b8,b16"), ','))
    shares.push_back(s[0] == 'b' ? Reuse{1, std::stoi(s.substr(1))} : Reuse{std::stoi(s), 1});
  const int frames = std::stoi(env_or("WEFT_KIOSK_FRAMES", smoke ? "3" : "24"));
  const std::vector<std::string> size = split(env_or("WEFT_KIOSK_SIZE", smoke ? "64x48" : "640x480"), 'x');
  const int w = std::stoi(size.at(0)), h = std::stoi(size.at(1));
  // 6°/s at 15 frames/s; the smoke holds the camera still, where reuse must change nothing.
  const double kDegPerFrame = std::stod(env_or("WEFT_KIOSK_DEG_PER_FRAME", smoke ? "0" : "0.4"));
  constexpr double kFramesPerSecond = 15.0;
  // The renderer's clock (kept per-vertex values extrapolated to each frame's time) unless
  // WEFT_KIOSK_PLAIN_REUSE: reuse holding kept values as they are.
  const bool clocked = std::getenv("WEFT_KIOSK_PLAIN_REUSE") == nullptr;
  // Frames before timing: the reuse reaches its steady state within R of them.
  int kWarm = smoke ? 4 : 16;
  for (const Reuse& s : shares) kWarm = std::max(kWarm, s.longest());

  gpu::EglContext ctx = gpu::EglContext::headless();
  std::ostringstream table;
  table << "Machine: " << ctx.renderer() << " (stages by " << (gpu::software_renderer() ? "CPU clock" : "GPU timestamps where the driver has them") << "); " << w << "×" << h << ", turntable " << kDegPerFrame << "°/frame (6°/s at 15 frames/s: 0.4), " << frames
        << " timed frames after " << kWarm << " warm ones.\n\n"
        << "| bundle | rung | vertices | reuse R | zoom | weave layer | ms/frame | CPU ms/frame | backdrop | surfaces | vertex passes | cloth | weave | other | first frame ms | "
           "error vs all, R = 1 mean | worst |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& item : split(bundles, ',')) {
    const auto eq = item.find('=');
    ASSERT_NE(eq, std::string::npos) << item;
    const std::string name = item.substr(0, eq), file = item.substr(eq + 1);
    for (const std::string& method_name : methods) {
      const auto t_first = std::chrono::steady_clock::now();
      const bundle::BundleReader reader = bundle::BundleReader::open(file);
      const KioskBundle kb = read_kiosk_bundle(reader, method_name);
      const methods::RuntimeMethod& method = kiosk_method(method_name, kb, file);
      const std::vector<Fabric> cloth = cloth_fabrics(kb.scene);
      std::unique_ptr<gpu::SceneRenderer> r = make_kiosk_renderer(kb.scene, cloth, method, kb.shading);
      r->set_lighting(kb.scene.sgs);
      // The same frames with every vertex recomputed, for the reuse's error.
      std::unique_ptr<gpu::SceneRenderer> full = make_kiosk_renderer(kb.scene, cloth, method, kb.shading);
      full->set_lighting(kb.scene.sgs);
      full->set_visible_vertices_only(false);
      full->set_depth_prepass(false);
      gpu::OffscreenTarget target(w, h), truth(w, h);
      const glm::dvec3 pivot = turntable_pivot(kb.scene.scene);
      // As the kiosk draws a zoom: dollied toward its close-up, turned about the pivot moved as far toward the target.
      const Camera closeup = closeup_of(kb.scene.scene, cloth, h);
      arm_weave_range(*r, kb.scene, closeup, w, h);
      arm_weave_range(*full, kb.scene, closeup, w, h);
      double zoom = 0.0;
      auto camera_at = [&](int k) {
        const Camera c = dolly(kb.scene.scene.camera, closeup, zoom);
        return turned_about_z(c, k * kDegPerFrame, glm::mix(pivot, c.target, zoom));
      };
      target.bind();
      r->draw(camera_at(0), w, h);
      glFinish();
      const double first_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_first).count();
      const bool per_vertex = method.shading == methods::Shading::per_vertex;
      for (const std::string& vertices : vertex_sets)
      for (const Reuse& reuse : shares)
      for (const double z : zooms)
      for (const std::string& weave : weaves) {
        zoom = z;
        // on or pixel: each float lit per pixel up close; table: the per-vertex table; off.
        r->set_weave(weave != "off");
        full->set_weave(weave != "off");
        r->set_weave_pixel_terms(weave != "table");
        full->set_weave_pixel_terms(weave != "table");
        const bool visible_only = vertices != "all";
        // Measured against the full frame (WEFT_KIOSK_NO_ERROR: not, where reading frames back would dwarf them, e.g. 4K).
        const bool reused = (reuse.longest() > 1 || (per_vertex && visible_only)) && std::getenv("WEFT_KIOSK_NO_ERROR") == nullptr;
        if (reuse.longest() > 1 && !per_vertex) continue;
        if (!per_vertex && vertices != vertex_sets.front()) continue;
        r->set_visible_vertices_only(visible_only);
        r->set_depth_prepass(visible_only);
        r->refresh_all();
        r->set_vertex_refresh(reuse.all);
        r->set_broad_lobe_refresh(reuse.broad);
        // GPU timestamps on a real GPU; the CPU clock on llvmpipe, whose timestamps are not its work.
        gpu::FrameProfile profile(gpu::software_renderer() ? gpu::TimerQueryFunctions{} : gpu::timer_query_functions());
        std::vector<double> ms, errors;
        double cpu = 0.0;
        for (int k = 1; k <= kWarm + frames; ++k) {
          const bool timed = k > kWarm;
          if (timed) profile.begin_frame();
          const auto t0 = std::chrono::steady_clock::now();
          const double c0 = cpu_ms();
          target.bind();
          if (clocked) r->set_clock(double(k) / kFramesPerSecond);
          r->draw(camera_at(k), w, h);
          glFinish();
          if (timed) {
            profile.end_frame();
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            cpu += (cpu_ms() - c0) / double(frames);
          }
          if (timed && reused) {
            truth.bind();
            full->draw(camera_at(k), w, h);
            errors.push_back(cloth_rmse(target.read_rgba(), truth.read_rgba()));
          }
        }
        const auto st = profile.median_ms();
        auto stage = [&](gpu::Stage s) { return st[size_t(s)]; };
        double mean_err = 0.0, worst = 0.0;
        for (double e : errors) mean_err += e / double(errors.size()), worst = std::max(worst, e);
        char row[512];
        std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %.2f | %s | %.1f | %.0f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.0f | %s | %s |\n", name.c_str(),
                      (method_name == "auto" ? "auto: " + method.name : method.name).c_str(), per_vertex ? vertices.c_str() : "",
                      reuse.name().c_str(), z, weave.c_str(), median(ms), cpu,
                      stage(gpu::Stage::backdrop), stage(gpu::Stage::surfaces), stage(gpu::Stage::vertex_pass), stage(gpu::Stage::cloth),
                      stage(gpu::Stage::weave), stage(gpu::Stage::other), first_ms,
                      reused ? (std::to_string(mean_err * 100.0).substr(0, 6) + " %").c_str() : "",
                      reused ? (std::to_string(worst * 100.0).substr(0, 6) + " %").c_str() : "");
        table << row;
        std::cout << row << std::flush;
        if (const char* shots = std::getenv("WEFT_KIOSK_SHOTS")) {
          const std::string stem = std::string(shots) + "/" + name + "_" + method.name + "_" + (per_vertex ? vertices : "") + "_" +
                                   std::to_string(reuse.longest()) + "_zoom" + std::to_string(int(std::lround(100 * z))) + "_" + weave;
          std::filesystem::create_directories(shots);
          const std::vector<float> shown = target.read_rgba();  // binds the target for the image too
          write_exr(gpu::read_linear_image(w, h), stem + ".exr");
          truth.bind();
          full->draw(camera_at(kWarm + frames), w, h);
          const std::vector<float> every = truth.read_rgba();
          write_exr(gpu::read_linear_image(w, h), stem + "_every_vertex.exr");
          std::cout << stem << ": drawn " << cloth_census(shown) << "; every vertex " << cloth_census(every) << "\n";
          print_non_finite_vertices(kb.scene, *r);
        }
        // A camera that does not move: reused values are the values, so the frame is the full one.
        if (reused && (kDegPerFrame == 0.0 || reuse.longest() == 1)) {
          EXPECT_LE(worst, 1e-6) << name << " " << method.name << " R=" << reuse.name() << ": reuse or culling differs from the full frame of the same view";
        }
      }
    }
  }
  std::cout << "\n" << table.str();
  if (const char* out = std::getenv("WEFT_KIOSK_OUT")) std::ofstream(out) << table.str();
  std::filesystem::remove_all(dir);
}
