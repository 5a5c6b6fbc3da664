#include "capture/capture_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "camera/hdr_merge.h"
#include "capture/capture_card.h"
#include "lighting/sg_fit.h"
#include "probe/mirror_ball_unwrap.h"
#include "reference/environment_samples.h"

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;

glm::dvec3 irradiance_up(const EnvMap& map) {
  glm::dvec3 e(0);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const double z = map.direction(x, y).z;
      if (z > 0) e += glm::dvec3(map.at(x, y)) * (z * map.solid_angle(y));
    }
  return e;
}
}  // namespace

BallView read_ball(const Photo& photo, const CardView& view, const ResponseModel& response) {
  const CaptureCard& card = capture_card();
  const CardCamera& cam = view.camera;
  const double R = card.ball_radius / 1000.0;
  const glm::dvec3 ball = card_to_world(card.ball_centre) + glm::dvec3(0, 0, R);
  const auto centre = cam.project(ball);
  if (!centre) throw std::runtime_error("the mirror ball is behind the camera");
  const double d = glm::length(ball - cam.C);
  const double r_px = cam.f * R / std::sqrt(d * d - R * R);
  HdrImage image{photo.width, photo.height, std::vector<glm::vec3>(static_cast<size_t>(photo.width) * photo.height, glm::vec3(0))};
  const double half_diag2 = (photo.width * photo.width + photo.height * photo.height) / 4.0;
  int on_ball = 0, clipped = 0;
  const int x0 = std::max(0, static_cast<int>(centre->x - r_px - 2)), x1 = std::min(photo.width, static_cast<int>(centre->x + r_px + 3));
  const int y0 = std::max(0, static_cast<int>(centre->y - r_px - 2)), y1 = std::min(photo.height, static_cast<int>(centre->y + r_px + 3));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::array<std::uint8_t, 3> code{photo.at(x, y, 0), photo.at(x, y, 1), photo.at(x, y, 2)};
      const double r2 = ((x + 0.5 - photo.width / 2.0) * (x + 0.5 - photo.width / 2.0) +
                         (y + 0.5 - photo.height / 2.0) * (y + 0.5 - photo.height / 2.0)) / half_diag2;
      image.radiance[static_cast<size_t>(y) * photo.width + x] = glm::vec3(response.relative(code, r2));
      const double a = (x + 0.5 - centre->x) / r_px, b = (y + 0.5 - centre->y) / r_px;
      if (a * a + b * b < 1) {
        ++on_ball;
        clipped += std::max({code[0], code[1], code[2]}) >= 250;
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

CaptureLighting capture_lighting(const std::vector<BallView>& balls, int sg_count) {
  if (balls.empty()) throw std::invalid_argument("capture_lighting: no ball views");
  CaptureLighting out;
  out.map = EnvMap(balls[0].map.width, balls[0].map.height);
  for (const BallView& b : balls)
    for (size_t i = 0; i < out.map.texels.size(); ++i) out.map.texels[i] += b.map.texels[i] / static_cast<float>(balls.size());
  const glm::dvec3 e = irradiance_up(out.map);
  const glm::dvec3 to_units = kPi / glm::max(e, glm::dvec3(1e-9));
  for (auto& t : out.map.texels) t *= glm::vec3(to_units);
  SgFitOptions fit;
  fit.count = sg_count;
  fit.grid_width = 128;
  out.sgs = fit_sgs(out.map, fit);
  // The SGs as directional lights: their map cut into cells, each at its power's centroid.
  EnvMap sg_map(256, 128);
  for (int y = 0; y < sg_map.height; ++y)
    for (int x = 0; x < sg_map.width; ++x) sg_map.at(x, y) = glm::vec3(evaluate(out.sgs, sg_map.direction(x, y)));
  glm::dvec3 e_sg(0);
  for (const DirectionalSample& s : environment_samples(sg_map, 32))
    if (s.direction.z > 0) {
      out.lights.push_back({s.direction, s.power});
      e_sg += s.power * s.direction.z;
    }
  // The fit keeps the card's irradiance, which the grey patches measured, exactly.
  const glm::dvec3 fix = kPi / glm::max(e_sg, glm::dvec3(1e-9));
  for (auto& l : out.lights) l.power *= fix;
  for (auto& g : out.sgs) g.amplitude *= fix;
  return out;
}

}  // namespace weft
