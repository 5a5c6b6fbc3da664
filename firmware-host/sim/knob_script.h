#pragma once
// The panel simulator's script: what a hand does to the knobs, over time. Host code.
//
// One command per line; `#` starts a comment; times in milliseconds (decimals allowed).
// A time cursor starts at 0; `turn`, `click` and `wait` advance it, the others act at it.
//   wait <ms>                          advance the cursor
//   at <ms>                            move the cursor to an absolute time (never backwards)
//   turn <dial> <±detents> [every <ms>]   turn dial 0..3 by whole detents, <ms> per detent
//                                      (default 80); + is clockwise
//   press <button> / release <button>  button 0..4 down / up (pressed = line pulled low)
//   click <button> [hold <ms>]         press, hold (default 80 ms), release
//   bounce <count> [<period_ms>]       from now on every contact edge chatters: the line flips
//                                      back and forth <count> more times, <period_ms> apart
//                                      (default 0.3); `bounce 0` for clean contacts
//   glitch <dial> <a|b> [<width_ms>]   a lone spike on one encoder line (default 0.5 ms wide)
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft::sim {

class ScriptError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct KnobAction {
  enum class Kind { turn, press, release, glitch };
  Kind kind = Kind::turn;
  uint64_t start_us = 0;
  int target = 0;               // dial (turn, glitch) or button (press, release)
  int detents = 0;              // turn
  uint64_t duration_us = 0;     // turn: per detent; glitch: spike width
  int line = 0;                 // glitch: 0 = A, 1 = B
  int bounce_count = 0;         // contact bounce in force for this action
  uint64_t bounce_period_us = 300;
  int script_line = 0;          // for messages
};

// Throws ScriptError naming the line and what is wrong.
std::vector<KnobAction> parse_knob_script(const std::string& text);

}  // namespace weft::sim
