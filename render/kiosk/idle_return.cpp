#include "kiosk/idle_return.h"

#include <algorithm>
#include <cmath>

namespace weft {

input::AppearanceState blend_appearance(const input::AppearanceState& from, const input::AppearanceState& to, double t) {
  if (from.preset_index != to.preset_index || from.colourway != to.colourway || !(t < 1.0)) return to;
  t = std::max(t, 0.0);
  input::AppearanceState out = to;
  for (int j = 0; j < 2; ++j) {
    for (int c = 0; c < 3; ++c)
      out.thread[j].albedo[c] = float((1.0 - t) * from.thread[j].albedo[c] + t * to.thread[j].albedo[c]);
    const double a = std::max(double(from.thread[j].gamma_scale), 1e-6), b = std::max(double(to.thread[j].gamma_scale), 1e-6);
    out.thread[j].gamma_scale = float(a * std::pow(b / a, t));
  }
  double turn = std::fmod(double(to.env_rotation_deg) - double(from.env_rotation_deg), 360.0);
  if (turn > 180.0) turn -= 360.0;
  if (turn < -180.0) turn += 360.0;
  double rotation = std::fmod(double(from.env_rotation_deg) + t * turn, 360.0);
  if (rotation < 0.0) rotation += 360.0;
  out.env_rotation_deg = float(rotation);
  out.zoom = float((1.0 - t) * from.zoom + t * to.zoom);
  return out;
}

bool same_appearance(const input::AppearanceState& a, const input::AppearanceState& b) {
  for (int j = 0; j < 2; ++j) {
    for (int c = 0; c < 3; ++c)
      if (a.thread[j].albedo[c] != b.thread[j].albedo[c]) return false;
    if (a.thread[j].gamma_scale != b.thread[j].gamma_scale) return false;
  }
  return a.preset_index == b.preset_index && a.colourway == b.colourway && a.env_rotation_deg == b.env_rotation_deg &&
         a.zoom == b.zoom && a.selection == b.selection;
}

IdleReturn::IdleReturn(double idle_seconds, double ease_seconds)
    : idle_seconds_(idle_seconds), ease_seconds_(std::max(ease_seconds, 0.0)) {}

void IdleReturn::touched(Clock::time_point now) {
  last_touch_ = now;
  home_ = false;
  easing_ = false;
}

bool IdleReturn::due(Clock::time_point now) const {
  return idle_seconds_ > 0.0 && !home_ && !easing_ && std::chrono::duration<double>(now - last_touch_).count() >= idle_seconds_;
}

void IdleReturn::start(const input::AppearanceState& from, const input::AppearanceState& home, Clock::time_point now) {
  from_ = from;
  home_state_ = home;
  ease_start_ = now;
  easing_ = !same_appearance(from, home);  // already home: nothing to redraw
  home_ = true;
}

std::optional<input::AppearanceState> IdleReturn::step(Clock::time_point now) {
  if (!easing_) return std::nullopt;
  const double t = ease_seconds_ > 0.0 ? std::chrono::duration<double>(now - ease_start_).count() / ease_seconds_ : 1.0;
  if (t >= 1.0) easing_ = false;
  // Smoothstep: the look leaves and arrives gently.
  const double s = std::clamp(t, 0.0, 1.0);
  return blend_appearance(from_, home_state_, t >= 1.0 ? 1.0 : s * s * (3.0 - 2.0 * s));
}

}  // namespace weft
