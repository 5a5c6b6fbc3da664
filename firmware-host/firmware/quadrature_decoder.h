#pragma once
// Quadrature decoding of one detented rotary encoder from its two contact lines (A, B).
// Portable firmware code: no heap, no OS calls, no exceptions.
//
// The 2-bit state is (A << 1) | B. One detent is a full Gray cycle of four transitions; the
// direction called "+1" (clockwise on the panel) is 00 → 01 → 11 → 10 → 00.
// A 16-entry table maps (previous, current) to a quarter step of −1, 0, +1, or "double":
//  - Contact bounce toggles one line back and forth between two adjacent states, so its quarter
//    steps cancel (+1 −1 +1 …) and never reach a detent.
//  - A double step (both lines changed between two samples, 00↔11 or 01↔10) means one state was
//    missed. Its direction cannot be read from the two states alone. It is counted as two quarter
//    steps in the direction of the last valid quarter step (a knob spinning fast enough to skip a
//    state keeps spinning the same way); with no known direction yet it is ignored. Either way it
//    is counted in illegal_steps().
//  - Detents are emitted only when the lines return to the rest state (the mechanical detent,
//    11 for the usual pull-up wiring). The quarter steps accumulated since the last rest are then
//    rounded to whole detents (|acc| 2..5 → 1, 6..9 → 2, …) and the accumulator is cleared, so a
//    missed or spurious quarter step never carries over into later detents.
#include <cstdint>

namespace weft::firmware {

class QuadratureDecoder {
public:
  static constexpr uint8_t kRestPullUp = 0b11;

  explicit QuadratureDecoder(uint8_t rest_state = kRestPullUp);

  // Starts from the lines' current levels (call at power-up).
  void reset(uint8_t state);
  // Feeds the current (A << 1) | B; returns the detents completed by this sample (signed).
  int update(uint8_t state);

  uint8_t state() const { return state_; }
  uint32_t illegal_steps() const { return illegal_steps_; }

private:
  uint8_t rest_;
  uint8_t state_;
  int8_t last_direction_ = 0;
  int16_t quarter_steps_ = 0;
  uint32_t illegal_steps_ = 0;
};

}  // namespace weft::firmware
