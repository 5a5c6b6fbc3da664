#include "capture/capture_simulation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

#include <nlohmann/json.hpp>

#include "capture/capture_card.h"
#include "capture/capture_lighting.h"
#include "capture/card_camera.h"
#include "capture/card_samples.h"
#include "capture/closeup_simulation.h"
#include "capture/photo_files.h"
#include "capture/response_calibration.h"
#include "capture/simulated_camera.h"
#include "capture/swatch_frame.h"
#include "core/cloth_bsdf.h"
#include "probe/mock_probe_source.h"
#include "reference/environment_samples.h"

namespace weft {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSwatchHalf = 0.035;  // a 70 mm swatch
constexpr int kClothGrid = 9;          // view points across the swatch per side
constexpr int kBracketStep = 3;        // stops between the ball's bracketed exposures
constexpr int kMaxBrackets = 6;

struct Lights {
  std::vector<FitLight> above;  // the samples above the card's horizon
  glm::dvec3 irradiance{0.0};   // E at +Z
};

Lights lights_above(const EnvMap& map, int cells) {
  Lights l{simulated_swatch_lights(map, cells)};
  for (const FitLight& s : l.above) l.irradiance += s.power * s.direction.z;
  return l;
}

// The map as the ball's camera convention sees it (camera/mirror_ball.h: the camera looks along
// +Y, image x along +X, image y down along −Z), for a camera looking at the ball from `cam`.
EnvMap map_in_ball_frame(const EnvMap& map, const CardCamera& cam, const glm::dvec3& ball) {
  const glm::dvec3 forward = glm::normalize(ball - cam.C);
  const glm::dvec3 right = glm::normalize(cam.right() - glm::dot(cam.right(), forward) * forward);
  const glm::dvec3 up = glm::cross(right, forward);
  EnvMap out(2048, 1024);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const glm::dvec3 d = out.direction(x, y);
      out.at(x, y) = glm::vec3(map.lookup(d.x * right + d.y * forward + d.z * up));
    }
  return out;
}

}  // namespace

std::vector<FitLight> simulated_swatch_lights(const EnvMap& map, int light_cells) {
  std::vector<FitLight> above;
  for (const DirectionalSample& s : environment_samples(map, light_cells))
    if (s.direction.z > 0) above.push_back({s.direction, s.power});
  return above;
}

glm::dvec3 simulated_swatch_radiance(ClothBsdf::Point& point, const std::vector<FitLight>& lights, const glm::dvec3& wo) {
  glm::dvec3 sum(0);
  for (const FitLight& l : lights) sum += l.power * point.integrand(l.direction, wo);
  return sum;
}

