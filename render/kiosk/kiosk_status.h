#pragma once
// The kiosk's health as a fleet reads it: what `weft run` shows and how well, written as a JSON
// status file (kiosk/kiosk_status_file.h) and read back by `weft status`.
//
// {"format":"weft-status","version":1,"state":"running","written":"2026-12-03T15:20:00Z",
//  "uptime_s":…,"pid":…,"bundle":{"path":…,"last_good":false,"scene":…},"method":…,"display":…,
//  "frames":{"ticks":…,"drawn":…,"fps":…,"last_frame_ms":…},"probe":{"state":…,"updates":…},
//  "panel":{"sources":[…],"changes":…},"content_update":{"at":"…"|null,"result":…}}
#include <cstdint>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft {

struct KioskStatus {
  // starting, running, stopping; or why the kiosk cannot run: no display, no usable bundle.
  std::string state = "starting";
  std::time_t written = 0;  // UTC seconds
  double uptime_s = 0;
  long pid = 0;
  std::string bundle;         // the file shown
  bool last_good = false;     // the last good copy, because the bundle itself was unusable
  std::string scene;          // the scene shown
  std::string method;         // the runtime method (rung) drawing it
  std::string display;        // drm:CONNECTOR, headless or none
  long ticks = 0, drawn = 0;  // display refreshes, frames drawn
  double fps = 0;             // frames drawn per second since the previous status
  double last_frame_ms = 0;   // the newest frame's time to draw
  std::string probe = "off";  // off, waiting (for its first fit) or fitted
  std::uint64_t probe_updates = 0;
  std::vector<std::string> panel;  // the knob sources
  long knob_changes = 0;           // knob states shown
  std::time_t content_update_at = 0;  // the latest content update (bundle replaced); 0: none
  std::string content_update;         // its result: shown, unchanged or refused: WHY; "" when none
};

// A status file that does not parse or is not a weft status.
class StatusFormatError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// A time as the status file and the journal write it: ISO 8601 in UTC ("2026-12-04T05:07:37Z").
std::string utc(std::time_t t);
std::string status_json(const KioskStatus& s);
KioskStatus parse_status_json(const std::string& text);  // throws StatusFormatError saying what is wrong
// For a person: one "name: value" line each; `now` gives the status's age.
std::string status_text(const KioskStatus& s, std::time_t now);

}  // namespace weft
