#include "panel/knob_mapping.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "panel/hsv_color.h"

namespace weft::input {
namespace {

int wrap(int v, int period) { return ((v % period) + period) % period; }
bool edits(ThreadSelection s, int thread) {
  return s == ThreadSelection::both || static_cast<int>(s) == thread + 1;
}

}  // namespace

KnobMapper::KnobMapper(std::vector<PresetLook> presets, MappingConfig config)
    : presets_(std::move(presets)), config_(config) {
  if (presets_.empty()) throw std::invalid_argument("KnobMapper needs at least one fabric preset");
}

int KnobMapper::brightness_max_steps(int thread) const {
  const auto& a = presets_[positions_.preset].albedo[thread];
  const double v = std::max({a[0], a[1], a[2]});
  if (!(v > 0) || v >= 1) return 0;
  return static_cast<int>(std::floor(config_.brightness_steps_per_octave * std::log2(1.0 / v) + 1e-9));
}

int KnobMapper::accelerated(int dial, int detents, uint32_t time_ms) {
  const int direction = detents > 0 ? 1 : -1;
  const uint32_t dt = time_ms - last_time_[dial];
  int factor = 1;
  if (direction == last_direction_[dial]) {
    if (dt < config_.accel_x4_ms) factor = 4;
    else if (dt < config_.accel_x2_ms) factor = 2;
  }
  last_time_[dial] = time_ms;
  last_direction_[dial] = direction;
  return detents * factor;
}

void KnobMapper::set_colourways(std::vector<ColourwayPresets> colourways) {
  for (const auto& c : colourways)
    if (c.presets.size() != presets_.size()) throw std::invalid_argument("colourway '" + c.name + "': its presets differ in number");
  colourways_ = std::move(colourways);
  if (!colourways_.empty()) wear_colourway(0);
}

std::vector<std::string> KnobMapper::colourway_names() const {
  std::vector<std::string> names;
  for (const auto& c : colourways_) names.push_back(c.name);
  return names;
}

void KnobMapper::wear_colourway(uint32_t index) {
  positions_.colourway = index;
  presets_ = colourways_.at(index).presets;
  select_preset(colourways_[index].start_preset);
}

void KnobMapper::select_preset(uint32_t index) {
  const ThreadSelection keep = positions_.selection;
  const int zoom = positions_.zoom_steps;
  const uint32_t colourway = positions_.colourway;
  positions_ = KnobPositions{};
  positions_.colourway = colourway;
  positions_.preset = index;
  positions_.selection = keep;
  positions_.zoom_steps = zoom;
}

void KnobMapper::clamp() {
  auto& p = positions_;
  if (colourways_.empty()) {
    p.colourway = 0;
  } else {
    if (p.colourway >= colourways_.size()) p.colourway = 0;
    presets_ = colourways_[p.colourway].presets;
  }
  if (p.preset >= presets_.size()) p.preset = 0;
  if (static_cast<uint8_t>(p.selection) > 2) p.selection = ThreadSelection::both;
  const int hue_period = static_cast<int>(std::lround(360.0 / config_.hue_deg_per_step));
  const int env_period = static_cast<int>(std::lround(360.0 / config_.env_deg_per_step));
  for (int t = 0; t < 2; ++t) {
    p.hue_steps[t] = wrap(p.hue_steps[t], hue_period);
    p.brightness_steps[t] = std::clamp(p.brightness_steps[t], config_.brightness_min_steps, brightness_max_steps(t));
    p.gloss_steps[t] = std::clamp(p.gloss_steps[t], -config_.gloss_limit_steps, config_.gloss_limit_steps);
  }
  p.env_steps = wrap(p.env_steps, env_period);
  p.zoom_steps = std::clamp(p.zoom_steps, 0, std::max(config_.zoom_steps, 0));
}

bool KnobMapper::apply(const KnobEvent& event) {
  const KnobPositions before = positions_;
  auto& p = positions_;
  p.zoom_steps += event.zoom;
  for (int d = 0; d < kDialCount; ++d) {
    if (event.dial[d] == 0) continue;
    const int steps = accelerated(d, event.dial[d], event.time_ms);
    if (d == config_.zoom_dial) {
      p.zoom_steps += steps;
      continue;
    }
    for (int t = 0; t < 2; ++t) {
      if (!edits(p.selection, t)) continue;
      if (d == 0) p.hue_steps[t] += steps;
      if (d == 1) p.brightness_steps[t] += steps;
      if (d == 2) p.gloss_steps[t] += steps;
    }
    if (d == 3) p.env_steps += steps;
  }
  uint8_t pressed = static_cast<uint8_t>(event.buttons & ~buttons_);  // act on press, not hold
  buttons_ = event.buttons;
  int next_colourway = event.colourway;
  if (config_.colourway_button >= 0 && (pressed & (1u << config_.colourway_button))) {
    pressed = static_cast<uint8_t>(pressed & ~(1u << config_.colourway_button));  // instead of its own job
    ++next_colourway;
  }
  if (next_colourway > 0 && !colourways_.empty()) {
    const auto count = static_cast<uint32_t>(colourways_.size());
    wear_colourway((p.colourway + static_cast<uint32_t>(next_colourway)) % count);
  }
  const auto n = static_cast<uint32_t>(presets_.size());
  if (pressed & 1u) p.selection = static_cast<ThreadSelection>((static_cast<int>(p.selection) + 1) % 3);
  if (pressed & 2u) select_preset((p.preset + n - 1) % n);
  if (pressed & 4u) select_preset((p.preset + 1) % n);
  if (pressed & 8u) p.env_steps = 0;
  if (pressed & 16u) select_preset(p.preset);
  clamp();
  return !(positions_ == before);
}

void KnobMapper::set_positions(const KnobPositions& positions) {
  positions_ = positions;
  clamp();
}

AppearanceState KnobMapper::appearance() const {
  const auto& p = positions_;
  AppearanceState s;
  s.preset_index = p.preset;
  s.colourway = p.colourway;
  s.selection = p.selection;
  s.env_rotation_deg = static_cast<float>(p.env_steps * config_.env_deg_per_step);
  s.zoom = config_.zoom_steps > 0 ? static_cast<float>(p.zoom_steps) / static_cast<float>(config_.zoom_steps) : 0.0f;
  for (int t = 0; t < 2; ++t) {
    const auto& a = presets_[p.preset].albedo[t];
    Hsv c = hsv_from_rgb(a[0], a[1], a[2]);
    c.h += p.hue_steps[t] * config_.hue_deg_per_step;
    c.v = std::min(1.0, c.v * std::exp2(static_cast<double>(p.brightness_steps[t]) / config_.brightness_steps_per_octave));
    double rgb[3];
    rgb_from_hsv(c, rgb);
    for (int k = 0; k < 3; ++k) s.thread[t].albedo[k] = static_cast<float>(rgb[k]);
    s.thread[t].gamma_scale =
        static_cast<float>(std::exp2(-static_cast<double>(p.gloss_steps[t]) / config_.gloss_steps_per_octave));
  }
  return s;
}

}  // namespace weft::input
