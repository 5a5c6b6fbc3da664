#pragma once
// Looks between two AppearanceStates: the kiosk's way home when nobody is at the panel
// (render/kiosk/idle_return.h). Every field's rule sits here, so a new knob says in one place how
// it eases.
#include <algorithm>
#include <cmath>

#include "panel/appearance_state.h"

namespace weft::input {

// The look a fraction t ∈ [0, 1] of the way from `from` to `to`: thread albedos in linear RGB,
// gloss (γ scale) geometrically, the light's turn along the shorter arc, the zoom linearly. A
// different preset or colourway cannot be blended (another fabric): `to` at once. The thread
// selection is an on-screen hint: `to`'s.
inline AppearanceState blend_appearance(const AppearanceState& from, const AppearanceState& to, double t) {
  if (from.preset_index != to.preset_index || from.colourway != to.colourway || !(t < 1.0)) return to;
  t = std::max(t, 0.0);
  AppearanceState out = to;
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

}  // namespace weft::input
