#include "firmware/button_debouncer.h"

namespace weft::firmware {

void ButtonDebouncer::reset(bool raw_pressed, uint32_t now_ms) {
  stable_ = candidate_ = raw_pressed;
  candidate_since_ms_ = now_ms;
}

bool ButtonDebouncer::update(bool raw_pressed, uint32_t now_ms) {
  if (raw_pressed != candidate_) {
    candidate_ = raw_pressed;
    candidate_since_ms_ = now_ms;
  }
  // Unsigned difference: correct across the 32-bit millisecond wrap (49 days).
  if (candidate_ != stable_ && now_ms - candidate_since_ms_ >= stable_ms_) stable_ = candidate_;
  return stable_;
}

}  // namespace weft::firmware
