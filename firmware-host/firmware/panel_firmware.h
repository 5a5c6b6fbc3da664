#pragma once
// The panel's main loop, minus the hardware: scans the encoder and button lines at a fixed rate,
// decodes and debounces them, and builds an input report whenever the USB host polls and there
// is something to say. On the microcontroller `scan` runs from a 1 kHz timer and `poll_report`
// from the interrupt-IN endpoint; on the host the simulator drives both. No heap, no OS calls.
#include <cstdint>

#include "firmware/button_debouncer.h"
#include "firmware/hid_report.h"
#include "firmware/quadrature_decoder.h"

namespace weft::firmware {

// Raw line levels (1 = high). Encoders: bit i of `a`/`b` is dial i's A/B line. Buttons are wired
// to ground with pull-ups, so a held button reads low.
struct PanelLines {
  uint8_t a = 0xFF;
  uint8_t b = 0xFF;
  uint8_t buttons = 0xFF;
};

struct FirmwareConfig {
  uint16_t debounce_ms = 5;
  uint8_t encoder_rest_state = QuadratureDecoder::kRestPullUp;
};

class PanelFirmware {
public:
  explicit PanelFirmware(const FirmwareConfig& config = {});

  void reset(const PanelLines& lines, uint32_t now_ms);
  void scan(const PanelLines& lines, uint32_t now_ms);
  // Fills `out` and returns true when dial motion is pending or the buttons changed since the
  // last report. Motion beyond ±127 detents stays pending for the next report.
  bool poll_report(uint32_t now_ms, PanelReport& out);

  uint32_t illegal_steps(int dial) const { return decoders_[dial].illegal_steps(); }
  uint8_t buttons() const { return buttons_; }

private:
  QuadratureDecoder decoders_[kDialCount];
  ButtonDebouncer debouncers_[kButtonCount];
  int16_t pending_[kDialCount] = {};
  uint8_t buttons_ = 0;
  uint8_t buttons_sent_ = 0;
  uint8_t pressed_since_report_ = 0;
  uint8_t sequence_ = 0;
};

}  // namespace weft::firmware
