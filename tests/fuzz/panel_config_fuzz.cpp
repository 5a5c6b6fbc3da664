// libFuzzer target for the kiosk's panel configuration and its knob state file: any
// text either parses into values inside their documented limits or raises the loader's own
// error (PanelConfigError, KnobStateError); a state file that parses round-trips exactly.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "panel/knob_state_file.h"
#include "panel/panel_config.h"

namespace {

using namespace weft::input;

const std::vector<PresetLook>& presets() {
  static const std::vector<PresetLook> p = {
      {"linen_plain", {{{0.06, 0.24, 0.3}, {0.06, 0.24, 0.3}}}},
      {"velvet", {{{0.015, 0.006, 0.0}, {0.015, 0.006, 0.0}}}},
  };
  return p;
}

void config(const std::string& text) {
  try {
    const PanelConfig c = parse_panel_config(text, "fuzz-panel.json");
    if (c.sources.empty() || c.hid.read_timeout_ms < 0) __builtin_trap();
    for (const std::string& s : c.sources)
      if (s != "hid" && s != "gpio" && s != "keyboard") __builtin_trap();
  } catch (const PanelConfigError&) {
  }
}

void knob_state(const std::string& text) {
  try {
    const KnobPositions k = parse_knob_state(text, presets());
    if (k.preset >= presets().size()) __builtin_trap();
    // What was accepted must be written back to the same positions.
    if (!(parse_knob_state(knob_state_text(k, presets()), presets()) == k)) __builtin_trap();
  } catch (const KnobStateError&) {
  }
}

}  // namespace

// The first byte picks the loader, so one corpus covers both.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] & 1)
    knob_state(text);
  else
    config(text);
  return 0;
}
