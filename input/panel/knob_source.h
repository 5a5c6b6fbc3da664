#pragma once
// One interface for every way knob motion reaches the kiosk (USB HID panel, GPIO encoders,
// keyboard). A source runs on its own thread and hands each change to a sink; device trouble
// (absent, unplugged, garbage) is logged and retried, never thrown at the caller.
#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "firmware/hid_report.h"
#include "journal/journal_log.h"

namespace weft::input {

inline constexpr int kDialCount = firmware::kDialCount;
inline constexpr int kButtonCount = firmware::kButtonCount;

struct KnobEvent {
  std::array<int, kDialCount> dial{};  // detents since the previous event, + = clockwise
  uint8_t buttons = 0;                 // buttons held now (bit i = button i)
  uint32_t time_ms = 0;                // the source's clock; used for turn acceleration
  int zoom = 0;                        // detents of the zoom control (keyboard t/g), + = closer
  int colourway = 0;                   // presses of the colourway control (keyboard c): next colourway
};

using KnobSink = std::function<void(const KnobEvent&)>;
// Where operator-readable log lines go (journal_log.h).
using LogSink = weft::LogSink;
// Writes "weft panel: <line>" to stderr (journald picks it up under systemd, with priorities).
LogSink stderr_log();

class KnobSource {
public:
  virtual ~KnobSource() = default;
  virtual std::string describe() const = 0;
  // Starts the source's thread; events go to `sink` from that thread.
  virtual void start(KnobSink sink) = 0;
  // Stops and joins the thread (prompt: within one read timeout). Safe to call twice.
  virtual void stop() = 0;
};

}  // namespace weft::input
