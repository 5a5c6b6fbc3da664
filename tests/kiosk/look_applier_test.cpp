// The look as one piece (kiosk/look_applier.h): which commands a knob state turns into, recorded
// by a sink that stands in for the kiosk's renderer.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "kiosk/idle_return.h"
#include "kiosk/knob_appearance.h"
#include "kiosk/look_applier.h"
#include "panel/knob_mapping.h"

using namespace weft;
using Clock = std::chrono::steady_clock;

namespace {

// One command as the sink received it.
struct Command {
  std::string name;  // wear_colourway, show_label, dress_cloth, aim_zoom, turn_light
  double value = 0;  // the colourway, the zoom, the light's turn; the preset for show_label
  Fabric fabric{};   // dress_cloth's
};

class RecordingSink final : public LookSink {
public:
  std::vector<Command> commands;

  void wear_colourway(std::uint32_t colourway) override { commands.push_back({"wear_colourway", double(colourway)}); }
  void show_label(std::uint32_t preset, std::uint32_t) override { commands.push_back({"show_label", double(preset)}); }
  void dress_cloth(const Fabric& fabric) override { commands.push_back({"dress_cloth", 0, fabric}); }
  void aim_zoom(double zoom) override { commands.push_back({"aim_zoom", zoom}); }
  void turn_light(float degrees) override { commands.push_back({"turn_light", degrees}); }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Command& c : commands) out.push_back(c.name);
    return out;
  }
  const Command& last(const std::string& name) const {
    for (auto c = commands.rbegin(); c != commands.rend(); ++c)
      if (c->name == name) return *c;
    throw std::runtime_error("no " + name);
  }
};

Fabric preset(const std::string& name, double red) {
  Fabric f;
  f.name = name;
  for (auto& t : f.threads) t.albedo = dvec3(red, 0.3, 0.2);
  return f;
}

// Two colourways of two presets each: the knobs dress colourway k's preset p.
struct Presets {
  std::vector<std::vector<Fabric>> by_colourway{{preset("linen", 0.6), preset("wool", 0.5)},
                                                {preset("linen", 0.2), preset("wool", 0.1)}};
  LookApplier::PresetsOf of() const {
    return [this](std::uint32_t k) -> const std::vector<Fabric>& { return by_colourway.at(k); };
  }
};

constexpr double kBaseZoom = 0.25;  // --zoom

}  // namespace

TEST(LookApplier, TheFirstLookIssuesEveryCommand) {
  RecordingSink sink;
  Presets presets;
  LookApplier look(sink, kBaseZoom, presets.of());
  input::AppearanceState s;
  s.preset_index = 1;
  s.zoom = 0.5f;
  s.env_rotation_deg = 30.0f;
  look.apply(s);
  EXPECT_EQ(sink.names(), (std::vector<std::string>{"wear_colourway", "show_label", "dress_cloth", "aim_zoom", "turn_light"}));
  EXPECT_EQ(sink.last("show_label").value, 1);
  EXPECT_EQ(sink.last("dress_cloth").fabric.name, "wool");
  EXPECT_DOUBLE_EQ(sink.last("aim_zoom").value, 0.75);
  EXPECT_DOUBLE_EQ(sink.last("turn_light").value, 30.0);
  ASSERT_TRUE(look.light_turn_deg());
  EXPECT_EQ(*look.light_turn_deg(), 30.0f);
  s.zoom = 1.0f;  // past the close-up: held there
  look.apply(s);
  EXPECT_DOUBLE_EQ(sink.last("aim_zoom").value, 1.0);
}

// Thread 0's hue, from a panel event to the fabric the cloth is dressed in: the dress alone.
TEST(LookApplier, AHueTurnDressesTheClothInItAndIssuesNothingElse) {
  RecordingSink sink;
  Presets presets;
  LookApplier look(sink, kBaseZoom, presets.of());
  input::KnobMapper mapper(preset_looks(presets.by_colourway[0]));
  input::KnobEvent select_warp;
  select_warp.buttons = 1;  // push dial 0: both threads → warp
  mapper.apply(select_warp);
  look.apply(mapper.appearance());
  const Fabric before = sink.last("dress_cloth").fabric;
  sink.commands.clear();

  input::KnobEvent turn;
  turn.dial[0] = 10;  // 30° of hue
  turn.time_ms = 1000;
  ASSERT_TRUE(mapper.apply(turn));
  look.apply(mapper.appearance());
  EXPECT_EQ(sink.names(), (std::vector<std::string>{"show_label", "dress_cloth"}));
  const Fabric& dressed = sink.last("dress_cloth").fabric;
  EXPECT_EQ(dressed.threads[0].albedo, apply_knobs(presets.by_colourway[0][0], mapper.appearance()).threads[0].albedo);
  EXPECT_NE(dressed.threads[0].albedo, before.threads[0].albedo);  // the warp turned
  EXPECT_EQ(dressed.threads[1].albedo, before.threads[1].albedo);  // the weft did not
}

