#pragma once
// Knobs from the keyboard, for development without a panel. Keys (terminal, no Enter needed):
//   q/a  dial 0 ±1      w/s  dial 1 ±1      e/d  dial 2 ±1      r/f  dial 3 ±1
//   t/g  zoom closer / back ±1
//   1..4 click the push of dial 0..3        0 or space  click the reset button (4)
// Upper-case turns by 5 detents. Reads from a file descriptor (stdin by default) so tests can
// feed a pipe; a terminal is put in non-canonical mode while the source runs.
#include <atomic>
#include <thread>
#include <vector>

#include "panel/knob_source.h"
#include "panel/retry_backoff.h"

namespace weft::input {

// The events one key stands for (a click is a press and a release); empty for other keys.
std::vector<KnobEvent> keyboard_events(char key, uint32_t time_ms);

class KeyboardKnobSource final : public KnobSource {
public:
  explicit KeyboardKnobSource(int fd = 0, LogSink log = {});
  ~KeyboardKnobSource() override;

  std::string describe() const override { return "keyboard knobs"; }
  void start(KnobSink sink) override;
  void stop() override;

private:
  void run(KnobSink sink);

  int fd_;
  LogSink log_;
  StopSignal stop_;
  std::thread thread_;
};

}  // namespace weft::input
