#include "panel/gpio_panel_decoder.h"

namespace weft::input {

std::vector<unsigned> GpioPanelConfig::offsets() const {
  std::vector<unsigned> out;
  for (int o : encoder_a) if (o >= 0) out.push_back(static_cast<unsigned>(o));
  for (int o : encoder_b) if (o >= 0) out.push_back(static_cast<unsigned>(o));
  for (int o : buttons) if (o >= 0) out.push_back(static_cast<unsigned>(o));
  return out;
}

GpioPanelDecoder::GpioPanelDecoder(const GpioPanelConfig& config) : config_(config) {
  for (auto& d : debouncers_) d = firmware::ButtonDebouncer(config.debounce_ms);
  a_.fill(1);
  b_.fill(1);
}

void GpioPanelDecoder::reset(const std::vector<std::pair<unsigned, int>>& levels, uint32_t now_ms) {
  for (auto [offset, level] : levels) {
    for (int i = 0; i < kDialCount; ++i) {
      if (config_.encoder_a[i] == static_cast<int>(offset)) a_[i] = level != 0;
      if (config_.encoder_b[i] == static_cast<int>(offset)) b_[i] = level != 0;
    }
    for (int i = 0; i < kButtonCount; ++i)
      if (config_.buttons[i] == static_cast<int>(offset)) raw_pressed_[i] = level == 0;  // pull-up
  }
  buttons_ = 0;
  for (int i = 0; i < kDialCount; ++i) decoders_[i].reset(static_cast<uint8_t>((a_[i] << 1) | b_[i]));
  for (int i = 0; i < kButtonCount; ++i) {
    debouncers_[i].reset(raw_pressed_[i], now_ms);
    if (raw_pressed_[i]) buttons_ |= static_cast<uint8_t>(1u << i);
  }
}

bool GpioPanelDecoder::on_edge(unsigned offset, int level, uint32_t time_ms, KnobEvent& out) {
  out = KnobEvent{};
  out.time_ms = time_ms;
  bool changed = false;
  for (int i = 0; i < kDialCount; ++i) {
    bool mine = false;
    if (config_.encoder_a[i] == static_cast<int>(offset)) a_[i] = level != 0, mine = true;
    if (config_.encoder_b[i] == static_cast<int>(offset)) b_[i] = level != 0, mine = true;
    if (!mine) continue;
    out.dial[i] = decoders_[i].update(static_cast<uint8_t>((a_[i] << 1) | b_[i]));
    changed |= out.dial[i] != 0;
  }
  for (int i = 0; i < kButtonCount; ++i)
    if (config_.buttons[i] == static_cast<int>(offset)) raw_pressed_[i] = level == 0;
  changed |= update_buttons(time_ms);
  out.buttons = buttons_;
  return changed;
}

bool GpioPanelDecoder::on_idle(uint32_t now_ms, KnobEvent& out) {
  out = KnobEvent{};
  out.time_ms = now_ms;
  const bool changed = update_buttons(now_ms);
  out.buttons = buttons_;
  return changed;
}

bool GpioPanelDecoder::update_buttons(uint32_t now_ms) {
  uint8_t held = 0;
  for (int i = 0; i < kButtonCount; ++i)
    if (debouncers_[i].update(raw_pressed_[i], now_ms)) held |= static_cast<uint8_t>(1u << i);
  const bool changed = held != buttons_;
  buttons_ = held;
  return changed;
}

int GpioPanelDecoder::settle_timeout_ms() const {
  for (const auto& d : debouncers_)
    if (d.pending()) return d.stable_ms() + 1;
  return -1;
}

}  // namespace weft::input
