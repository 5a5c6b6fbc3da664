#pragma once
// Encoders and buttons wired straight to the kiosk's GPIO lines: turns timestamped line edges into
// knob events with the firmware core's own decoder and debouncer (one decoding, two transports).
#include <array>
#include <string>
#include <vector>

#include "firmware/button_debouncer.h"
#include "firmware/quadrature_decoder.h"
#include "panel/knob_source.h"

namespace weft::input {

struct GpioPanelConfig {
  std::string chip = "gpiochip0";
  std::array<int, kDialCount> encoder_a{5, 13, 19, 20};   // line offsets; −1 = not wired
  std::array<int, kDialCount> encoder_b{6, 16, 26, 21};
  std::array<int, kButtonCount> buttons{12, 17, 22, 23, 24};
  uint16_t debounce_ms = 5;
  // All wired line offsets, in a fixed order (A lines, B lines, buttons); the request order.
  std::vector<unsigned> offsets() const;
};

class GpioPanelDecoder {
public:
  explicit GpioPanelDecoder(const GpioPanelConfig& config);

  // Initial line levels (offset → level) before any edge.
  void reset(const std::vector<std::pair<unsigned, int>>& levels, uint32_t now_ms);
  // A line changed to `level`. Fills `out` and returns true when a detent completed or the
  // debounced buttons changed.
  bool on_edge(unsigned offset, int level, uint32_t time_ms, KnobEvent& out);
  // Lets pending button changes settle when no edge came; call after a wait times out.
  bool on_idle(uint32_t now_ms, KnobEvent& out);
  // How long until a pending button change could settle (−1: nothing pending).
  int settle_timeout_ms() const;

private:
  bool update_buttons(uint32_t now_ms);

  GpioPanelConfig config_;
  std::array<firmware::QuadratureDecoder, kDialCount> decoders_;
  std::array<firmware::ButtonDebouncer, kButtonCount> debouncers_;
  std::array<uint8_t, kDialCount> a_{}, b_{};
  std::array<uint8_t, kButtonCount> raw_pressed_{};
  uint8_t buttons_ = 0;
};

}  // namespace weft::input
