#include "capture/capture_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "capture/capture_card.h"
#include "image/image.h"
#include "image/tone_map.h"

namespace weft {

namespace {

double round_to(double x, double step) { return std::round(x / step) * step; }

unsigned char display(double v) { return static_cast<unsigned char>(std::lround(255.0 * srgb_encode(v))); }

}  // namespace

void write_fitted_fabric(const CaptureFitResult& result, const std::filesystem::path& presets_dir,
                         const std::filesystem::path& file, const std::optional<AppearanceCheck>& check) {
  const FabricFit& fit = result.fit;
  std::ifstream in(fabric_file(fit.preset, presets_dir));
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(in);
  doc["name"] = file.stem().string();
  doc["description"] = "Fitted by weft capture to " + std::to_string(result.photos.size()) + " photos (weave of " + fit.preset + ")";
  doc.erase("display_name");
  doc.erase("composition");
  nlohmann::ordered_json sigma = nlohmann::ordered_json::array();
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& t = fit.fabric.threads[j];
    // The file's albedo is a colour with its brightest channel 1 and a scale (the presets' form).
    const double scale = std::max({t.albedo.r, t.albedo.g, t.albedo.b, 1e-6});
    auto& thread = doc["threads"][j];
    thread["albedo"] = {round_to(t.albedo.r / scale, 1e-4), round_to(t.albedo.g / scale, 1e-4), round_to(t.albedo.b / scale, 1e-4)};
    thread["albedo_scale"] = round_to(scale, 1e-5);
    thread["kd"] = round_to(t.kd, 1e-4);
    thread["gamma_s_deg"] = round_to(glm::degrees(t.gamma_s), 1e-3);
    thread["gamma_v_deg"] = round_to(glm::degrees(t.gamma_v), 1e-3);
    const ThreadUncertainty& s = fit.sigma[j];
    sigma.push_back({{"albedo", {s.albedo.r, s.albedo.g, s.albedo.b}}, {"kd", s.kd},
                     {"gamma_s_deg", glm::degrees(s.gamma_s)}, {"gamma_v_deg", glm::degrees(s.gamma_v)}});
  }
  nlohmann::ordered_json capture;
  capture["weave_family"] = fit.preset;
  capture["rms_relative_residual"] = fit.rms_relative;
  capture["robust_cost"] = fit.cost;
  capture["observations"] = result.observations.size();
  capture["sigma"] = sigma;
  for (const auto& [name, cost] : fit.family_costs) capture["family_costs"][name] = cost;
  for (const CapturedPhoto& p : result.photos)
    capture["photos"].push_back({{"file", p.file}, {"turn_deg", glm::degrees(p.turn)}, {"cells", p.cells},
                                 {"corner_tags", p.corner_tags}, {"reprojection_px", p.reprojection_px},
                                 {"edge_width_px", p.edge_width_px}, {"response_beta", p.response.model.beta},
                                 {"vignetting", p.response.model.vignetting}, {"ball_brackets", p.brackets},
                                 {"ball_clipped", p.ball_clipped}});
  if (result.closeup) {
    const CloseupClusters& c = *result.closeup;
    auto rgb = [](const glm::dvec3& v) { return nlohmann::ordered_json{v.r, v.g, v.b}; };
    nlohmann::ordered_json& j = capture["closeup"];
    j = {{"file", result.closeup_file}, {"gap_share", c.gap_share}, {"used", fit.closeup && fit.closeup->used}};
    if (c.scale) j["scale_tag_px_per_mm"] = c.scale->px_per_mm;
    if (const auto& t = result.thread_counts)
      j["thread_counts"] = {{"ends_per_cm", t->ends_per_cm},     {"picks_per_cm", t->picks_per_cm},
                            {"resolved", result.counts_resolved()},         {"score", t->score},
                            {"strong_lines", t->points},         {"fitted_lines", t->fitted_lines},
                            {"fitted_share", t->fitted_share},   {"warp_off_tag_deg", glm::degrees(t->angle)},
                            {"resolution_per_cm", t->resolution_per_cm}};
    if (const auto& g = result.registration)
      j["registration"] = {{"registered", g->registered}, {"why_not", g->why}, {"tile_bins", {g->tile_bins.x, g->tile_bins.y}},
                           {"pixels", g->pixels}, {"phase", {g->phase.x, g->phase.y}}, {"mirrored", g->mirrored},
                           {"explained", g->explained}, {"explained_median_phase", g->explained_median},
                           {"exposure", g->exposure}, {"warp_albedo", rgb(g->albedo[0])}, {"weft_albedo", rgb(g->albedo[1])},
                           {"warp_over_weft_albedo", rgb(g->albedo_ratio)}, {"albedo_read", g->albedo_read},
                           {"warp_mean", rgb(g->thread_mean[0])}, {"weft_mean", rgb(g->thread_mean[1])},
                           {"inner_bins", {g->inner_bins[0], g->inner_bins[1]}}};
    for (const CloseupSplit& s : c.splits)
      j["splits"].push_back({{"features", s.lightness ? "colour and lightness" : "colour"}, {"pixels", s.pixels},
                             {"shares", {s.share[0], s.share[1]}}, {"valley", s.valley}});
    if (const auto& f = fit.closeup) {
      j["one_colour"] = f->one_colour;
      j["one_lightness"] = f->one_lightness;
      if (!f->used) j["not_used"] = f->rejected;
      j["registered"] = f->registered;
      if (f->split >= 0) {
        j["split"] = f->split;
        j["warp_share"] = f->warp_share;
      }
      if (f->registered || f->split >= 0) j["measured_warp_over_weft"] = rgb(f->measured_ratio);
      j["fitted_warp_over_weft"] = rgb(f->fitted_ratio);
      if (f->measured_level) j["measured_level"] = rgb(*f->measured_level);
      if (f->fitted_level) j["fitted_level"] = rgb(*f->fitted_level);
    }
  }
  if (check)
    capture["appearance_check"] = {{"map", check->map}, {"truth", check->truth}, {"views", check->views},
                                   {"relative_rmse", check->relative_rmse},
                                   {"thread_delta_e2000", check->thread_delta_e2000},
                                   {"ends_ratio", check->ends_ratio}, {"picks_ratio", check->picks_ratio}};
  doc["capture"] = capture;
  std::ofstream(file) << doc.dump(2) << "\n";
}

