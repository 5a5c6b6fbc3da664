#pragma once
// weft-panel-sim's command line: turns a script of knob motions into the exact HID reports the
// panel sends (printed, or played on a uhid device). Its --panel-config option names the kiosk's
// panel config, whose format belongs to input/ (which depends on firmware-host, never the other
// way): the executable's main (input/panel/panel_sim_main.cpp) passes the reader in.
#include <functional>
#include <stdexcept>
#include <string>

#include "sim/uhid_panel.h"

namespace weft::sim {

// The USB identity in the panel config at `path`; throws std::runtime_error with the message
// to print when the file cannot be read or holds no valid config.
using PanelConfigReader = std::function<UhidIdentity(const std::string& path)>;

// The whole command: parses argv, prints usage or reports; returns the exit status.
int panel_sim_main(int argc, char** argv, const PanelConfigReader& read_panel_config);

}  // namespace weft::sim
