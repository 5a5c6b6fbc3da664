#pragma once
// A knob panel that is not there: a HidTransport that plays the reports the panel simulator
// (firmware-host) produces for a knob script, paced at their real times from when it is opened.
// Lets the kiosk run "with the panel attached" for demos, checks and latency measurements.
#include <memory>
#include <stdexcept>
#include <string>

#include "panel/hid_transport.h"

namespace weft::input {

class PanelScriptError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct SimulatedPanel {
  std::unique_ptr<HidTransport> transport;
  double seconds = 0;   // when its last report goes out (at the given speed)
  size_t reports = 0;
};

// Throws PanelScriptError (naming the script line) for a bad script. `speed` > 1 plays faster.
SimulatedPanel make_simulated_panel(const std::string& script_text, double speed = 1.0);

}  // namespace weft::input