void write_side_by_side(const CaptureFitResult& result, const std::filesystem::path& file) {
  const CaptureCard& card = capture_card();
  constexpr int zoom = 3, grid = 16;
  const int cell = kPanel * zoom, w = 3 * cell, h = static_cast<int>(result.photos.size()) * cell;
  std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3, 128);
  const glm::dvec3 window = card_to_world(card.swatch_window.centre());
  const double radius = card.swatch_radius / 1000.0;
  for (size_t i = 0; i < result.photos.size(); ++i) {
    const CapturedPhoto& p = result.photos[i];
    // The fitted model on a coarse grid of views across the swatch, interpolated (it varies slowly).
    std::vector<glm::dvec3> model(grid * grid);
#pragma omp parallel for schedule(dynamic)
    for (int g = 0; g < grid * grid; ++g) {
      const glm::dvec3 pos = window + glm::dvec3((g % grid) / (grid - 1.0) * 2 * radius - radius, radius - (g / grid) / (grid - 1.0) * 2 * radius, 0);
      model[g] = swatch_radiance(result.fit.fabric, p.turn, glm::normalize(p.camera_centre - pos), result.lighting.lights);
    }
    for (int py = 0; py < kPanel; ++py)
      for (int px = 0; px < kPanel; ++px) {
        const double gx = (px + 0.5) / kPanel * (grid - 1), gy = (py + 0.5) / kPanel * (grid - 1);
        const int x0 = std::min(static_cast<int>(gx), grid - 2), y0 = std::min(static_cast<int>(gy), grid - 2);
        const double ax = gx - x0, ay = gy - y0;
        const glm::dvec3 fitted = (1 - ay) * ((1 - ax) * model[y0 * grid + x0] + ax * model[y0 * grid + x0 + 1]) +
                                  ay * ((1 - ax) * model[(y0 + 1) * grid + x0] + ax * model[(y0 + 1) * grid + x0 + 1]);
        const bool masked = p.panel_marker[py * kPanel + px];
        const glm::dvec3 photo = p.panel[py * kPanel + px];
        const glm::dvec3 shown[3] = {photo, masked ? glm::dvec3(0.2) : fitted,
                                     masked ? glm::dvec3(0.2) : 4.0 * glm::abs(photo - fitted)};
        for (int k = 0; k < 3; ++k)
          for (int zy = 0; zy < zoom; ++zy)
            for (int zx = 0; zx < zoom; ++zx) {
              const size_t q = (static_cast<size_t>(i * cell + py * zoom + zy) * w + k * cell + px * zoom + zx) * 3;
              for (int c = 0; c < 3; ++c) rgb[q + c] = display(shown[k][c]);
            }
      }
  }
  write_png_rgb8(w, h, rgb, file);
}