void simulate_capture(const Fabric& fabric, const EnvMap& map, const CaptureSimulationOptions& options,
                      const std::filesystem::path& dir, const std::optional<std::filesystem::path>& truth_out) {
  if (options.photos < 1 || options.photos > 64) throw std::invalid_argument("photos must be in [1, 64]");
  if (options.width < 320 || options.height < 240) throw std::invalid_argument("photos must be at least 320×240");
  if (options.jpeg_quality < 1 || options.jpeg_quality > 100) throw std::invalid_argument("JPEG quality must be in [1, 100]");
  std::filesystem::create_directories(dir);
  const CaptureCard& card = capture_card();
  const SimulatedCamera truth_cam;
  const Lights lights = lights_above(map, options.light_cells);
  const glm::dvec3 white = lights.irradiance / kPi;  // radiance of a ρ = 1 diffuser
  // Exposure: the paper at half scale, leaving headroom for the cloth's highlights.
  const double k = 0.5 / (card.paper_reflectance * std::max({white.r, white.g, white.b}));
  const ClothBsdf bsdf(fabric, options.tangent_samples);
  const double f = 1.2 * options.width;
  const glm::dvec3 card_centre = card_to_world({card.width / 2, card.height / 2});
  const glm::dvec3 window_centre = card_to_world(card.swatch_window.centre());
  const glm::dvec3 ball = card_to_world(card.ball_centre) + glm::dvec3(0, 0, card.ball_radius / 1000.0);
  const double ball_r = card.ball_radius / 1000.0;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);

  nlohmann::ordered_json truth;
  truth["fabric"] = fabric.name;
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& t = fabric.threads[j];
    truth["threads"].push_back({{"albedo", {t.albedo.r, t.albedo.g, t.albedo.b}}, {"kd", t.kd},
                                {"gamma_s_deg", glm::degrees(t.gamma_s)}, {"gamma_v_deg", glm::degrees(t.gamma_v)}});
  }
  truth["response"] = {{"beta", truth_cam.response.beta}, {"vignetting", truth_cam.response.vignetting},
                       {"white_balance", {truth_cam.white_balance.r, truth_cam.white_balance.g, truth_cam.white_balance.b}}};

  const int w = options.width, h = options.height;
  std::atomic<int> rows_done{0};
  const int rows_total = w > 0 ? h * options.photos : 1;
  for (int i = 0; i < options.photos; ++i) {
    // A hand-held camera in front of the card's bottom edge, looking down at it.
    const double turn = kPi * i / options.photos;
    const double az = glm::radians(-90.0 + (i - (options.photos - 1) / 2.0) * 8.0 + 3.0 * jitter(rng));
    const double el = glm::radians(52.0 + 4.0 * jitter(rng));
    const double dist = 0.45 + 0.02 * jitter(rng);
    const glm::dvec3 target = card_centre + glm::dvec3(0.005 * jitter(rng), 0.005 * jitter(rng), 0);
    const glm::dvec3 centre = target + dist * glm::dvec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const CardCamera cam = CardCamera::look_at(w, h, f, centre, target, glm::radians(2.0 * jitter(rng)));
    const SurfaceFrame frame = swatch_frame(turn);
    const glm::dvec3 u = frame.u, v = frame.v;
    const glm::dvec3 marker = window_centre - v * (card.marker_offset / 1000.0);

    // The swatch's radiance on a grid of view points (it changes slowly across the swatch).
    std::vector<glm::dvec3> cloth(kClothGrid * kClothGrid);
#pragma omp parallel for schedule(dynamic)
    for (int g = 0; g < kClothGrid * kClothGrid; ++g) {
      const glm::dvec3 p = window_centre + glm::dvec3((g % kClothGrid) / (kClothGrid - 1.0) * 0.1 - 0.05,
                                                      (g / kClothGrid) / (kClothGrid - 1.0) * 0.1 - 0.05, 0);
      const glm::dvec3 wo = glm::normalize(cam.C - p);
      ClothBsdf::Point point = bsdf.at(frame);
      cloth[g] = simulated_swatch_radiance(point, lights.above, wo);
    }
    auto cloth_at = [&](const glm::dvec3& p) {
      const double gx = std::clamp((p.x - window_centre.x + 0.05) / 0.1 * (kClothGrid - 1), 0.0, kClothGrid - 1.001);
      const double gy = std::clamp((p.y - window_centre.y + 0.05) / 0.1 * (kClothGrid - 1), 0.0, kClothGrid - 1.001);
      const int x0 = static_cast<int>(gx), y0 = static_cast<int>(gy);
      const double ax = gx - x0, ay = gy - y0;
      auto at = [&](int x, int y) { return cloth[y * kClothGrid + x]; };
      return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x0 + 1, y0)) + ay * ((1 - ax) * at(x0, y0 + 1) + ax * at(x0 + 1, y0 + 1));
    };
    // Radiance of the card-plane point p (world).
    auto plane_radiance = [&](const glm::dvec3& p) -> glm::dvec3 {
      const glm::dvec3 d = p - window_centre;
      if (std::abs(glm::dot(d, u)) < kSwatchHalf && std::abs(glm::dot(d, v)) < kSwatchHalf) {
        const glm::dvec3 m = (p - marker) * 1000.0;
        const double r = tag_reflectance(card.swatch_marker.id, card.swatch_marker.size, {glm::dot(m, u), -glm::dot(m, v)});
        return r >= 0 ? r * white : cloth_at(p);
      }
      const double r = card_reflectance(world_to_card(p), false);
      return (r > 0 ? r : 0.2) * white;  // off the card: a grey table
    };

    // The ball, as the mock probe camera draws it, in a box around its image.
    const auto ball_px = cam.project(ball);
    const double ball_dist = glm::length(ball - cam.C);
    const double r_px = f * ball_r / std::sqrt(ball_dist * ball_dist - ball_r * ball_r);
    const int box = 2 * static_cast<int>(std::ceil(r_px)) + 4;
    const int ox = static_cast<int>(std::floor(ball_px->x)) - box / 2, oy = static_cast<int>(std::floor(ball_px->y)) - box / 2;
    MockCameraOptions mock;
    mock.width = mock.height = box;
    mock.ball = MirrorBall{ball_px->x - ox, ball_px->y - oy, r_px};
    mock.calibration.response = truth_cam.response.curve();
    mock.calibration.radiance_scale = k;
    mock.background_radiance = 0;
    mock.seed = options.seed * 131 + i;
    MockProbeSource ball_camera(map_in_ball_frame(map, cam, ball), mock);
    ball_camera.open();
    const CameraResponse curve = truth_cam.response.curve();
    // The photo at `exposure` times the metered one: the card and cloth scaled, the ball as the
    // mock camera takes it at that exposure (clipping where it does).
    auto shoot = [&](double exposure, int shot_index, bool count_progress) {
      const ProbeFrame ball_frame = ball_camera.capture(ProbeExposure{exposure, 1.0});
      auto ball_linear = [&](int x, int y) {
        const int bx = std::clamp(x - ox, 0, box - 1), by = std::clamp(y - oy, 0, box - 1);
        const size_t q = (static_cast<size_t>(by) * box + bx) * 3;
        return glm::dvec3(mock.calibration.response.decode(ball_frame.rgb[q]), mock.calibration.response.decode(ball_frame.rgb[q + 1]),
                          mock.calibration.response.decode(ball_frame.rgb[q + 2]));
      };
      Photo photo{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 3)};
