#include "capture/closeup_simulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "capture/capture_card.h"
#include "capture/card_samples.h"
#include "capture/float_radiance.h"
#include "capture/swatch_frame.h"
#include "core/weave_layout.h"

namespace weft {

namespace {

constexpr int kArcBins = 128;    // along each float: its tilt, so its shading, changes smoothly
constexpr int kSupersample = 3;  // per side: the yarns' edges are partial pixels, as a lens draws them

}  // namespace

SimulatedCloseup simulate_closeup(const Fabric& fabric, const std::vector<FitLight>& lights, const SimulatedCamera& camera,
                       const CloseupSimulationOptions& options) {
  const double t = options.turn;
  const SurfaceFrame frame = swatch_frame(t);
  const glm::dvec3 u = frame.u, v = frame.v;
  const FloatRadiance along = float_radiance(fabric, lights, t, kArcBins, options.tangent_samples);

  std::mt19937_64 rng(options.seed * 104729 + 17);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double roll = 2 * std::numbers::pi * uniform(rng);
  const glm::dvec2 phase(uniform(rng), uniform(rng));
  const WeaveLayout layout(fabric);
  const glm::dvec2 repeat_mm = 10.0 * weave_repeat_cm(fabric);
  const int w = options.width, h = options.height;
  const double mm_per_px = options.field_mm / w;
  // The tag: in a random corner, far enough in that all of its paper is in the frame; its axes are
  // the warp's and the weft's as the frame sees them (image y up here, as the card's plane).
  const CardTag& tag = capture_card().closeup_tag;
  const int corner = static_cast<int>(uniform(rng) * 4) % 4;
  // The paper's half-extent along the frame's axes at this angle (its side is 1.25 of the tag's).
  const double inset = 0.625 * tag.size * (std::abs(std::cos(t - roll)) + std::abs(std::sin(t - roll))) + 0.1;
  const glm::dvec2 tag_centre((corner & 1 ? 1 : -1) * (0.5 * options.field_mm - inset),
                              (corner & 2 ? 1 : -1) * (0.5 * h * mm_per_px - inset));
  const glm::dvec2 warp_dir(std::cos(t - roll), std::sin(t - roll)), weft_dir(-warp_dir.y, warp_dir.x);
  glm::dvec3 white(0);  // radiance of a ρ = 1 diffuser
  for (const FitLight& l : lights) white += l.power * std::max(l.direction.z, 0.0) / std::numbers::pi;
  std::vector<glm::dvec3> linear(static_cast<size_t>(w) * h);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec3 sum(0);
      for (int s = 0; s < kSupersample * kSupersample; ++s) {
        const double px = (x + (s % kSupersample + 0.5) / kSupersample - 0.5 * w) * mm_per_px;
        const double py = (0.5 * h - y - (s / kSupersample + 0.5) / kSupersample) * mm_per_px;
        if (options.scale_tag) {
          const glm::dvec2 m = glm::dvec2(px, py) - tag_centre;
          const double r = tag_reflectance(tag.id, tag.size, {glm::dot(m, warp_dir), -glm::dot(m, weft_dir)});
          if (r >= 0) {
            sum += r * white;
            continue;
          }
        }
        const glm::dvec3 p(px * std::cos(roll) - py * std::sin(roll), px * std::sin(roll) + py * std::cos(roll), 0);
        const WeaveSample at = layout.at(glm::dot(p, u) / repeat_mm.x + phase.x, glm::dot(p, v) / repeat_mm.y + phase.y);
        if (at.thread >= 0) sum += along[at.thread][arc_bin(at.arc, kArcBins)];
      }
      linear[static_cast<size_t>(y) * w + x] = options.exposure_scale * sum / double(kSupersample * kSupersample);
    }

  std::vector<double> peaks;
  for (const glm::dvec3& l : linear) {
    const glm::dvec3 balanced = l * camera.white_balance;
    peaks.push_back(std::max({balanced.r, balanced.g, balanced.b}));
  }
  std::nth_element(peaks.begin(), peaks.begin() + peaks.size() * 995 / 1000, peaks.end());
  const double peak = peaks[peaks.size() * 995 / 1000];
  const double exposure = std::exp2(-stops_to_fit(peak));

  SimulatedCloseup out;
  glm::dvec3 warp(0), weft(0);
  for (int b = 0; b < kArcBins; ++b) {
    warp += along[0][b];
    weft += along[1][b];
  }
  out.warp_over_weft = warp / glm::max(weft, glm::dvec3(1e-300));
  Photo& photo = out.photo;
  photo = Photo{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 3)};
  const CameraResponse curve = camera.response.curve();
#pragma omp parallel for schedule(static)
  for (int y = 0; y < h; ++y) {
    std::mt19937_64 noise_rng(options.seed * 6151 + static_cast<std::uint64_t>(y));
    std::normal_distribution<double> unit(0.0, 1.0);
    for (int x = 0; x < w; ++x) {
      const auto code = camera.develop(exposure * linear[static_cast<size_t>(y) * w + x], image_radius2(photo, x + 0.5, y + 0.5),
                                       curve, noise_rng, unit);
      std::copy(code.begin(), code.end(), &photo.rgb[(static_cast<size_t>(y) * w + x) * 3]);
    }
  }
  return out;
}

}  // namespace weft
