// Benchmark (label bench, not run in CI): the weave layer up close, against the resolved
// reference (the reference's resolved weave, supersampled pixels) under the same 10 SGs.
//  - accuracy at the close-up (scene/weave_scale.h closeup_camera: the scene's close-up, or its
//    camera moved in until a repeat spans 24 pixels of the accuracy image): relative RMSE over the
//    cloth pixels of the fabric-level rung alone and with the weave layer, and with the layer over
//    the pixels where a repeat spans 16 pixels or more (the close-up: a grazing close-up's
//    far part holds repeats of a few pixels, where the layer fades to the fabric level). The
//    reference is supersampled 8×8 by default: at 3×3 its yarn edges alone are 11 % off an 8×8
//    one (linen, this view), more than the target;
//  - speed at 640×480 of the same view, with and without the layer (median of timed frames);
//  - at the scene's own camera the layer must leave the frame exactly as the rung draws it;
//  - flicker: a camera dollying from 60 % to 100 % of the way to the close-up in 16 steps (the
//    level-of-detail transition), mean frame-to-frame relative change with and without the layer:
//    per pixel (the texture moving across the screen counts), and at fixed surface points (each
//    pixel's surface point, found by a ray, looked up where the frame before showed it: what is
//    left is shimmer, and the view's own small change).
// A scene's named close-up (the showroom's, framed for the kiosk's 480 lines) is moved on toward
// its target until a repeat spans 24 pixels of the accuracy image too.
// WEFT_WEAVE_CASES picks cases (SCENE:FABRIC, FABRIC empty for the scene's own, and
// @EX,EY,EZ:TX,TY,TZ[:FOV] after it for a close-up of one's own), WEFT_WEAVE_SUPERSAMPLE the reference's rays per pixel along each axis ("swatch:linen_plain,showroom:"); WEFT_WEAVE_OUT writes the table;
// WEFT_WEAVE_FLICKER_ONLY skips the references, accuracy and speed (minutes instead of an hour);
// WEFT_WEAVE_IMAGES=DIR writes each case's reference and each rung's frame with the layer (EXR and
// PNG); WEFT_WEAVE_CHART=FILE.png draws the close-up's speed against accuracy (each rung alone and
// with the layer, error over the whole close-up), and WEFT_WEAVE_CHART_FROM=TABLE.md[,…] draws it
// from tables this bench wrote, rendering nothing. WEFT_WEAVE_REFERENCE_FROM=DIR takes each
// case's resolved reference from DIR (a WEFT_WEAVE_IMAGES directory of an earlier run of the same
// case) instead of rendering it: the rungs measured again in minutes, not the reference's quarter
// hour. WEFT_WEAVE_TERMS=table: over a per-vertex rung the layer reads each float's lighting off
// its per-vertex table (the kiosk's choice on a GPU too slow for the default, each float lit per
// pixel); the rung's name in the table says so. The bake is weft bake's default (tables, visibility, masks): the weave layer's lights take
// their visibility from the masks, as in a kiosk.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/cli_parse.h"
#include "bake/scene/scene_bake.h"
#include "bench/chart.h"
#include "image/image.h"
#include "lighting/env_map.h"
#include "runtime/visibility_mask.h"
#include "measure/image_metrics.h"
#include "frame/frame_inputs.h"
#include "frame/frame_render.h"
#include "kiosk/camera_zoom.h"
#include "reference/ray_scene.h"
#include "reference/scene_render.h"
#include "scene/weave_scale.h"

using namespace weft;

