#pragma once
// The kiosk's knob configuration (JSON, e.g. /etc/weft/panel.json). Every field is optional:
// {
//   "sources": ["hid", "gpio", "keyboard"],         which backends to run (default ["hid"])
//   "hid":  {"vendor_id": "0x1209", "product_id": "0x57ef"},
//   "gpio": {"chip": "gpiochip0", "encoder_a": [5,13,19,20], "encoder_b": [6,16,26,21],
//            "buttons": [12,17,22,23,24], "debounce_ms": 5},   −1 = not wired
//   "state_file": "/var/lib/weft/knobs.json",
//   "zoom_dial": -1, "colourway_button": -1        a dial that zooms, a button that steps the colourway
// }
#include <stdexcept>
#include <string>
#include <vector>

#include "panel/gpio_panel_decoder.h"
#include "panel/hid_knob_source.h"

namespace weft::input {

class PanelConfigError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct PanelConfig {
  std::vector<std::string> sources{"hid"};
  HidSourceOptions hid;
  GpioPanelConfig gpio;
  std::string state_file = "/var/lib/weft/knobs.json";
  int zoom_dial = -1;  // a dial (0–3) that zooms instead of its own job (MappingConfig::zoom_dial); −1: none
  int colourway_button = -1;  // a button (0–4) that steps to the next colourway instead of its own job; −1: none
};

// Throws PanelConfigError naming the field and the value; `origin` names the file.
PanelConfig parse_panel_config(const std::string& json_text, const std::string& origin);

}  // namespace weft::input
