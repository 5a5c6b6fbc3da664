#pragma once
// Debouncing of one push button. A change of the raw contact level is accepted once it has held
// for `stable_ms` without interruption; chatter shorter than that is ignored. Works both from a
// periodic scan (call update every tick) and from timestamped edges (call update at each edge
// and again once the level may have settled). No heap, no OS calls.
#include <cstdint>

namespace weft::firmware {

class ButtonDebouncer {
public:
  explicit ButtonDebouncer(uint16_t stable_ms = 5) : stable_ms_(stable_ms) {}

  void reset(bool raw_pressed, uint32_t now_ms);
  // Returns the debounced state after seeing `raw_pressed` at `now_ms`.
  bool update(bool raw_pressed, uint32_t now_ms);

  bool pressed() const { return stable_; }
  // True while a raw change is waiting to prove itself stable.
  bool pending() const { return candidate_ != stable_; }
  uint16_t stable_ms() const { return stable_ms_; }

private:
  uint16_t stable_ms_;
  bool stable_ = false;
  bool candidate_ = false;
  uint32_t candidate_since_ms_ = 0;
};

}  // namespace weft::firmware
