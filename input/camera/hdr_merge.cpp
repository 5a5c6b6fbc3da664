#include "camera/hdr_merge.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace weft {

glm::vec3 HdrImage::sample(double x, double y) const {
  const double fx = std::clamp(x - 0.5, 0.0, width - 1.0);
  const double fy = std::clamp(y - 0.5, 0.0, height - 1.0);
  const int x0 = std::min(static_cast<int>(fx), width - 2 < 0 ? 0 : width - 2);
  const int y0 = std::min(static_cast<int>(fy), height - 2 < 0 ? 0 : height - 2);
  const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
  const float tx = static_cast<float>(fx - x0), ty = static_cast<float>(fy - y0);
  return (at(x0, y0) * (1 - tx) + at(x1, y0) * tx) * (1 - ty) + (at(x0, y1) * (1 - tx) + at(x1, y1) * tx) * ty;
}

namespace {

// A code this high may be clipped (the ISP's curve and noise blur the top): such samples are
// left out and the shorter frames measure the pixel.
constexpr uint8_t kClipped = 250;

}  // namespace

HdrImage merge_bracket(std::span<const ProbeFrame> bracket, const CameraCalibration& calibration,
                       const MirrorBall& ball, BracketStats* stats) {
  if (bracket.empty()) throw ProbeError(ProbeFailure::bad_frame, "empty exposure bracket");
  const int w = bracket[0].width, h = bracket[0].height;
  for (const auto& f : bracket)
    if (f.width != w || f.height != h || f.stride < 3 * w || f.rgb.size() < static_cast<size_t>(f.stride) * h)
      throw ProbeError(ProbeFailure::bad_frame, "frames of the bracket differ in size or are truncated");
  if (ball.radius <= 0 || ball.centre_x - ball.radius < 0 || ball.centre_y - ball.radius < 0 ||
      ball.centre_x + ball.radius > w || ball.centre_y + ball.radius > h)
    throw ProbeError(ProbeFailure::bad_frame, "the configured mirror ball (centre " + std::to_string(ball.centre_x) + ", " +
                                                  std::to_string(ball.centre_y) + ", radius " + std::to_string(ball.radius) +
                                                  ") does not fit in the " + std::to_string(w) + "×" + std::to_string(h) + " frame");

  // Radiance per unit linear sensor value, for each frame.
  std::vector<double> scale;
  size_t shortest = 0, longest = 0;
  for (size_t i = 0; i < bracket.size(); ++i) {
    const double exposure = bracket[i].exposure.exposure_s * bracket[i].exposure.analogue_gain;
    if (!(exposure > 0)) throw ProbeError(ProbeFailure::bad_frame, "a frame reports a non-positive exposure");
    scale.push_back(1.0 / (calibration.ball_reflectance * calibration.radiance_scale * exposure));
    if (scale[i] > scale[shortest]) shortest = i;
    if (scale[i] < scale[longest]) longest = i;
  }

  HdrImage image;
  image.width = w;
  image.height = h;
  image.radiance.assign(static_cast<size_t>(w) * h, glm::vec3(0));
  const int x0 = static_cast<int>(ball.centre_x - ball.radius), x1 = static_cast<int>(std::ceil(ball.centre_x + ball.radius));
  const int y0 = static_cast<int>(ball.centre_y - ball.radius), y1 = static_cast<int>(std::ceil(ball.centre_y + ball.radius));
  size_t on_ball = 0, black = 0, saturated = 0;
  std::vector<float> peaks;
  const double r2 = ball.radius * ball.radius;
  for (int y = y0; y < std::min(y1, h); ++y)
    for (int x = x0; x < std::min(x1, w); ++x) {
      // Σ sensor values / Σ exposures over the unclipped frames: each frame weighted by its
      // exposure, which is what shot noise makes optimal. Dark codes are kept (even 0): leaving
      // out the samples that noise pushed low would bias dim pixels up.
      glm::vec3 sum(0), weight(0);
      for (size_t i = 0; i < bracket.size(); ++i) {
        const uint8_t* p = bracket[i].pixel(x, y);
        for (int c = 0; c < 3; ++c) {
          if (p[c] >= kClipped) continue;
          sum[c] += static_cast<float>(calibration.response.decode(p[c]));
          weight[c] += static_cast<float>(1.0 / scale[i]);
        }
      }
      const uint8_t* ps = bracket[shortest].pixel(x, y);
      const uint8_t* pl = bracket[longest].pixel(x, y);
      glm::vec3 L;
      for (int c = 0; c < 3; ++c) {
        if (weight[c] > 0) L[c] = sum[c] / weight[c];
        else if (ps[c] >= kClipped) L[c] = static_cast<float>(calibration.response.decode(ps[c]) * scale[shortest]);  // a lower bound
        else L[c] = static_cast<float>(calibration.response.decode(pl[c]) * scale[longest]);
      }
      image.radiance[static_cast<size_t>(y) * w + x] = L;
      const double dx = x + 0.5 - ball.centre_x, dy = y + 0.5 - ball.centre_y;
      if (dx * dx + dy * dy > r2) continue;
      ++on_ball;
      if (pl[0] <= 2 && pl[1] <= 2 && pl[2] <= 2) ++black;
      if (ps[0] >= kClipped || ps[1] >= kClipped || ps[2] >= kClipped) ++saturated;
      peaks.push_back(static_cast<float>(calibration.response.decode(std::max({ps[0], ps[1], ps[2]}))));
    }
  BracketStats s;
  if (on_ball > 0) {
    s.black_fraction = static_cast<double>(black) / on_ball;
    s.saturated_fraction = static_cast<double>(saturated) / on_ball;
    s.peak_sensor = *std::max_element(peaks.begin(), peaks.end());
  }
  if (stats) *stats = s;
  if (s.black_fraction > 0.98)
    throw ProbeError(ProbeFailure::bad_frame, "black frames (" + std::to_string(static_cast<int>(100 * s.black_fraction)) +
                                                  " % of the ball dark even at the longest exposure: lens cap, lights off or a dead sensor?)");
  if (s.saturated_fraction > 0.5)
    throw ProbeError(ProbeFailure::bad_frame, "saturated frames (" + std::to_string(static_cast<int>(100 * s.saturated_fraction)) +
                                                  " % of the ball clipped even at the shortest exposure)");
  return image;
}

}  // namespace weft
