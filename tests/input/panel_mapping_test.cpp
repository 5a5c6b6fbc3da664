// Knob → appearance mapping, the render hand-off, persistence and configuration.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <thread>

#include "panel/appearance_channel.h"
#include "panel/hsv_color.h"
#include "panel/keyboard_knob_source.h"
#include "panel/knob_controller.h"
#include "panel/knob_mapping.h"
#include "panel/knob_state_file.h"
#include "panel/panel_config.h"
#include "support/panel_fakes.h"

using namespace weft::input;
using weft::test::installed_presets;
using weft::test::LogCapture;
using weft::test::preset_index;

namespace {

KnobEvent turn(int dial, int detents, uint32_t time_ms) {
  KnobEvent e;
  e.dial[dial] = detents;
  e.time_ms = time_ms;
  return e;
}

KnobEvent buttons(uint8_t held, uint32_t time_ms = 0) {
  KnobEvent e;
  e.buttons = held;
  e.time_ms = time_ms;
  return e;
}

// Slow detents (200 ms apart: no acceleration), starting at `t`.
void slow_turn(KnobMapper& m, int dial, int detents, uint32_t& t) {
  for (int i = 0; i < std::abs(detents); ++i) m.apply(turn(dial, detents > 0 ? 1 : -1, t += 200));
}

void click(KnobMapper& m, int button) {
  m.apply(buttons(static_cast<uint8_t>(1u << button)));
  m.apply(buttons(0));
}

void expect_rgb(const ThreadAppearance& t, double r, double g, double b) {
  EXPECT_NEAR(t.albedo[0], r, 1e-6);
  EXPECT_NEAR(t.albedo[1], g, 1e-6);
  EXPECT_NEAR(t.albedo[2], b, 1e-6);
}

KnobMapper linen_mapper() {
  const auto presets = installed_presets();
  KnobMapper m(presets);
  KnobPositions p;
  p.preset = preset_index(presets, "linen_plain");
  m.set_positions(p);
  return m;
}

std::filesystem::path temp_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("weft_panel_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace

TEST(HsvColor, KnownConversions) {
  // Linen's A = (0.2, 0.8, 1.0)·0.3: max B, hue = 60·((R−G)/Δ + 4) = 195°, s = 0.24/0.3.
  const Hsv c = hsv_from_rgb(0.06, 0.24, 0.30);
  EXPECT_NEAR(c.h, 195.0, 1e-9);
  EXPECT_NEAR(c.s, 0.8, 1e-9);
  EXPECT_NEAR(c.v, 0.3, 1e-12);
  double rgb[3];
  rgb_from_hsv({210.0, 0.8, 0.3}, rgb);  // sector 3: (m, m + X, v) with X = C/2
  EXPECT_NEAR(rgb[0], 0.06, 1e-12);
  EXPECT_NEAR(rgb[1], 0.18, 1e-12);
  EXPECT_NEAR(rgb[2], 0.30, 1e-12);
  rgb_from_hsv({-120.0, 1.0, 1.0}, rgb);  // wraps to 240°: blue
  EXPECT_NEAR(rgb[0], 0.0, 1e-12);
  EXPECT_NEAR(rgb[2], 1.0, 1e-12);
  const Hsv grey = hsv_from_rgb(0.4, 0.4, 0.4);
  EXPECT_EQ(grey.s, 0.0);
}

TEST(KnobMapper, PresetIsTheStartingPoint) {
  const auto m = linen_mapper();
  const auto s = m.appearance();
  for (int t = 0; t < 2; ++t) {
    expect_rgb(s.thread[t], 0.06, 0.24, 0.30);
    EXPECT_EQ(s.thread[t].gamma_scale, 1.0f);
  }
  EXPECT_EQ(s.env_rotation_deg, 0.0f);
  EXPECT_EQ(s.selection, ThreadSelection::both);
}

TEST(KnobMapper, HueBrightnessGlossExactValues) {
  auto m = linen_mapper();
  uint32_t t = 0;
  slow_turn(m, 0, +5, t);  // hue 195° + 5·3° = 210°
  expect_rgb(m.appearance().thread[0], 0.06, 0.18, 0.30);
  slow_turn(m, 1, +8, t);  // value ×2 → 0.6
  expect_rgb(m.appearance().thread[1], 0.12, 0.36, 0.60);
  slow_turn(m, 2, +4, t);  // half an octave glossier
  EXPECT_NEAR(m.appearance().thread[0].gamma_scale, 1.0 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(m.appearance().thread[1].gamma_scale, 1.0 / std::sqrt(2.0), 1e-6);
  // Select the warp only (push dial 0 twice: both → warp) and turn its hue back 10 steps to 180°.
  click(m, 0);
  EXPECT_EQ(m.positions().selection, ThreadSelection::warp);
  slow_turn(m, 0, -10, t);
  expect_rgb(m.appearance().thread[0], 0.12, 0.60, 0.60);
  expect_rgb(m.appearance().thread[1], 0.12, 0.36, 0.60);
  // Environment: −3 steps wraps to 345°, its push sets it back to 0°.
  slow_turn(m, 3, -3, t);
  EXPECT_EQ(m.appearance().env_rotation_deg, 345.0f);
  click(m, 3);
  EXPECT_EQ(m.appearance().env_rotation_deg, 0.0f);
  // Reset: every edit of this fabric undone.
  slow_turn(m, 3, +2, t);
  click(m, 4);
  for (int th = 0; th < 2; ++th) {
    expect_rgb(m.appearance().thread[th], 0.06, 0.24, 0.30);
    EXPECT_EQ(m.appearance().thread[th].gamma_scale, 1.0f);
  }
  EXPECT_EQ(m.appearance().env_rotation_deg, 0.0f);
}

TEST(KnobMapper, Limits) {
  auto m = linen_mapper();
  uint32_t t = 0;
  m.apply(turn(1, +100, t += 200));
  // A may not exceed 1: floor(8·log2(1/0.3)) = 13 steps.
  EXPECT_EQ(m.positions().brightness_steps[0], 13);
  EXPECT_NEAR(m.appearance().thread[0].albedo[2], 0.3 * std::exp2(13.0 / 8.0), 1e-6);
  m.apply(turn(1, -100, t += 200));
  EXPECT_EQ(m.positions().brightness_steps[0], -24);
  EXPECT_NEAR(m.appearance().thread[0].albedo[2], 0.3 / 8.0, 1e-6);
  m.apply(turn(2, +100, t += 200));
  EXPECT_EQ(m.appearance().thread[0].gamma_scale, 0.25f);
  m.apply(turn(2, -100, t += 200));
  EXPECT_EQ(m.appearance().thread[1].gamma_scale, 4.0f);
  m.apply(turn(0, 125, t += 200));  // 375° wraps to 15° more than the preset
  EXPECT_EQ(m.positions().hue_steps[0], 5);
}

TEST(KnobMapper, Acceleration) {
  auto m = linen_mapper();
  m.apply(turn(2, +1, 1000));   // first: ×1
  m.apply(turn(2, +1, 1100));   // 100 ms later: ×1
  m.apply(turn(2, +1, 1130));   // 30 ms: ×2
  m.apply(turn(2, +1, 1140));   // 10 ms: ×4
  m.apply(turn(2, -1, 1145));   // reversal: ×1
  m.apply(turn(2, -2, 1155));   // 10 ms, same way, 2 detents: −8
  EXPECT_EQ(m.positions().gloss_steps[0], 1 + 1 + 2 + 4 - 1 - 8);
  m.apply(turn(3, -1, 1200));   // each dial keeps its own timing: ×1
  EXPECT_EQ(m.positions().env_steps, 71);  // 5° steps wrap at 72
}

TEST(KnobMapper, ButtonsActOnPressNotHold) {
  const auto presets = installed_presets();
  KnobMapper m(presets);
  m.apply(buttons(0b100));  // next preset
  m.apply(buttons(0b100));  // still held: nothing
  EXPECT_EQ(m.positions().preset, 1u);
  m.apply(buttons(0));
  m.apply(buttons(0b010));  // previous
  m.apply(buttons(0));
  m.apply(buttons(0b010));  // previous again: wraps to the last
  EXPECT_EQ(m.positions().preset, presets.size() - 1);
  // A new preset starts unedited.
  uint32_t t = 0;
  slow_turn(m, 0, 3, t);
  m.apply(buttons(0b100));
  EXPECT_EQ(m.positions().hue_steps[0], 0);
  EXPECT_EQ(m.positions().preset, 0u);
}

TEST(AppearanceChannel, ReadersNeverSeeATornState) {
  // The writer publishes states whose every field equals a counter; a torn copy would mix two.
  AppearanceChannel ch;
  std::atomic<bool> stop{false};
  std::atomic<uint32_t> last_published{0};
  std::thread writer([&] {
    for (uint32_t i = 1; !stop; ++i) {
      AppearanceState s;
      s.preset_index = i;
      for (auto& th : s.thread) {
        for (float& a : th.albedo) a = static_cast<float>(i % 1000000);
        th.gamma_scale = static_cast<float>(i % 1000000);
      }
      s.env_rotation_deg = static_cast<float>(i % 1000000);
      ch.publish(s);
      last_published = i;
    }
  });
  uint64_t reads = 0, torn = 0, backwards = 0;
  uint32_t last = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (reads < 100000 && std::chrono::steady_clock::now() < end) {
    AppearanceState s;
    if (!ch.read(s) || s.preset_index == 0) continue;  // 0: the default state before the first write
    ++reads;
    const float v = static_cast<float>(s.preset_index % 1000000);
    for (const auto& th : s.thread) {
      for (float a : th.albedo) torn += a != v;
      torn += th.gamma_scale != v;
    }
    torn += s.env_rotation_deg != v;
    backwards += s.preset_index < last;
    last = s.preset_index;
  }
  stop = true;
  writer.join();
  EXPECT_GT(reads, 0u);
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  AppearanceState final_state;
  uint64_t version = 0;
  ASSERT_TRUE(ch.read(final_state, &version));
  EXPECT_EQ(final_state.preset_index, last_published.load());
  EXPECT_EQ(version, last_published.load());
}

TEST(KnobStateFile, RoundTrip) {
  const auto presets = installed_presets();
  KnobPositions p;
  p.preset = preset_index(presets, "silk_shot");
  p.selection = ThreadSelection::weft;
  p.hue_steps = {7, 100};
  p.brightness_steps = {-3, 2};
  p.gloss_steps = {16, -5};
  p.env_steps = 44;
  const auto dir = temp_dir("roundtrip");
  const auto file = dir / "knobs.json";
  std::string why;
  ASSERT_TRUE(write_file_atomically(file, knob_state_text(p, presets), why)) << why;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);  // no temporary left
  const auto r = restore_knob_state(file, presets, 0);
  EXPECT_TRUE(r.from_file) << r.message;
  EXPECT_EQ(r.positions, p);
  EXPECT_NE(r.message.find("restored"), std::string::npos);
  // Overwriting replaces the whole file.
  p.env_steps = 3;
  ASSERT_TRUE(write_file_atomically(file, knob_state_text(p, presets), why)) << why;
  EXPECT_EQ(restore_knob_state(file, presets, 0).positions, p);
  std::filesystem::remove_all(dir);
}

TEST(KnobStateFile, CorruptFilesFallBackToThePresetAndSayWhy) {
  const auto presets = installed_presets();
  KnobPositions p;
  p.preset = 1;
  p.hue_steps = {4, 4};
  const std::string good = knob_state_text(p, presets);
  const auto dir = temp_dir("corrupt");
  const auto file = dir / "knobs.json";
  auto flip = [](std::string s, const std::string& from, const std::string& to) {
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const std::vector<std::pair<std::string, std::string>> cases{
      {good.substr(0, good.size() / 2), "not valid JSON"},               // torn write
      {"", "not valid JSON"},                                            // empty
      {std::string("\x00\xff\x13garbage", 10), "not valid JSON"},
      {flip(good, "\"hue_steps\": 4", "\"hue_steps\": 5"), "checksum mismatch"},  // bit rot
      {flip(good, "weft-knobs", "something"), "not a weft knob state file"},
      {"[1,2,3]", "not a weft knob state file"},
      {"{\"format\": [1], \"checksum\": \"0\"}", "not a weft knob state file"},  // fuzzer find
      {"{\"format\": 7}", "not a weft knob state file"},
  };
  for (const auto& [text, reason] : cases) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    const auto r = restore_knob_state(file, presets, 2);
    EXPECT_FALSE(r.from_file);
    EXPECT_EQ(r.positions, KnobPositions{.preset = 2}) << r.message;
    EXPECT_NE(r.message.find("unusable"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find(reason), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("falling back to preset '" + presets[2].name + "'"), std::string::npos) << r.message;
  }
  // A preset that is no longer installed.
  std::vector<PresetLook> fewer(presets.begin() + 2, presets.end());
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good;
  const auto r = restore_knob_state(file, fewer, 0);
  EXPECT_FALSE(r.from_file);
  EXPECT_NE(r.message.find("is not installed"), std::string::npos) << r.message;
  // Missing file: not an error, but said.
  const auto missing = restore_knob_state(dir / "none.json", presets, 0);
  EXPECT_FALSE(missing.from_file);
  EXPECT_NE(missing.message.find("no saved knob state"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(KnobStateFile, UnwritableDirectoryIsReported) {
  std::string why;
  EXPECT_FALSE(write_file_atomically("/nonexistent-weft-dir/knobs.json", "{}", why));
  EXPECT_NE(why.find("cannot create"), std::string::npos) << why;
}

TEST(KnobController, PublishesSavesAndRestores) {
  const auto presets = installed_presets();
  const auto dir = temp_dir("controller");
  LogCapture log;
  KnobControllerOptions options;
  options.state_file = dir / "knobs.json";
  options.default_preset = preset_index(presets, "linen_plain");
  options.save_delay = std::chrono::milliseconds(20);
  KnobPositions saved;
  {
    KnobController c(KnobMapper(presets), options, log.sink());
    c.restore();
    EXPECT_TRUE(log.contains("no saved knob state")) << log.all();
    const uint64_t v0 = c.channel().version();
    c.on_event(turn(0, +5, 200));
    EXPECT_EQ(c.channel().version(), v0 + 1);
    AppearanceState s;
    ASSERT_TRUE(c.channel().read(s));
    expect_rgb(s.thread[0], 0.06, 0.18, 0.30);
    ASSERT_TRUE(weft::test::wait_until([&] { return c.saves() == 1; }));
    saved = c.positions();
  }
  KnobController again(KnobMapper(presets), options, log.sink());
  again.restore();
  EXPECT_TRUE(log.contains("restored knob state")) << log.all();
  EXPECT_EQ(again.positions(), saved);
  AppearanceState s;
  ASSERT_TRUE(again.channel().read(s));
  expect_rgb(s.thread[1], 0.06, 0.18, 0.30);
  std::filesystem::remove_all(dir);
}

TEST(PanelConfig, ParsesAndRejects) {
  const auto c = parse_panel_config(R"({"sources":["hid","gpio"],"hid":{"vendor_id":"0x1d50","product_id":4660},
      "gpio":{"chip":"gpiochip4","encoder_a":[1,2,3,-1],"debounce_ms":8},"state_file":"/tmp/k.json"})", "panel.json");
  EXPECT_EQ(c.sources, (std::vector<std::string>{"hid", "gpio"}));
  EXPECT_EQ(c.hid.vendor_id, 0x1d50);
  EXPECT_EQ(c.hid.product_id, 4660);
  EXPECT_EQ(c.gpio.chip, "gpiochip4");
  EXPECT_EQ(c.gpio.encoder_a[3], -1);
  EXPECT_EQ(c.gpio.debounce_ms, 8);
  EXPECT_EQ(c.state_file, "/tmp/k.json");
  const auto d = parse_panel_config("{}", "panel.json");
  EXPECT_EQ(d.hid.vendor_id, weft::firmware::kPanelVendorId);
  auto rejects = [](const std::string& text, const std::string& says) {
    try {
      parse_panel_config(text, "panel.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const PanelConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  rejects("{", "not valid JSON");
  rejects(R"({"hid":{"vendor_id":"0x12345"}})", "hid.vendor_id");
  rejects(R"({"hid":{"product_id":"zz"}})", "hid.product_id");
  rejects(R"({"sources":["usb"]})", "unknown knob source");
  rejects(R"({"gpio":{"encoder_b":[1,2]}})", "gpio.encoder_b");
  rejects(R"({"gpio":{"buttons":[1,2,3,4,"x"]}})", "gpio.buttons[4]");
}

TEST(KnobMapper, ZoomStepsToTheCloseUpAndBackWithinItsLimits) {
  KnobMapper m = linen_mapper();
  EXPECT_EQ(m.appearance().zoom, 0.0f);
  KnobEvent in;
  in.zoom = 3;
  EXPECT_TRUE(m.apply(in));
  EXPECT_FLOAT_EQ(m.appearance().zoom, 3.0f / 8.0f);
  in.zoom = 40;  // past the close-up: held there
  m.apply(in);
  EXPECT_FLOAT_EQ(m.appearance().zoom, 1.0f);
  EXPECT_FALSE(m.apply(in));  // nothing changes at the limit
  KnobEvent next;
  next.buttons = 4;  // the next preset keeps the view
  m.apply(next);
  EXPECT_FLOAT_EQ(m.appearance().zoom, 1.0f);
  in.zoom = -100;
  m.apply(in);
  EXPECT_EQ(m.appearance().zoom, 0.0f);
  // A dial given to the zoom zooms instead of its own job.
  MappingConfig c;
  c.zoom_dial = 3;
  KnobMapper z(installed_presets(), c);
  KnobEvent turn;
  turn.dial[3] = 2;
  z.apply(turn);
  EXPECT_FLOAT_EQ(z.appearance().zoom, 2.0f / 8.0f);
  EXPECT_EQ(z.appearance().env_rotation_deg, 0.0f);
}

TEST(PanelConfig, ZoomDialIsADialOrNone) {
  EXPECT_EQ(parse_panel_config(R"({"sources": ["keyboard"]})", "p.json").zoom_dial, -1);
  EXPECT_EQ(parse_panel_config(R"({"zoom_dial": 3})", "p.json").zoom_dial, 3);
  for (const char* bad : {R"({"zoom_dial": 4})", R"({"zoom_dial": -2})", R"({"zoom_dial": 1.5})", R"({"zoom_dial": "3"})"})
    EXPECT_THROW(parse_panel_config(bad, "p.json"), PanelConfigError) << bad;
}

TEST(PanelConfig, AnEmptySourceListIsRefused) {
  EXPECT_THROW(parse_panel_config(R"({"sources": []})", "p.json"), PanelConfigError);
}

namespace {

// Two colourways over the installed presets: "Ocean" dresses linen_plain blue, "Moss" velvet green.
std::vector<ColourwayPresets> two_colourways(const std::vector<PresetLook>& presets) {
  std::vector<ColourwayPresets> c(2);
  c[0] = {"Ocean", presets, preset_index(presets, "linen_plain")};
  c[0].presets[c[0].start_preset].albedo = {{{0.03, 0.09, 0.18}, {0.03, 0.09, 0.18}}};
  c[1] = {"Moss", presets, preset_index(presets, "velvet")};
  c[1].presets[c[1].start_preset].albedo = {{{0.1, 0.25, 0.05}, {0.1, 0.25, 0.05}}};
  return c;
}

KnobEvent next_colourway() {
  KnobEvent e;
  e.colourway = 1;
  return e;
}

}  // namespace

TEST(KnobMapper, TheColourwayControlStepsThroughTheColourwaysEachStartingUnedited) {
  const auto presets = installed_presets();
  KnobMapper m(presets);
  EXPECT_FALSE(m.apply(next_colourway()));  // without colourways it does nothing
  m.set_colourways(two_colourways(presets));
  EXPECT_EQ(m.colourway_names(), (std::vector<std::string>{"Ocean", "Moss"}));
  AppearanceState s = m.appearance();
  EXPECT_EQ(s.colourway, 0u);
  EXPECT_EQ(s.preset_index, preset_index(presets, "linen_plain"));
  expect_rgb(s.thread[0], 0.03, 0.09, 0.18);
  uint32_t t = 0;
  slow_turn(m, 0, 10, t);  // a hue edit of Ocean
  EXPECT_TRUE(m.apply(next_colourway()));
  s = m.appearance();
  EXPECT_EQ(s.colourway, 1u);
  EXPECT_EQ(s.preset_index, preset_index(presets, "velvet"));
  expect_rgb(s.thread[1], 0.1, 0.25, 0.05);  // Moss, unedited
  EXPECT_EQ(m.positions().hue_steps[0], 0);
  slow_turn(m, 1, -8, t);  // the knobs edit the colourway worn: half as bright
  expect_rgb(m.appearance().thread[0], 0.05, 0.125, 0.025);
  EXPECT_TRUE(m.apply(next_colourway()));  // wraps round to Ocean
  EXPECT_EQ(m.appearance().colourway, 0u);
  expect_rgb(m.appearance().thread[0], 0.03, 0.09, 0.18);
}

TEST(KnobMapper, AColourwayButtonCyclesInsteadOfItsOwnJob) {
  const auto presets = installed_presets();
  MappingConfig config;
  config.colourway_button = 3;
  KnobMapper m(presets, config);
  m.set_colourways(two_colourways(presets));
  uint32_t t = 0;
  slow_turn(m, 3, 4, t);  // the environment turned
  click(m, 3);            // not "environment back to 0°": the next colourway
  EXPECT_EQ(m.appearance().colourway, 1u);
  click(m, 3);
  EXPECT_EQ(m.appearance().colourway, 0u);
  const auto keys = keyboard_events('c', 5);
  ASSERT_EQ(keys.size(), 1u);
  EXPECT_EQ(keys[0].colourway, 1);
  EXPECT_EQ(parse_panel_config(R"({"colourway_button": 4})", "p.json").colourway_button, 4);
  EXPECT_EQ(parse_panel_config("{}", "p.json").colourway_button, -1);
  for (const char* bad : {R"({"colourway_button": 5})", R"({"colourway_button": -2})", R"({"colourway_button": "1"})"})
    EXPECT_THROW(parse_panel_config(bad, "p.json"), PanelConfigError) << bad;
}

TEST(KnobStateFile, TheColourwayWornIsSavedAndRestoredByName) {
  const auto presets = installed_presets();
  const auto dir = temp_dir("colourway");
  LogCapture log;
  KnobControllerOptions options;
  options.state_file = dir / "knobs.json";
  options.default_preset = preset_index(presets, "linen_plain");
  options.save_delay = std::chrono::milliseconds(20);
  const auto controller = [&] {
    KnobMapper m(presets);
    m.set_colourways(two_colourways(presets));
    return std::make_unique<KnobController>(std::move(m), options, log.sink());
  };
  {
    auto c = controller();
    c->restore();
    c->on_event(next_colourway());
    c->on_event(turn(2, 3, 100));
    c->flush();
  }
  auto again = controller();
  again->restore();
  EXPECT_TRUE(log.contains("colourway 'Moss'")) << log.all();
  AppearanceState s;
  ASSERT_TRUE(again->channel().read(s));
  EXPECT_EQ(s.colourway, 1u);
  EXPECT_EQ(s.preset_index, preset_index(presets, "velvet"));
  EXPECT_EQ(again->positions().gloss_steps[0], 3);
  // A colourway the bundle does not have: the first colourway's start, saying why.
  const auto r = restore_knob_state(options.state_file, presets, options.default_preset, {"Ocean", "Sand"});
  EXPECT_TRUE(r.unusable);
  EXPECT_NE(r.message.find("colourway 'Moss' is not in the bundle"), std::string::npos) << r.message;
  EXPECT_EQ(r.positions.colourway, 0u);
  std::filesystem::remove_all(dir);
}