namespace {
const std::filesystem::path kAssets = WEFT_SOURCE_ASSETS;

struct Case {
  std::string scene, fabric;  // fabric empty: the scene's own
  std::string closeup;  // "EX,EY,EZ:TX,TY,TZ[:FOV]" after '@' (app/cli_parse.h parse_camera): in place of the scene's close-up
};

std::vector<Case> cases() {
  const char* env = std::getenv("WEFT_WEAVE_CASES");
  std::string list = env ? env
                         : "swatch:linen_plain,swatch:silk_crepe_de_chine,swatch:polyester_satin_charmeuse,"
                           "swatch:polyester_satin_charmeuse_back,swatch:silk_shot,swatch:velvet,showroom:";
  std::vector<Case> out;
  std::stringstream ss(list);
  std::string item;
  // Cases are split at commas; a camera's commas are inside its "@…" part, so a case runs on to the
  // next item that names a scene (holds no '@' part of its own and starts with a letter).
  std::vector<std::string> items;
  while (std::getline(ss, item, ','))
    if (!items.empty() && items.back().find('@') != std::string::npos && !std::isalpha(static_cast<unsigned char>(item[0])))
      items.back() += "," + item;
    else
      items.push_back(item);
  for (const std::string& it : items) {
    const auto at = it.find('@');
    const std::string name = it.substr(0, at);
    const auto colon = name.find(':');
    out.push_back({name.substr(0, colon), colon == std::string::npos ? "" : name.substr(colon + 1),
                   at == std::string::npos ? "" : it.substr(at + 1)});
  }
  return out;
}

double mean_change(const Image& a, const Image& b, const std::vector<bool>& cloth) {
  double d2 = 0.0, sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (cloth[i]) {
      const glm::dvec3 d = a.pixels[i] - b.pixels[i];
      d2 += glm::dot(d, d) / 3.0;
      sum += (b.pixels[i].r + b.pixels[i].g + b.pixels[i].b) / 3.0;
      ++n;
    }
  return n && sum > 0.0 ? std::sqrt(d2 / n) / (sum / n) : 0.0;
}
// Where surface point x lies in a width×height image from `c` (camera_ray's inverse: (0,0) the
// top-left corner); false behind the camera.
bool project(const Camera& c, int width, int height, const glm::dvec3& x, glm::dvec2& px) {
  const glm::dvec3 forward = glm::normalize(c.target - c.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const glm::dvec3 d = x - c.position;
  const double f = glm::dot(d, forward);
  if (f <= 0.0) return false;
  const double tan_half = std::tan(glm::radians(c.fov_deg) / 2.0), aspect = double(width) / height;
  px = {(glm::dot(d, right) / f / (tan_half * aspect) + 1.0) * width / 2.0, (1.0 - glm::dot(d, up) / f / tan_half) * height / 2.0};
  return true;
}

// Relative change at fixed surface points from frame `prev` (camera `was`) to `next` (camera
// `now`): each cloth pixel of `next` whose surface point `was` also saw (the first hit along its
// ray), compared with `prev` bilinearly interpolated there among cloth pixels.
double surface_change(const RayScene& rays, const GpuFrame& prev, const Camera& was, const GpuFrame& next, const Camera& now,
                      int w, int h) {
  double d2 = 0.0, sum = 0.0;
  size_t n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!next.cloth[size_t(y) * w + x]) continue;
      const auto hit = rays.intersect(now.position, camera_ray(now, w, h, x + 0.5, y + 0.5));
      if (!hit) continue;
      const glm::dvec3 p = rays.surface(*hit).position;
      glm::dvec2 q;
      if (!project(was, w, h, p, q)) continue;
      const glm::dvec3 back = p - was.position;
      const auto seen = rays.intersect(was.position, glm::normalize(back));
      if (!seen || glm::length(rays.surface(*seen).position - p) > 1e-4 * glm::length(back)) continue;
      const double fx = q.x - 0.5, fy = q.y - 0.5;
      const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
      if (x0 < 0 || y0 < 0 || x0 + 1 >= w || y0 + 1 >= h) continue;
      bool all_cloth = true;
      for (int k = 0; k < 4; ++k) all_cloth = all_cloth && prev.cloth[size_t(y0 + k / 2) * w + x0 + k % 2];
      if (!all_cloth) continue;
      const double ax = fx - x0, ay = fy - y0;
      const glm::dvec3 was_value = (1 - ay) * ((1 - ax) * prev.image.at(x0, y0) + ax * prev.image.at(x0 + 1, y0)) +
                                   ay * ((1 - ax) * prev.image.at(x0, y0 + 1) + ax * prev.image.at(x0 + 1, y0 + 1));
      const glm::dvec3 d = next.image.at(x, y) - was_value;
      d2 += glm::dot(d, d) / 3.0;
      sum += (was_value.r + was_value.g + was_value.b) / 3.0;
      ++n;
    }
  return n && sum > 0.0 ? std::sqrt(d2 / n) / (sum / n) : 0.0;
}
// The cloth pixels where a repeat of the weave spans at least `pixels` pixels: the footprint of the
// pixel in tile units (rays through its centre and its right and lower neighbours) at most
// 1/pixels of a repeat along both axes.
std::vector<bool> resolved_pixels(const RayScene& rays, const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                  const Camera& c, int w, int h, double pixels) {
  std::vector<bool> out(size_t(w) * h, false);
  auto tile_point = [&](double px, double py, size_t& object) -> std::optional<glm::dvec2> {
    const auto hit = rays.intersect(c.position, camera_ray(c, w, h, px, py));
    if (!hit) return std::nullopt;
    object = hit->object;
    const SceneObject& o = scene.objects[hit->object];
    if (!o.is_cloth()) return std::nullopt;
    return rays.surface(*hit).uv * weave_tiles_per_uv(o, object_fabric(o, fabrics.at(o.fabric)));
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      size_t a = 0, b = 0, d = 0;
      const auto st = tile_point(x + 0.5, y + 0.5, a), sx = tile_point(x + 1.5, y + 0.5, b), sy = tile_point(x + 0.5, y + 1.5, d);
      if (!st || !sx || !sy || a != b || a != d) continue;
      const double footprint = std::max(glm::length(*sx - *st), glm::length(*sy - *st));
      out[size_t(y) * w + x] = footprint <= 1.0 / pixels;
    }
  return out;
}

