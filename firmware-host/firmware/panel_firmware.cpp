#include "firmware/panel_firmware.h"

namespace weft::firmware {
namespace {

uint8_t encoder_state(const PanelLines& lines, int dial) {
  return static_cast<uint8_t>((((lines.a >> dial) & 1u) << 1) | ((lines.b >> dial) & 1u));
}
bool raw_pressed(const PanelLines& lines, int button) { return ((lines.buttons >> button) & 1u) == 0; }

}  // namespace

PanelFirmware::PanelFirmware(const FirmwareConfig& config) {
  for (auto& d : decoders_) d = QuadratureDecoder(config.encoder_rest_state);
  for (auto& b : debouncers_) b = ButtonDebouncer(config.debounce_ms);
}

void PanelFirmware::reset(const PanelLines& lines, uint32_t now_ms) {
  for (int i = 0; i < kDialCount; ++i) {
    decoders_[i].reset(encoder_state(lines, i));
    pending_[i] = 0;
  }
  buttons_ = 0;
  for (int i = 0; i < kButtonCount; ++i) {
    debouncers_[i].reset(raw_pressed(lines, i), now_ms);
    if (debouncers_[i].pressed()) buttons_ |= static_cast<uint8_t>(1u << i);
  }
  buttons_sent_ = buttons_;
  pressed_since_report_ = 0;
}

void PanelFirmware::scan(const PanelLines& lines, uint32_t now_ms) {
  for (int i = 0; i < kDialCount; ++i) {
    const int detents = decoders_[i].update(encoder_state(lines, i));
    const int sum = pending_[i] + detents;
    pending_[i] = static_cast<int16_t>(sum > 32000 ? 32000 : sum < -32000 ? -32000 : sum);
  }
  uint8_t held = 0;
  for (int i = 0; i < kButtonCount; ++i)
    if (debouncers_[i].update(raw_pressed(lines, i), now_ms)) held |= static_cast<uint8_t>(1u << i);
  pressed_since_report_ |= static_cast<uint8_t>(held & ~buttons_);  // new presses only
  buttons_ = held;
}

bool PanelFirmware::poll_report(uint32_t now_ms, PanelReport& out) {
  bool motion = false;
  for (int16_t p : pending_) motion |= p != 0;
  // A press shorter than the polling interval still shows in one report (then its release).
  const uint8_t buttons = static_cast<uint8_t>(buttons_ | pressed_since_report_);
  if (!motion && buttons == buttons_sent_) return false;
  out.sequence = sequence_++;
  for (int i = 0; i < kDialCount; ++i) {
    const int sent = pending_[i] > 127 ? 127 : pending_[i] < -127 ? -127 : pending_[i];
    out.dial[i] = static_cast<int8_t>(sent);
    pending_[i] = static_cast<int16_t>(pending_[i] - sent);
  }
  out.buttons = buttons;
  out.time_ms = static_cast<uint16_t>(now_ms & 0xFFFFu);
  buttons_sent_ = buttons;
  pressed_since_report_ = 0;
  return true;
}

}  // namespace weft::firmware
