#include "firmware/quadrature_decoder.h"

namespace weft::firmware {
namespace {

constexpr int8_t kDouble = 2;  // both lines changed: a state was missed
// kQuarterStep[(previous << 2) | current]
constexpr int8_t kQuarterStep[16] = {
    //        to 00     to 01     to 10     to 11
    /* 00 */ 0,       +1,       -1,       kDouble,
    /* 01 */ -1,      0,        kDouble,  +1,
    /* 10 */ +1,      kDouble,  0,        -1,
    /* 11 */ kDouble, -1,       +1,       0,
};

}  // namespace

QuadratureDecoder::QuadratureDecoder(uint8_t rest_state)
    : rest_(rest_state & 3u), state_(rest_state & 3u) {}

void QuadratureDecoder::reset(uint8_t state) {
  state_ = state & 3u;
  last_direction_ = 0;
  quarter_steps_ = 0;
}

int QuadratureDecoder::update(uint8_t state) {
  state &= 3u;
  const int8_t step = kQuarterStep[(state_ << 2) | state];
  state_ = state;
  if (step == kDouble) {
    ++illegal_steps_;
    quarter_steps_ = static_cast<int16_t>(quarter_steps_ + 2 * last_direction_);
  } else if (step != 0) {
    quarter_steps_ = static_cast<int16_t>(quarter_steps_ + step);
    last_direction_ = step;
  } else {
    return 0;
  }
  if (state_ != rest_) return 0;
  const int magnitude = quarter_steps_ < 0 ? -quarter_steps_ : quarter_steps_;
  const int detents = (magnitude + 2) / 4;
  const int signed_detents = quarter_steps_ < 0 ? -detents : detents;
  quarter_steps_ = 0;
  return signed_detents;
}

}  // namespace weft::firmware