std::string fit_summary(const CaptureFitResult& r, const std::optional<AppearanceCheck>& check) {
  char line[512];
  std::string out;
  std::snprintf(line, sizeof line, "weave family %s, RMS relative residual %g over %zu cells of %zu photos, %g s\n",
                r.fit.preset.c_str(), r.fit.rms_relative, r.observations.size(), r.photos.size(), r.seconds);
  out += line;
  if (r.closeup && r.fit.closeup) {
    const CloseupFit& f = *r.fit.closeup;
    std::string what;
    if (f.registered || f.split >= 0) {
      std::snprintf(line, sizeof line, "warp ÷ weft (%.3f %.3f %.3f) measured %s, (%.3f %.3f %.3f) fitted", f.measured_ratio.r,
                    f.measured_ratio.g, f.measured_ratio.b,
                    f.registered ? "where the weave registered to it puts them" : "from its colour clusters", f.fitted_ratio.r,
                    f.fitted_ratio.g, f.fitted_ratio.b);
      what = line;
    }
    if (f.one_colour) {
      std::snprintf(line, sizeof line, "one %s (its clusters do not separate): the threads' %s tied", f.one_lightness ? "colour" : "hue",
                    f.one_lightness ? "colours" : "chromaticities");
      what += (what.empty() ? "" : "; ") + std::string(line);
    }
    if (f.measured_level && f.fitted_level) {
      std::snprintf(line, sizeof line, "the swatch straight above (%.3f %.3f %.3f) over the tag's paper, (%.3f %.3f %.3f) fitted",
                    f.measured_level->r, f.measured_level->g, f.measured_level->b, f.fitted_level->r, f.fitted_level->g,
                    f.fitted_level->b);
      what += (what.empty() ? "" : "; ") + std::string(line);
    }
    out += "close-up " + r.closeup_file + ": " + (what.empty() ? "nothing taken" : what) +
           (f.used ? "" : "; not used: " + f.rejected) + "\n";
  }
  {
    const WeaveSpec& weave = r.fit.fabric.weave;
    std::string source = "from the close-up's spectrum";
    if (!r.closeup)
      source = "the family's (no close-up)";
    else if (!r.closeup->scale)
      source = "the family's (no scale tag in the close-up)";
    else if (!r.thread_counts)
      source = "the family's (the close-up leaves no room beside its scale tag)";
    else if (r.counts_resolved() && !r.thread_counts->resolved())
      source = "from the close-up's spectrum, its lattice confirmed by the close-up's registration to it";
    else if (!r.counts_resolved())
    {
      char why[160];
      std::snprintf(why, sizeof why, "the family's (the weave's lattice not resolved in the close-up: %.0f %% of its lines on it, %d fitted)",
                    100.0 * r.thread_counts->score, r.thread_counts->fitted_lines);
      source = why;
    }
    std::snprintf(line, sizeof line, "ends %.1f, picks %.1f per cm: %s\n", weave.ends_per_cm, weave.picks_per_cm, source.c_str());
    out += line;
  }
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& t = r.fit.fabric.threads[j];
    const ThreadUncertainty& s = r.fit.sigma[j];
    std::snprintf(line, sizeof line, "thread %d: A (%.4f %.4f %.4f) ±(%.4f %.4f %.4f)  kd %.3f ±%.3f  γs %.2f° ±%.2f  γv %.2f° ±%.2f\n",
                  j + 1, t.albedo.r, t.albedo.g, t.albedo.b, s.albedo.r, s.albedo.g, s.albedo.b, t.kd, s.kd,
                  glm::degrees(t.gamma_s), glm::degrees(s.gamma_s), glm::degrees(t.gamma_v), glm::degrees(s.gamma_v));
    out += line;
  }
  if (check) {
    std::snprintf(line, sizeof line,
                  "appearance under %s: relative RMSE %.4f against %s over %d views; thread colours ΔE2000 %.2f, %.2f\n",
                  check->map.c_str(), check->relative_rmse, check->truth.c_str(), check->views,
                  check->thread_delta_e2000[0], check->thread_delta_e2000[1]);
    out += line;
    std::snprintf(line, sizeof line, "thread counts against %s: ends ×%.3f, picks ×%.3f\n", check->truth.c_str(),
                  check->ends_ratio, check->picks_ratio);
    out += line;
  }
  return out;
}

}  // namespace weft
