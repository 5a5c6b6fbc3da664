#include "capture/capture_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>

#include "camera/hdr_merge.h"
#include "capture/capture_card.h"
#include "capture/card_samples.h"
#include "capture/light_cells.h"
#include "lighting/fit_error.h"
#include "probe/mirror_ball_unwrap.h"

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

BallView read_ball(const std::vector<BallExposure>& exposures, const CardView& view, const ResponseModel& response) {
  if (exposures.empty()) throw std::invalid_argument("read_ball: no exposures");
  const Photo& photo = *exposures[0].photo;
  const CaptureCard& card = capture_card();
  const CardCamera& cam = view.camera;
  const double R = card.ball_radius / 1000.0;
  const glm::dvec3 ball = card_to_world(card.ball_centre) + glm::dvec3(0, 0, R);
  const auto centre = cam.project(ball);
  if (!centre) throw std::runtime_error("the mirror ball is behind the camera");
  const double d = glm::length(ball - cam.C);
  const double r_px = cam.f * R / std::sqrt(d * d - R * R);
  HdrImage image{photo.width, photo.height, std::vector<glm::vec3>(static_cast<size_t>(photo.width) * photo.height, glm::vec3(0))};
  int on_ball = 0, clipped = 0;
  const int x0 = std::max(0, static_cast<int>(centre->x - r_px - 2)), x1 = std::min(photo.width, static_cast<int>(centre->x + r_px + 3));
  const int y0 = std::max(0, static_cast<int>(centre->y - r_px - 2)), y1 = std::min(photo.height, static_cast<int>(centre->y + r_px + 3));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const double r2 = image_radius2(photo, x + 0.5, y + 0.5);
      // Each exposure's value scaled back to the photo's, weighted by its exposure squared (the
      // codes' noise is about constant, so a longer exposure measures better); clipped codes, and
      // JPEG's ringing just below them, say only that the value is higher.
      glm::dvec3 sum(0);
      double weight = 0;
      glm::dvec3 darkest(0);
      for (const BallExposure& e : exposures) {
        const std::array<std::uint8_t, 3> code{e.photo->at(x, y, 0), e.photo->at(x, y, 1), e.photo->at(x, y, 2)};
        const double t = std::exp2(e.ev);
        darkest = response.relative(code, r2) / t;
        if (std::max({code[0], code[1], code[2]}) >= kBallClipCode) continue;
        sum += t * t * darkest;
        weight += t * t;
      }
      const bool all_clipped = weight == 0;
      image.radiance[static_cast<size_t>(y) * photo.width + x] = glm::vec3(all_clipped ? darkest : sum / weight);
      const double a = (x + 0.5 - centre->x) / r_px, b = (y + 0.5 - centre->y) / r_px;
      if (a * a + b * b < 1) {
        ++on_ball;
        clipped += all_clipped;
      }
    }
  // Unwrapped in the ball's camera convention (camera/mirror_ball.h), then turned into the world:
  // the convention's +X is the camera's right, +Y its view of the ball, +Z the up between them.
  const MirrorBall mb{centre->x, centre->y, r_px};
  const EnvMap local = unwrap_mirror_ball(image, mb, 128, 64);
  const glm::dvec3 forward = glm::normalize(ball - cam.C);
  const glm::dvec3 right = glm::normalize(cam.right() - glm::dot(cam.right(), forward) * forward);
  const glm::dvec3 up = glm::cross(right, forward);
  BallView out{EnvMap(128, 64), on_ball ? static_cast<double>(clipped) / on_ball : 1.0};
  for (int y = 0; y < out.map.height; ++y)
    for (int x = 0; x < out.map.width; ++x) {
      const glm::dvec3 w = out.map.direction(x, y);
      out.map.at(x, y) = glm::vec3(local.lookup({glm::dot(w, right), glm::dot(w, forward), glm::dot(w, up)}));
    }
  return out;
}

CaptureLighting capture_lighting(const std::vector<BallView>& balls, const LightCellOptions& cells) {
  if (balls.empty()) throw std::invalid_argument("capture_lighting: no ball views");
  CaptureLighting out;
  out.map = EnvMap(balls[0].map.width, balls[0].map.height);
  for (const BallView& b : balls)
    for (size_t i = 0; i < out.map.texels.size(); ++i) out.map.texels[i] += b.map.texels[i] / static_cast<float>(balls.size());
  const glm::dvec3 up(0, 0, 1);
  const glm::dvec3 e = irradiance(out.map, std::span(&up, 1))[0];
  const glm::dvec3 to_units = kPi / glm::max(e, glm::dvec3(1e-9));
  for (auto& t : out.map.texels) t *= glm::vec3(to_units);
  // The ball's own radiance as directional lights, as the reference renderer takes a map: a
  // sharp highlight keeps its direction and spread, which a few SGs would blur.
  out.lights = light_cells(out.map, cells);
  return out;
}

}  // namespace weft
