// The knob state file's checksum is FNV-1a 64 of the compact JSON without the checksum member,
// as 16 lowercase hex digits (panel/knob_state_file.h): the expected value was computed
// independently (Python, from the FNV reference's offset basis and prime), so files written by
// any earlier kiosk keep reading back.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "panel/knob_state_file.h"

namespace weft::input {
namespace {

TEST(KnobStateChecksum, IsFnv1aOfTheCompactObjectWithoutIt) {
  const std::vector<PresetLook> presets{{"linen_plain", {}}, {"silk_shot", {}}};
  KnobPositions p;
  p.preset = 1;
  p.selection = ThreadSelection::warp;
  p.hue_steps = {3, 0};
  p.brightness_steps = {-2, 4};
  p.gloss_steps = {1, -1};
  p.env_steps = 5;
  const std::string text = knob_state_text(p, presets);
  const auto j = nlohmann::ordered_json::parse(text);
  // FNV-1a 64 of {"format":"weft-knobs","version":1,"preset":"silk_shot","selection":"warp","threads":[{"hue_steps":3,
  // "brightness_steps":-2,"gloss_steps":1},{"hue_steps":0,"brightness_steps":4,"gloss_steps":-1}],"env_steps":5}
  EXPECT_EQ(j.at("checksum"), "500b68d3070b66a0");
  EXPECT_EQ(parse_knob_state(text, presets), p);

  std::string damaged = text;
  damaged.replace(damaged.find("\"env_steps\": 5"), 14, "\"env_steps\": 6");
  EXPECT_THROW(parse_knob_state(damaged, presets), KnobStateError);
}

}  // namespace
}  // namespace weft::input
