#include "capture/capture_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "capture/capture_card.h"
#include "capture/capture_rejection.h"
#include "capture/card_detection.h"
#include "capture/card_samples.h"
#include "capture/closeup_registration.h"
#include "capture/closeup_shot.h"
#include "capture/photo_files.h"
#include "core/weave_layout.h"

namespace weft {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kCellMm = 6.0;
constexpr double kMarkerClearMm = 11.0;  // the marker's 10-cell square, half diagonal and a margin

std::array<std::uint8_t, 3> code_at(const Photo& p, int x, int y) { return {p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2)}; }

int distinct_turns(std::vector<double> turns) {
  // Turns closer than 20° count as one.
  for (double& t : turns) t = std::fmod(std::fmod(t, 2 * kPi) + 2 * kPi, 2 * kPi);
  std::sort(turns.begin(), turns.end());
  int n = 0;
  for (size_t i = 0; i < turns.size(); ++i) {
    bool same = false;
    for (size_t k = 0; k < i; ++k) {
      const double d = std::abs(std::remainder(turns[i] - turns[k], 2 * kPi));
      same = same || d < glm::radians(20.0);
    }
    n += !same;
  }
  return n;
}

}  // namespace

CaptureFitResult fit_capture(const std::filesystem::path& dir, const std::filesystem::path& presets_dir,
                             const CaptureFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const CaptureCard& card = capture_card();
  if (!std::filesystem::is_directory(dir)) throw CaptureRejection(dir.string() + ": not a folder of photos");
  const auto files = list_photos(dir);
  if (files.size() < 3)
    throw CaptureRejection(dir.string() + ": " + std::to_string(files.size()) + " photos; a capture needs 3 to 8, the swatch turned between them");
  std::optional<CaptureInfo> info;
  try {
    info = read_capture_info(dir / "capture.json");
  } catch (const PhotoError& e) {
    throw CaptureRejection(e.what());
  }
  const std::optional<double> focal = info ? info->focal_px : std::nullopt;
  auto progress = options.open_progress ? options.open_progress("photos") : std::function<void(double)>();

  CaptureFitResult result;
  std::vector<BallView> balls;
  const glm::dvec3 window = card_to_world(card.swatch_window.centre());
  const double radius = card.swatch_radius / 1000.0;
  auto load = [](const std::filesystem::path& file) {
    try {
      return read_photo(file);
    } catch (const PhotoError& e) {
      throw CaptureRejection(e.what());
    }
  };
  // First the cards and their grey samples: the response is fitted across all the photos.
  std::vector<Photo> photos;
  std::vector<CardView> views;
  std::vector<std::vector<ResponseSample>> samples;
  for (size_t i = 0; i < files.size(); ++i) {
    const std::string name = files[i].filename().string();
    const Photo& photo = photos.emplace_back(load(files[i]));
    const CardView view = locate_card(photo, focal, name);
    if (view.edge_width > options.max_edge_width_px)
      throw CaptureRejection(name + ": blurred (the tags' edges are " + std::to_string(view.edge_width) +
                             " px wide; hold the camera still, focus on the card)");
    if (!view.marker_turn)
      throw CaptureRejection(name + ": the swatch marker (tag 4, cut from the card's strip) is not on the swatch");
    samples.push_back(card_response_samples(photo, view));
    if (usable_samples(samples.back()) < 4)
      throw CaptureRejection(name + ": too few usable grey samples on the card (over- or under-exposed?)");
    views.push_back(view);
    if (progress) progress(0.5 * (i + 1) / files.size());
  }
  const std::vector<ResponseFit> responses = fit_shared_response(samples);

  for (size_t i = 0; i < files.size(); ++i) {
    const std::string name = files[i].filename().string();
    const Photo& photo = photos[i];
    const CardView& view = views[i];
    CapturedPhoto shot;
    shot.file = name;
    shot.turn = *view.marker_turn;
    shot.corner_tags = view.corner_tags;
    shot.reprojection_px = view.reprojection_rms;
    shot.edge_width_px = view.edge_width;
    shot.focal_estimated = view.focal_estimated;
    shot.camera_centre = view.camera.C;
    shot.response = responses[i];
    const ResponseModel& response = shot.response.model;

    // The swatch's cells: mean relative value and where they were seen from.
    const int cells_per_side = static_cast<int>(std::round(2 * card.swatch_radius / kCellMm));
    std::vector<glm::dvec3> sum(cells_per_side * cells_per_side, glm::dvec3(0)), where(sum.size(), glm::dvec3(0));
    std::vector<int> count(sum.size(), 0);
    long pixels = 0, clipped = 0;
    auto near_marker = [&](const glm::dvec3& w) { return glm::length(w - view.marker_centre) * 1000.0 < kMarkerClearMm; };
    const std::vector<glm::dvec3> box{window + glm::dvec3(-radius, -radius, 0), window + glm::dvec3(radius, -radius, 0),
                                      window + glm::dvec3(radius, radius, 0), window + glm::dvec3(-radius, radius, 0)};
    for_card_pixels(photo, view, box, [&](const glm::dvec3& w) { return glm::length(w - window) < radius && !near_marker(w); },
               [&](int x, int y, const glm::dvec3& w) {
                 const auto code = code_at(photo, x, y);
                 ++pixels;
                 clipped += std::max({code[0], code[1], code[2]}) >= 250;
                 const int cx = std::clamp(static_cast<int>((w.x - window.x + radius) * 1000.0 / kCellMm), 0, cells_per_side - 1);
                 const int cy = std::clamp(static_cast<int>((w.y - window.y + radius) * 1000.0 / kCellMm), 0, cells_per_side - 1);
                 const size_t c = static_cast<size_t>(cy) * cells_per_side + cx;
                 sum[c] += response.relative(code, image_radius2(photo, x + 0.5, y + 0.5));
                 where[c] += w;
                 ++count[c];
               });
    if (pixels == 0) throw CaptureRejection(name + ": the swatch window is outside the photo");
    if (static_cast<double>(clipped) / pixels > options.max_saturated)
      throw CaptureRejection(name + ": saturated (" + std::to_string(100.0 * clipped / pixels) +
                             " % of the swatch's pixels clipped; lower the exposure)");
    const int full = *std::max_element(count.begin(), count.end());
    for (size_t c = 0; c < sum.size(); ++c)
      if (count[c] >= 0.6 * full) {
        const glm::dvec3 p = where[c] / static_cast<double>(count[c]);
        result.observations.push_back({sum[c] / static_cast<double>(count[c]), glm::normalize(view.camera.C - p), shot.turn,
                                       static_cast<int>(i)});
        ++shot.cells;
      }

    // The panel for the report.
    shot.panel.resize(kPanel * kPanel);
    shot.panel_marker.resize(kPanel * kPanel);
    for (int py = 0; py < kPanel; ++py)
      for (int px = 0; px < kPanel; ++px) {
        const glm::dvec3 w = window + glm::dvec3((px + 0.5) / kPanel * 2 * radius - radius, radius - (py + 0.5) / kPanel * 2 * radius, 0);
        const glm::dvec2 q = view.to_image(w);
        const int x = std::clamp(static_cast<int>(q.x), 0, photo.width - 1), y = std::clamp(static_cast<int>(q.y), 0, photo.height - 1);
        shot.panel[py * kPanel + px] = response.relative(code_at(photo, x, y), image_radius2(photo, x + 0.5, y + 0.5));
        shot.panel_marker[py * kPanel + px] = near_marker(w);
      }

    // The ball's darker exposures, when the photographer bracketed it.
    const std::vector<BracketFile> bracket_files = list_brackets(files[i]);
    std::vector<Photo> brackets;
    for (const BracketFile& b : bracket_files) {
      brackets.push_back(load(b.file));
      if (brackets.back().width != photo.width || brackets.back().height != photo.height)
        throw CaptureRejection(b.file.filename().string() + ": not the size of " + name + ", which it brackets");
    }
    std::vector<BallExposure> exposures{{&photo, 0.0}};
    for (size_t k = 0; k < brackets.size(); ++k) exposures.push_back({&brackets[k], bracket_files[k].ev});
    BallView ball = read_ball(exposures, view, response);
    shot.brackets = static_cast<int>(brackets.size());
    shot.ball_clipped = ball.clipped_fraction;
    balls.push_back(std::move(ball));
    result.photos.push_back(std::move(shot));
    if (progress) progress(0.5 + 0.5 * (i + 1) / files.size());
  }
  std::vector<double> turns;
  for (const auto& p : result.photos) turns.push_back(p.turn);
  const int distinct = distinct_turns(turns);
  if (distinct < 3)
    throw CaptureRejection("too few swatch orientations: " + std::to_string(distinct) +
                           " distinct turns (at least 3, 20° apart; turn the swatch 30–60° between photos)");

  result.lighting = capture_lighting(balls);
  std::vector<Fabric> presets;
  for (const std::string& name : list_fabric_presets(presets_dir)) {
    Fabric f = load_fabric_preset(name, presets_dir);
    if (f.optical_thickness > 0) continue;  // a sheer's weave repeats an opaque preset's; the card cannot see through it
    presets.push_back(std::move(f));
  }
  // The close-up, read with the camera's response (its scale cancels in the clusters' ratio).
  std::optional<CloseupObservation> closeup;
  std::optional<Photo> closeup_photo_read;
  if (const auto file = closeup_photo(dir)) {
    result.closeup_file = file->filename().string();
    closeup_photo_read = load(*file);
    result.closeup = measure_closeup(*closeup_photo_read, result.photos.back().response.model, result.closeup_file);
    closeup = CloseupObservation{result.closeup->splits, result.photos.back().turn, result.closeup->level, {}};
    // The chosen family's lattice from the spectrum, and the close-up registered to its weave.
    if (result.closeup->spectrum)
      closeup->registered = [&](const Fabric& fitted) -> std::optional<CloseupObservation::Registered> {
        const WeaveLayout layout(fitted);
        result.thread_counts = weave_counts(*result.closeup->spectrum, layout.rows(), layout.shift());
        if (!result.thread_counts->candidate()) return std::nullopt;
        result.registration = register_closeup(*closeup_photo_read, result.photos.back().response.model, *result.closeup->scale,
                                               *result.thread_counts, fitted, result.lighting.lights, result.photos.back().turn);
        if (!result.registration->registered) return std::nullopt;
        std::optional<std::array<glm::dvec3, 2>> albedo;
        if (result.registration->albedo_read) albedo = result.registration->albedo;
        return CloseupObservation::Registered{result.registration->thread_mean, albedo, result.registration->explained};
      };
  }
  FabricFitOptions fit_options;
  if (options.open_progress) fit_options.progress = options.open_progress("fit");
  result.fit = fit_fabric(result.observations, result.lighting.lights, presets, fit_options, closeup);
  // The yarns' counts (the refit's registration read them for the chosen family) where the
  // close-up's spectrum resolves them or the close-up registers to them; the family's otherwise.
  if (result.counts_resolved()) {
    WeaveSpec& weave = result.fit.fabric.weave;
    weave.ends_per_cm = std::round(10.0 * result.thread_counts->ends_per_cm) / 10.0;
    weave.picks_per_cm = std::round(10.0 * result.thread_counts->picks_per_cm) / 10.0;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace weft