#pragma omp parallel for schedule(dynamic, 8)
      for (int y = 0; y < h; ++y) {
        std::mt19937_64 noise_rng(options.seed * 7919 + static_cast<std::uint64_t>(shot_index) * 100003 + y);
        std::normal_distribution<double> unit(0.0, 1.0);
        for (int x = 0; x < w; ++x) {
          // 2×2 samples: tag edges need their partial pixels for the detector's edge fit.
          glm::dvec3 linear(0);
          int on_ball = 0;
          for (int s = 0; s < 4; ++s) {
            const double sx = x + 0.25 + 0.5 * (s & 1), sy = y + 0.25 + 0.5 * (s >> 1);
            if (cam.sees_sphere(sx, sy, ball, ball_r)) {
              ++on_ball;
              continue;
            }
            if (const auto p = cam.on_card(sx, sy)) linear += exposure * k * plane_radiance(*p);
          }
          linear = (linear + static_cast<double>(on_ball) * ball_linear(x, y)) / 4.0;
          const auto code = truth_cam.develop(linear, image_radius2(photo, x + 0.5, y + 0.5), curve, noise_rng, unit);
          std::copy(code.begin(), code.end(), &photo.rgb[(static_cast<size_t>(y) * w + x) * 3]);
        }
        if (count_progress) {
          const int done = ++rows_done;
          if (options.progress && done % 64 == 0) {
#pragma omp critical
            options.progress(static_cast<double>(done) / rows_total);
          }
        }
      }
      // The ball's pixels that a fit would take as clipped.
      int ball_clipped = 0;
      for (int y = std::max(0, oy); y < std::min(h, oy + box); ++y)
        for (int x = std::max(0, ox); x < std::min(w, ox + box); ++x) {
          const double a = (x + 0.5 - ball_px->x) / r_px, b = (y + 0.5 - ball_px->y) / r_px;
          const std::uint8_t* q = &photo.rgb[(static_cast<size_t>(y) * w + x) * 3];
          ball_clipped += a * a + b * b < 1 && std::max({q[0], q[1], q[2]}) >= kBallClipCode;
        }
      return std::pair(std::move(photo), ball_clipped);
    };
    // The photographer's exposure: whole stops down from the metered one until the swatch's
    // brightest point sits below 90 % of full scale (a satin facing a lamp outshines the paper
    // many times; the fit refuses a clipped swatch).
    double peak = 0;
    for (const glm::dvec3& c : cloth) {
      const glm::dvec3 linear = k * c * truth_cam.white_balance;
      peak = std::max({peak, linear.r, linear.g, linear.b});
    }
    const int stops_down = std::min(10, stops_to_fit(peak));
    const double exposure = std::exp2(-stops_down);
    char name[32];
    std::snprintf(name, sizeof name, "photo_%02d.jpg", i + 1);
    auto [photo, clipped] = shoot(exposure, i, true);
    write_jpeg(photo, dir / name, options.jpeg_quality, truth_cam.jpeg_chroma);
    // Darker exposures, kBracketStep stops apart, until the ball's highlights are no longer
    // clipped, as a photographer brackets them.
    int brackets = 0;
    for (int ev = -kBracketStep; options.bracket_ball && clipped > 0 && ev >= -kBracketStep * kMaxBrackets; ev -= kBracketStep) {
      auto [dark, dark_clipped] = shoot(exposure * std::exp2(ev), i + options.photos * (-ev / kBracketStep), false);
      write_jpeg(dark, bracket_path(dir / name, ev), options.jpeg_quality, truth_cam.jpeg_chroma);
      clipped = dark_clipped;
      ++brackets;
    }
    nlohmann::ordered_json shot;
    shot["file"] = name;
    shot["turn_deg"] = glm::degrees(turn);
    shot["ball_brackets"] = brackets;
    shot["exposure_stops"] = -stops_down;
    shot["camera_centre"] = {cam.C.x, cam.C.y, cam.C.z};
    truth["photos"].push_back(shot);
  }
  if (options.closeup) {
    // Straight above the swatch, right after the last photo (the swatch not turned since).
    CloseupSimulationOptions closeup;  // the camera's macro mode, at its own size
    closeup.turn = kPi * (options.photos - 1) / options.photos;
    closeup.exposure_scale = k;
    closeup.tangent_samples = options.tangent_samples;
    closeup.seed = options.seed;
    const std::string name = std::string(kCloseupStem) + ".jpg";
    const SimulatedCloseup shot = simulate_closeup(fabric, lights.above, truth_cam, closeup);
    write_jpeg(shot.photo, dir / name, options.jpeg_quality, truth_cam.jpeg_chroma);
    const glm::dvec3& q = shot.warp_over_weft;
    truth["closeup"] = {{"file", name}, {"turn_deg", glm::degrees(closeup.turn)}, {"field_mm", closeup.field_mm},
                        {"warp_over_weft", {q.r, q.g, q.b}}};
  }
  CaptureInfo info{w, h, std::nullopt};
  if (options.record_focal) info.focal_px = f;
  write_capture_info(info, dir / "capture.json");
  if (truth_out) std::ofstream(*truth_out) << truth.dump(2) << "\n";
  if (options.progress) options.progress(1.0);
}

}  // namespace weft