TEST(LookApplier, EachOtherKnobIssuesItsOwnCommand) {
  RecordingSink sink;
  Presets presets;
  LookApplier look(sink, kBaseZoom, presets.of());
  input::AppearanceState s;
  look.apply(s);
  // The cloth is dressed and the label shown with every look (look_applier.h); the rest by knob.
  const std::vector<std::string> every = {"show_label", "dress_cloth"};
  auto after = [&](const std::string& command) {
    std::vector<std::string> names = every;
    if (command == "wear_colourway") names.insert(names.begin(), command);
    else if (!command.empty()) names.push_back(command);
    return names;
  };

  sink.commands.clear();
  s.zoom = 0.5f;
  look.apply(s);
  EXPECT_EQ(sink.names(), after("aim_zoom"));
  EXPECT_DOUBLE_EQ(sink.last("aim_zoom").value, 0.75);

  sink.commands.clear();
  s.env_rotation_deg = 45.0f;
  look.apply(s);
  EXPECT_EQ(sink.names(), after("turn_light"));

  sink.commands.clear();
  s.colourway = 1;
  look.apply(s);
  EXPECT_EQ(sink.names(), after("wear_colourway"));
  EXPECT_EQ(sink.last("wear_colourway").value, 1);
  EXPECT_EQ(sink.last("dress_cloth").fabric.threads[0].albedo, dvec3(0.5));  // the knobs' colour on colourway 1's linen
  EXPECT_EQ(sink.last("dress_cloth").fabric.threads[0].gamma_s, presets.by_colourway[1][0].threads[0].gamma_s);

  sink.commands.clear();
  s.preset_index = 1;
  s.thread[1].gamma_scale = 2.0f;
  look.apply(s);
  EXPECT_EQ(sink.names(), after(""));
  EXPECT_EQ(sink.last("dress_cloth").fabric.name, "wool");
  EXPECT_DOUBLE_EQ(sink.last("dress_cloth").fabric.threads[1].gamma_v, 2.0 * presets.by_colourway[1][1].threads[1].gamma_v);

  sink.commands.clear();
  s.selection = input::ThreadSelection::weft;  // the on-screen hint only
  look.apply(s);
  EXPECT_EQ(sink.names(), after(""));
}

TEST(LookApplier, ANewRendererGetsTheWholeLookButTheLightItWasLitWith) {
  RecordingSink sink;
  Presets presets;
  LookApplier look(sink, kBaseZoom, presets.of());
  input::AppearanceState s;
  s.env_rotation_deg = 90.0f;
  look.apply(s);
  look.new_renderer();
  EXPECT_FALSE(look.applied());
  ASSERT_TRUE(look.light_turn_deg());
  EXPECT_EQ(*look.light_turn_deg(), 90.0f);
  sink.commands.clear();
  look.apply(s);
  EXPECT_EQ(sink.names(), (std::vector<std::string>{"wear_colourway", "show_label", "dress_cloth", "aim_zoom"}));
}

// The way home is a run of looks through the same applier: at the end the sink holds what
// applying home directly gives, and the light turned back along the shorter arc.
TEST(LookApplier, IdleReturnGoesHomeThroughTheSameCommands) {
  RecordingSink sink;
  Presets presets;
  LookApplier look(sink, kBaseZoom, presets.of());
  input::AppearanceState home;  // the bundle's start: preset 0, unedited
  for (auto& t : home.thread)
    for (int c = 0; c < 3; ++c) t.albedo[c] = float(presets.by_colourway[0][0].threads[0].albedo[c]);
  input::AppearanceState away = home;
  away.thread[0].albedo[0] = 0.9f;
  away.thread[1].gamma_scale = 4.0f;
  away.env_rotation_deg = 300.0f;
  away.zoom = 1.0f;
  look.apply(away);

  IdleReturn idle(60.0, 3.0);
  const Clock::time_point t0 = Clock::now();
  idle.touched(t0);
  ASSERT_TRUE(idle.due(t0 + std::chrono::seconds(60)));
  idle.start(away, home, t0 + std::chrono::seconds(60));
  sink.commands.clear();
  int steps = 0;
  for (int ms = 0; ms <= 3000; ms += 100)
    if (const auto step = idle.step(t0 + std::chrono::seconds(60) + std::chrono::milliseconds(ms))) {
      look.apply(*step);
      ++steps;
    }
  EXPECT_EQ(steps, 31);
  ASSERT_TRUE(look.applied());
  EXPECT_EQ(*look.applied(), home);
  for (const Command& c : sink.commands) {
    if (c.name != "turn_light") continue;
    EXPECT_TRUE(c.value >= 300.0 || c.value == 0.0) << c.value;  // through 360°, not 180°
  }

  RecordingSink direct_sink;
  LookApplier direct(direct_sink, kBaseZoom, presets.of());
  direct.apply(home);
  for (const std::string name : {"dress_cloth", "aim_zoom", "turn_light"}) {
    EXPECT_EQ(sink.last(name).value, direct_sink.last(name).value) << name;
    EXPECT_EQ(sink.last(name).fabric.threads[0].albedo, direct_sink.last(name).fabric.threads[0].albedo) << name;
    EXPECT_EQ(sink.last(name).fabric.threads[1].gamma_s, direct_sink.last(name).fabric.threads[1].gamma_s) << name;
  }
  EXPECT_EQ(sink.names().front(), "show_label");  // the same colourway all the way: never worn again
}
