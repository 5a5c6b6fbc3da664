#include "panel/panel_config.h"

#include <nlohmann/json.hpp>

namespace weft::input {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw PanelConfigError(origin + ": " + what);
}

uint16_t usb_id(const json& j, const char* key, const std::string& origin) {
  long v = -1;
  if (j[key].is_number_integer()) {
    v = j[key].get<long>();
  } else if (j[key].is_string()) {
    const std::string s = j[key].get<std::string>();
    size_t used = 0;
    try {
      v = std::stol(s, &used, 16);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size()) v = -1;
  }
  if (v < 0 || v > 0xFFFF) fail(origin, std::string("hid.") + key + " must be a 16-bit USB id, got " + j[key].dump());
  return static_cast<uint16_t>(v);
}

template <size_t N>
void offsets(const json& g, const char* key, std::array<int, N>& out, const std::string& origin) {
  if (!g.contains(key)) return;
  const json& a = g[key];
  if (!a.is_array() || a.size() != N) fail(origin, std::string("gpio.") + key + " must list " + std::to_string(N) + " line offsets");
  for (size_t i = 0; i < N; ++i) {
    if (!a[i].is_number_integer() || a[i].get<long>() < -1 || a[i].get<long>() > 1023)
      fail(origin, std::string("gpio.") + key + "[" + std::to_string(i) + "] must be a line offset or -1, got " + a[i].dump());
    out[i] = a[i].get<int>();
  }
}

}  // namespace

PanelConfig parse_panel_config(const std::string& text, const std::string& origin) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    fail(origin, std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object()) fail(origin, "expected a JSON object");
  PanelConfig c;
  if (j.contains("sources")) {
    if (!j["sources"].is_array() || j["sources"].empty())
      fail(origin, "sources must be a list of at least one source (hid, gpio, keyboard); a kiosk without a panel runs with --panel none");
    c.sources.clear();
    for (const auto& s : j["sources"]) {
      if (!s.is_string() || (s != "hid" && s != "gpio" && s != "keyboard"))
        fail(origin, "unknown knob source " + s.dump() + " (hid, gpio or keyboard)");
      c.sources.push_back(s.get<std::string>());
    }
  }
  if (j.contains("hid")) {
    const json& h = j["hid"];
    if (!h.is_object()) fail(origin, "hid must be an object");
    if (h.contains("vendor_id")) c.hid.vendor_id = usb_id(h, "vendor_id", origin);
    if (h.contains("product_id")) c.hid.product_id = usb_id(h, "product_id", origin);
  }
  if (j.contains("gpio")) {
    const json& g = j["gpio"];
    if (!g.is_object()) fail(origin, "gpio must be an object");
    if (g.contains("chip")) {
      if (!g["chip"].is_string() || g["chip"].get<std::string>().empty()) fail(origin, "gpio.chip must be a chip name or path");
      c.gpio.chip = g["chip"].get<std::string>();
    }
    offsets(g, "encoder_a", c.gpio.encoder_a, origin);
    offsets(g, "encoder_b", c.gpio.encoder_b, origin);
    offsets(g, "buttons", c.gpio.buttons, origin);
    if (g.contains("debounce_ms")) {
      if (!g["debounce_ms"].is_number_integer() || g["debounce_ms"].get<long>() < 0 || g["debounce_ms"].get<long>() > 1000)
        fail(origin, "gpio.debounce_ms must be 0..1000, got " + g["debounce_ms"].dump());
      c.gpio.debounce_ms = static_cast<uint16_t>(g["debounce_ms"].get<int>());
    }
  }
  if (j.contains("state_file")) {
    if (!j["state_file"].is_string()) fail(origin, "state_file must be a path");
    c.state_file = j["state_file"].get<std::string>();
  }
  if (j.contains("zoom_dial")) {
    const auto& z = j["zoom_dial"];
    if (!z.is_number_integer() || z.get<long>() < -1 || z.get<long>() >= kDialCount)
      fail(origin, "zoom_dial must be a dial 0..3 (or -1: none), got " + z.dump());
    c.zoom_dial = z.get<int>();
  }
  if (j.contains("colourway_button")) {
    const auto& b = j["colourway_button"];
    if (!b.is_number_integer() || b.get<long>() < -1 || b.get<long>() >= kButtonCount)
      fail(origin, "colourway_button must be a button 0..4 (or -1: none), got " + b.dump());
    c.colourway_button = b.get<int>();
  }
  return c;
}

}  // namespace weft::input