// The close-up the accuracy image is measured at: the scene's close-up (named, or its camera
// moved in), then moved on toward its target until a repeat spans 24 pixels of `height` lines.
Camera accuracy_closeup(const Scene& scene, const std::map<std::string, Fabric>& fabrics, int height) {
  Scene moved = scene;
  if (moved.closeup) moved.camera = *moved.closeup;
  moved.closeup.reset();
  return closeup_camera(moved, fabrics, height);
}

// The chart's two points of one table row: the rung alone and with the layer, ms at 640×480
// against the error over the whole close-up.
void add_chart_points(std::vector<bench::ChartPoint>& points, const std::string& rung, double ms_alone, double alone,
                      double ms_woven, double woven) {
  if (std::isfinite(ms_alone) && std::isfinite(alone)) points.push_back({rung, ms_alone, alone});
  if (std::isfinite(ms_woven) && std::isfinite(woven)) points.push_back({rung + " + weave", ms_woven, woven});
}

// The chart's points from a table this bench wrote (its header and rule lines skipped).
std::vector<bench::ChartPoint> chart_points_from_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::vector<bench::ChartPoint> points;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cell;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, '|');) cell.push_back(c);
    // "| scene | fabric | repeat px | rung | vs fabric level | alone | + weave | ≥ 16 px | ms alone | ms + weave | …"
    if (cell.size() < 11 || cell[1].find("scene") != std::string::npos || cell[1].find("---") != std::string::npos) continue;
    auto number = [](const std::string& c) { return std::strtod(c.c_str(), nullptr); };
    std::string rung = cell[4];
    rung.erase(0, rung.find_first_not_of(' '));
    rung.erase(rung.find_last_not_of(' ') + 1);
    add_chart_points(points, rung, number(cell[9]), number(cell[6]), number(cell[10]), number(cell[7]));
  }
  return points;
}

const char* kChartTitle = "weave up close: ms/frame at 640x480 vs relative RMSE against the resolved reference";
}  // namespace

