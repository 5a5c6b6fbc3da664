#include "panel/knob_state_file.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>
#include <system_error>

#include "files/atomic_file.h"
#include "hashing/fnv1a_hash.h"

namespace weft::input {
namespace {

constexpr int kVersion = 1;
constexpr int kAbsurd = 100000;  // no knob is ever turned this far
const char* kSelectionNames[] = {"both", "warp", "weft"};

int steps(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number_integer())
    throw KnobStateError(std::string("'") + key + "' is missing or not an integer");
  const auto v = j[key].get<int64_t>();
  if (v < -kAbsurd || v > kAbsurd) throw KnobStateError(std::string("'") + key + "' = " + std::to_string(v) + " is absurd");
  return static_cast<int>(v);
}

// A text field, or "" when absent or of another type: json::value() would throw json's own
// type_error for {"format": [1]}, which no caller expects (found by the panel_config fuzzer).
std::string text_field(const nlohmann::ordered_json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

std::string knob_state_text(const KnobPositions& p, const std::vector<PresetLook>& presets,
                            const std::vector<std::string>& colourways) {
  nlohmann::ordered_json j;
  j["format"] = "weft-knobs";
  j["version"] = kVersion;
  j["preset"] = presets.at(p.preset).name;
  j["selection"] = kSelectionNames[static_cast<int>(p.selection) % 3];
  j["threads"] = nlohmann::ordered_json::array();
  for (int t = 0; t < 2; ++t)
    j["threads"].push_back({{"hue_steps", p.hue_steps[t]},
                            {"brightness_steps", p.brightness_steps[t]},
                            {"gloss_steps", p.gloss_steps[t]}});
  j["env_steps"] = p.env_steps;
  if (!colourways.empty()) j["colourway"] = colourways.at(p.colourway);
  j["checksum"] = fnv1a64_hex(j.dump());
  return j.dump(2) + "\n";
}

KnobPositions parse_knob_state(const std::string& text, const std::vector<PresetLook>& presets,
                               const std::vector<std::string>& colourways) {
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw KnobStateError(std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object() || text_field(j, "format") != "weft-knobs") throw KnobStateError("not a weft knob state file");
  if (!j.contains("version") || j["version"] != kVersion)
    throw KnobStateError("unsupported version " + (j.contains("version") ? j["version"].dump() : std::string("(none)")));
  if (!j.contains("checksum") || !j["checksum"].is_string()) throw KnobStateError("checksum missing");
  const std::string stored = j["checksum"].get<std::string>();
  j.erase("checksum");
  if (fnv1a64_hex(j.dump()) != stored) throw KnobStateError("checksum mismatch (file damaged)");

  KnobPositions p;
  const std::string preset = text_field(j, "preset");
  bool found = false;
  for (size_t i = 0; i < presets.size(); ++i)
    if (presets[i].name == preset) p.preset = static_cast<uint32_t>(i), found = true;
  if (!found) throw KnobStateError("fabric preset '" + preset + "' is not installed");
  const std::string selection = text_field(j, "selection");
  found = false;
  for (int i = 0; i < 3; ++i)
    if (selection == kSelectionNames[i]) p.selection = static_cast<ThreadSelection>(i), found = true;
  if (!found) throw KnobStateError("unknown thread selection '" + selection + "'");
  if (!j.contains("threads") || !j["threads"].is_array() || j["threads"].size() != 2)
    throw KnobStateError("'threads' must list 2 threads");
  for (int t = 0; t < 2; ++t) {
    const auto& th = j["threads"][t];
    if (!th.is_object()) throw KnobStateError("thread entry is not an object");
    p.hue_steps[t] = steps(th, "hue_steps");
    p.brightness_steps[t] = steps(th, "brightness_steps");
    p.gloss_steps[t] = steps(th, "gloss_steps");
  }
  p.env_steps = steps(j, "env_steps");
  if (j.contains("colourway") && !colourways.empty()) {
    const std::string worn = text_field(j, "colourway");
    const auto it = std::find(colourways.begin(), colourways.end(), worn);
    if (it == colourways.end()) throw KnobStateError("colourway '" + worn + "' is not in the bundle");
    p.colourway = static_cast<uint32_t>(it - colourways.begin());
  }
  return p;
}

bool write_file_atomically(const std::filesystem::path& file, const std::string& text, std::string& why) {
  try {
    weft::write_file_atomically(file, std::string_view(text));
    return true;
  } catch (const std::system_error& e) {
    why = e.what();
    return false;
  }
}

RestoredKnobs restore_knob_state(const std::filesystem::path& file, const std::vector<PresetLook>& presets,
                                 uint32_t default_preset, const std::vector<std::string>& colourways) {
  RestoredKnobs r;
  r.positions.preset = default_preset < presets.size() ? default_preset : 0;
  const std::string preset_name = presets.at(r.positions.preset).name;
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    r.message = "no saved knob state at " + file.string() + "; starting from preset '" + preset_name + "'";
    return r;
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    r.positions = parse_knob_state(text.str(), presets, colourways);
    r.from_file = true;
    r.message = "restored knob state from " + file.string() + " (preset '" + presets[r.positions.preset].name + "'" +
                (colourways.empty() ? "" : ", colourway '" + colourways[r.positions.colourway] + "'") + ")";
  } catch (const KnobStateError& e) {
    r.unusable = true;
    r.message = "saved knob state " + file.string() + " is unusable (" + e.what() +
                "); falling back to preset '" + preset_name + "'";
  }
  return r;
}

}  // namespace weft::input