TEST(WeaveCloseupBench, AccuracySpeedAndFlicker) {
  const char* chart_file = std::getenv("WEFT_WEAVE_CHART");
  std::vector<bench::ChartPoint> chart;
  if (const char* tables = std::getenv("WEFT_WEAVE_CHART_FROM")) {
    ASSERT_NE(chart_file, nullptr) << "WEFT_WEAVE_CHART_FROM needs WEFT_WEAVE_CHART";
    std::stringstream list(tables);
    for (std::string t; std::getline(list, t, ',');)
      for (const auto& p : chart_points_from_table(t)) chart.push_back(p);
    ASSERT_FALSE(chart.empty()) << "no rows in " << tables;
    bench::write_chart_png(chart_file, chart, kChartTitle);
    return;
  }
  const char* images = std::getenv("WEFT_WEAVE_IMAGES");
  if (images) std::filesystem::create_directories(images);
  // DIR/NAME.exr and DIR/NAME.png (at `exposure`) under WEFT_WEAVE_IMAGES.
  auto write_image = [&](const Image& image, const std::string& name, double exposure) {
    const std::filesystem::path stem = std::filesystem::path(images) / name;
    write_exr(image, stem.string() + ".exr");
    write_png(image, stem.string() + ".png", exposure);
  };
  constexpr int kW = 160, kH = 120;
  std::ostringstream table;
  table << "| scene | fabric | repeat px | rung | rung vs fabric-level reference | error alone | error + weave | error + weave, repeat ≥ 16 px | ms alone | ms + weave | ratio | "
           "far view max change | flicker alone | flicker + weave | at surface points alone | at surface points + weave |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Case& c : cases()) {
    FrameInputs in = load_frame_inputs({kAssets, c.scene, c.fabric, "", ""});
    if (!c.closeup.empty()) in.scene.closeup = parse_camera(c.closeup, in.scene.camera, "WEFT_WEAVE_CASES");
    const ReferenceLighting lighting = frame_lighting(in, {"sg", "", 10, 128});
    const Camera far = in.scene.camera;
    const Camera close = accuracy_closeup(in.scene, in.fabrics, kH);
    std::cerr << c.scene << "/" << c.fabric << ": close-up eye " << close.position.x << "," << close.position.y << ","
              << close.position.z << " target " << close.target.x << "," << close.target.y << "," << close.target.z << " fov "
              << close.fov_deg << "\n";
    in.scene.camera = close;
    // The repeat's size in pixels at the close-up's target, on the accuracy image.
    double repeat_px = 0.0;
    for (const auto& o : in.scene.objects)
      if (o.is_cloth()) {
        const glm::dvec2 r = weave_repeat_metres(o, object_fabric(o, in.fabrics.at(o.fabric)));
        const double d = glm::length(close.target - close.position);
        const double px = std::min(r.x, r.y) * kH / (2.0 * d * std::tan(glm::radians(close.fov_deg) / 2.0));
        repeat_px = repeat_px == 0.0 ? px : std::min(repeat_px, px);
      }
    const bool flicker_only = std::getenv("WEFT_WEAVE_FLICKER_ONLY") != nullptr;
    ReferenceRenderOptions ro;
    ro.width = kW;
    ro.height = kH;
    ro.sg_grid = 6;
    ro.tangent_samples = 16;
    ro.check_convergence = false;
    ro.resolved_weave = true;
    ro.supersample = std::getenv("WEFT_WEAVE_SUPERSAMPLE") ? std::atoi(std::getenv("WEFT_WEAVE_SUPERSAMPLE")) : 8;
    const auto t0 = std::chrono::steady_clock::now();
    ReferenceRenderResult ref, fabric_ref;
    double exposure = 1.0;  // the reference's, metered on its cloth: the same for every image of the case
    const char* reference_from = std::getenv("WEFT_WEAVE_REFERENCE_FROM");
    if (!flicker_only) {
      if (!reference_from) {
        ref = ReferenceRenderer(in.scene, in.fabrics, lighting, ro).render();
        std::cerr << c.scene << "/" << c.fabric << ": resolved reference " << kW << "x" << kH << " in "
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
      }
      ro.resolved_weave = false;
      ro.supersample = 1;
      fabric_ref = ReferenceRenderer(in.scene, in.fabrics, lighting, ro).render();
      if (reference_from) {
        // The pixels from the file (an EXR reads as an environment map does, row 0 at the top),
        // which pixels are cloth from the fabric-level reference: the same rays.
        const std::filesystem::path file = std::filesystem::path(reference_from) / (c.scene + "_" + c.fabric + "_reference.exr");
        const EnvMap read = load_env_map(file);
        ASSERT_EQ(read.width, kW) << file;
        ASSERT_EQ(read.height, kH) << file;
        ref.image = Image(kW, kH);
        for (size_t i = 0; i < ref.image.pixels.size(); ++i) ref.image.pixels[i] = glm::dvec3(read.texels[i]);
        ref.kinds = fabric_ref.kinds;
      }
      if (images) {
        std::vector<bool> cloth(ref.kinds.size());
        for (size_t i = 0; i < cloth.size(); ++i) cloth[i] = ref.kinds[i] == PixelKind::cloth;
        exposure = auto_exposure(ref.image, cloth);
        write_image(ref.image, c.scene + "_" + c.fabric + "_reference", exposure);
      }
    }
    const RayScene rays(in.scene);
    std::vector<bool> resolved = resolved_pixels(rays, in.scene, in.fabrics, close, kW, kH, 16.0);
    if (!flicker_only)
      for (size_t i = 0; i < resolved.size(); ++i) resolved[i] = resolved[i] && ref.kinds[i] == PixelKind::cloth;
    ShadingDataBakeOptions bo;
    bo.mask_resolution = kMaskResolution;
    in.shading = std::make_shared<ShadingData>(bake_shading_data(in.scene, in.fabrics, bo));
    const bool quick = std::getenv("WEFT_WEAVE_QUICK") != nullptr;  // accuracy of iwasaki_vertex only
    // Over a per-vertex rung, the layer's per-vertex table instead of each float lit per pixel.
    const bool table_terms = std::getenv("WEFT_WEAVE_TERMS") && std::string(std::getenv("WEFT_WEAVE_TERMS")) == "table";
    std::vector<std::string> methods = {"iwasaki_vertex", "iwasaki"};
    if (const char* m = std::getenv("WEFT_WEAVE_METHODS")) {
      methods.clear();
      std::stringstream list(m);
      for (std::string name; std::getline(list, name, ',');) methods.push_back(name);
    }
    for (const std::string& method : methods) {
      auto frame = [&](const Camera& cam, int w, int h, int frames, bool weave) {
        Scene s = in.scene;
        s.camera = cam;
        return render_gpu_frame(s, in.fabrics, lighting.sgs, method, w, h, frames, in.shading, gpu::Backdrop::measure, weave,
                                !table_terms);
      };
      const Image alone_image = frame(close, kW, kH, 0, false).image;
      const double nan = std::nan("");
      const double alone = flicker_only ? nan : bench::cloth_error(alone_image, ref.image, ref.kinds).relative_rmse;
      const double fabric_level = flicker_only ? nan : bench::cloth_error(alone_image, fabric_ref.image, fabric_ref.kinds).relative_rmse;
      const Image woven_image = frame(close, kW, kH, 0, true).image;
      const double woven = flicker_only ? nan : bench::cloth_error(woven_image, ref.image, ref.kinds).relative_rmse;
      if (images && !flicker_only) write_image(woven_image, c.scene + "_" + c.fabric + "_" + method + "_weave", exposure);
      const bench::MaskedError woven_resolved = flicker_only ? bench::MaskedError{} : bench::masked_error(woven_image, ref.image, resolved);
      const int speed_frames = method == "iwasaki" ? 1 : 5;
      const bool timed = !quick && !flicker_only;
      const double ms_alone = timed ? frame(close, 640, 480, speed_frames, false).median_ms : nan;
      const double ms_woven = timed ? frame(close, 640, 480, speed_frames, true).median_ms : nan;
      const GpuFrame far_alone = frame(far, kW, kH, 0, false), far_woven = frame(far, kW, kH, 0, true);
      double far_change = 0.0;
      for (size_t i = 0; i < far_alone.image.pixels.size(); ++i)
        far_change = std::max(far_change, glm::length(far_alone.image.pixels[i] - far_woven.image.pixels[i]));
      double flicker[2] = {0.0, 0.0}, at_points[2] = {0.0, 0.0};
      for (int weave = 0; weave < (quick ? 0 : 2); ++weave) {
        Camera was = dolly(far, close, 0.6);
        GpuFrame prev = frame(was, kW, kH, 0, weave);
        for (int k = 1; k <= 16; ++k) {
          const Camera now = dolly(far, close, 0.6 + 0.4 * k / 16.0);
          GpuFrame next = frame(now, kW, kH, 0, weave);
          std::vector<bool> both(next.cloth.size());
          for (size_t i = 0; i < both.size(); ++i) both[i] = next.cloth[i] && prev.cloth[i];
          flicker[weave] += mean_change(next.image, prev.image, both) / 16.0;
          at_points[weave] += surface_change(rays, prev, was, next, now, kW, kH) / 16.0;
          prev = std::move(next);
          was = now;
        }
      }
      char row[700];
      std::snprintf(row, sizeof row,
                    "| %s | %s | %.0f | %s | %.4f | %.4f | %.4f | %.4f (%zu px) | %.1f | %.1f | %.2f | %.1e | %.4f | %.4f | %.4f | %.4f |\n",
                    c.scene.c_str(), c.fabric.empty() ? "(scene's)" : c.fabric.c_str(), repeat_px, (table_terms && method.find("_vertex") != std::string::npos ? method + " (table)" : method).c_str(), fabric_level, alone,
                    woven, woven_resolved.relative_rmse, woven_resolved.pixels, ms_alone, ms_woven, ms_woven / ms_alone, far_change, flicker[0], flicker[1], at_points[0], at_points[1]);
      table << row;
      std::cout << row << std::flush;
      add_chart_points(chart, method, ms_alone, alone, ms_woven, woven);
      EXPECT_EQ(far_change, 0.0) << c.scene << " " << method << ": the layer changed the distant view";
    }
  }
  std::cout << "\n" << table.str();
  if (const char* out = std::getenv("WEFT_WEAVE_OUT")) std::ofstream(out) << table.str();
  if (chart_file && !chart.empty()) bench::write_chart_png(chart_file, chart, kChartTitle);
}
