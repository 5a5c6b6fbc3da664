// The knob backends end to end, without hardware: simulator bytes through the HID backend,
// simulator edges through the GPIO backend, garbage, unplugs and absent devices.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>

#include "panel/gpio_knob_source.h"
#include "panel/hid_knob_source.h"
#include "panel/keyboard_knob_source.h"
#include "panel/knob_controller.h"
#include "support/panel_fakes.h"
#include "sim/panel_simulator.h"

using namespace weft::input;
using namespace weft::test;

namespace {

// A shopper's session: hue +5, brightness +8, gloss +4 (both threads), then the warp alone
// 10 hue steps back, and the environment 3 steps back. 80 ms per detent: no acceleration.
const char* kSession =
    "turn 0 +5\nturn 1 +8\nturn 2 +4\nclick 0\nturn 0 -10\nturn 3 -3\n";

HidStep report_step(const weft::sim::TimedReport& r) {
  return {HidStep::bytes, std::vector<uint8_t>(r.bytes.begin(), r.bytes.end())};
}

std::unique_ptr<KnobController> linen_controller(LogCapture& log) {
  const auto presets = installed_presets();
  KnobControllerOptions options;
  options.default_preset = preset_index(presets, "linen_plain");
  auto c = std::make_unique<KnobController>(KnobMapper(presets), options, log.sink());
  c->restore();
  return c;
}

HidSourceOptions fast_retry() {
  HidSourceOptions o;
  o.read_timeout_ms = 5;
  o.backoff.first = o.backoff.current = std::chrono::milliseconds(1);
  o.backoff.longest = std::chrono::milliseconds(4);
  return o;
}

void expect_session_result(const KnobController& c) {
  AppearanceState s;
  ASSERT_TRUE(c.channel().read(s));
  // Worked out by hand from linen's A = (0.06, 0.24, 0.30) (hue 195°, s 0.8, v 0.3):
  // weft: hue 210°, v 0.6 → (0.12, 0.36, 0.60); warp: hue 180° → (0.12, 0.60, 0.60).
  const double expected[2][3] = {{0.12, 0.60, 0.60}, {0.12, 0.36, 0.60}};
  for (int t = 0; t < 2; ++t) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.thread[t].albedo[k], expected[t][k], 1e-6) << t << k;
    EXPECT_NEAR(s.thread[t].gamma_scale, std::sqrt(0.5), 1e-6);
  }
  EXPECT_EQ(s.env_rotation_deg, 345.0f);
  EXPECT_EQ(s.selection, ThreadSelection::warp);
}

void run_hid(FakeHidScript& script, KnobController& c, LogCapture& log, HidSourceStats* stats = nullptr) {
  HidKnobSource source(fast_retry(), std::make_unique<FakeHidTransport>(script), log.sink());
  source.start(c.sink());
  ASSERT_TRUE(wait_until([&] { return script.drained.load(); })) << log.all();
  source.stop();
  if (stats) *stats = source.stats();
}

}  // namespace

TEST(HidKnobSource, SimulatedSessionGivesExactParameters) {
  for (const char* hand : {"", "bounce 2 0.3\n"}) {
    SCOPED_TRACE(hand[0] ? "with contact bounce" : "clean contacts");
    const auto sim = weft::sim::simulate_script(std::string(hand) + kSession);
    FakeHidScript script;
    for (const auto& r : sim.reports) script.steps.push_back(report_step(r));
    LogCapture log;
    auto c = linen_controller(log);
    HidSourceStats stats;
    run_hid(script, *c, log, &stats);
    EXPECT_EQ(stats.reports, sim.reports.size());
    EXPECT_EQ(stats.malformed, 0u);
    EXPECT_EQ(stats.lost, 0u);
    EXPECT_TRUE(log.contains("USB knob panel 1209:57ef connected")) << log.all();
    expect_session_result(*c);
  }
}

TEST(HidKnobSource, GarbageAndShortReportsAreDroppedAndCounted) {
  const auto sim = weft::sim::simulate_script("turn 0 +1\nturn 0 +1\nturn 0 +1\n");
  ASSERT_EQ(sim.reports.size(), 3u);
  FakeHidScript script;
  script.steps.push_back(report_step(sim.reports[0]));
  script.steps.push_back({HidStep::bytes, {0x01, 0x01, 0x05, 0x00, 0x00}});              // short
  script.steps.push_back({HidStep::bytes, {0x55, 0xAA, 0x13, 0x37, 0, 0, 0, 0, 0}});     // wrong ID
  script.steps.push_back({HidStep::bytes, std::vector<uint8_t>(12, 0x01)});              // long
  script.steps.push_back({HidStep::bytes, {0x01, 0x01, 0x80, 0, 0, 0, 0, 0, 0}});        // −128
  script.steps.push_back({HidStep::bytes, {0x01, 0x01, 0x00, 0, 0, 0, 0xE0, 0, 0}});     // reserved bits
  script.steps.push_back({HidStep::bytes, {0x01}});                                      // one byte
  script.steps.push_back(report_step(sim.reports[2]));  // report 1 never arrives: a gap
  LogCapture log;
  auto c = linen_controller(log);
  HidSourceStats stats;
  run_hid(script, *c, log, &stats);
  EXPECT_EQ(stats.reports, 2u);
  EXPECT_EQ(stats.malformed, 6u);
  EXPECT_EQ(stats.lost, 1u);
  EXPECT_TRUE(log.contains("dropped a malformed report (report too short, 5 bytes); 1 dropped so far")) << log.all();
  EXPECT_TRUE(log.contains("unknown report ID")) << log.all();
  EXPECT_TRUE(log.contains("report too long, 12 bytes")) << log.all();
  EXPECT_EQ(c->positions().hue_steps[0], 2);  // only the two good reports moved the hue
}

TEST(HidKnobSource, UnplugMidReadReconnectsAndCarriesOn) {
  const auto sim = weft::sim::simulate_script("turn 0 +4\n");
  ASSERT_EQ(sim.reports.size(), 4u);
  FakeHidScript script;
  script.steps.push_back(report_step(sim.reports[0]));
  script.steps.push_back(report_step(sim.reports[1]));
  script.steps.push_back({HidStep::error, {}});           // pulled out mid-read
  script.open_results = {true, false, false, true};       // gone for two enumerations
  script.steps.push_back(report_step(sim.reports[2]));
  script.steps.push_back(report_step(sim.reports[3]));
  LogCapture log;
  auto c = linen_controller(log);
  HidSourceStats stats;
  run_hid(script, *c, log, &stats);
  EXPECT_EQ(stats.disconnects, 1u);
  EXPECT_EQ(stats.connects, 2u);
  EXPECT_EQ(script.failed_opens.load(), 2);
  EXPECT_TRUE(log.contains("read failed (No such device (fake unplug)): unplugged?")) << log.all();
  EXPECT_TRUE(log.contains("not found (no device matches (fake)); will keep looking")) << log.all();
  EXPECT_EQ(c->positions().hue_steps[0], 4);
}

TEST(HidKnobSource, AbsentDeviceIsLoggedNotFatal) {
  LogCapture log;
  auto c = linen_controller(log);
  HidSourceOptions o = fast_retry();
  o.vendor_id = 0x1209;
  o.product_id = 0xFFFE;  // no such panel on any test machine
  HidKnobSource source(o, make_hidapi_transport(), log.sink());
  source.start(c->sink());
  ASSERT_TRUE(wait_until([&] { return log.contains("USB knob panel 1209:fffe not found"); })) << log.all();
  source.stop();
  EXPECT_FALSE(source.connected());
  EXPECT_EQ(source.stats().reports, 0u);
}

TEST(GpioKnobSource, SimulatedEdgesGiveTheSameParametersAsHid) {
  for (const char* hand : {"", "bounce 3 0.2\n"}) {
    SCOPED_TRACE(hand[0] ? "with contact bounce" : "clean contacts");
    const auto edges = weft::sim::line_edges(weft::sim::parse_knob_script(std::string(hand) + kSession));
    std::atomic<bool> drained{false};
    LogCapture log;
    auto c = linen_controller(log);
    GpioOpener opener = [&](const GpioPanelConfig&, std::string&) {
      return std::unique_ptr<GpioLines>(new FakeGpioLines(edges, drained));
    };
    GpioKnobSource source(gpio_config_for_sim(), opener, log.sink());
    source.start(c->sink());
    ASSERT_TRUE(wait_until([&] { return drained.load(); }));
    source.stop();
    EXPECT_TRUE(log.contains("GPIO knobs on fake ready")) << log.all();
    expect_session_result(*c);
  }
}

TEST(GpioKnobSource, AbsentChipIsLoggedNotFatal) {
  LogCapture log;
  auto c = linen_controller(log);
  GpioPanelConfig config;
  config.chip = "weft-no-such-chip";
  Backoff backoff;
  backoff.first = backoff.current = std::chrono::milliseconds(1);
  GpioKnobSource source(config, {}, log.sink(), backoff);  // the real libgpiod opener
  source.start(c->sink());
  ASSERT_TRUE(wait_until([&] { return source.open_failures() >= 2; })) << log.all();
  source.stop();
  EXPECT_TRUE(log.contains("GPIO knobs on weft-no-such-chip unavailable (cannot open GPIO chip 'weft-no-such-chip'"))
      << log.all();
  EXPECT_FALSE(source.running_lines());
}

TEST(GpioPanelDecoder, ButtonsDebounceOnEdgeTimestamps) {
  GpioPanelDecoder d(gpio_config_for_sim());
  d.reset({}, 0);
  KnobEvent e;
  const unsigned reset_line = weft::sim::kFirstButtonLine + 4;
  EXPECT_FALSE(d.on_edge(reset_line, 0, 100, e));  // pressed, bouncing
  EXPECT_FALSE(d.on_edge(reset_line, 1, 101, e));
  EXPECT_FALSE(d.on_edge(reset_line, 0, 102, e));
  EXPECT_EQ(d.settle_timeout_ms(), 6);
  EXPECT_FALSE(d.on_idle(106, e));
  ASSERT_TRUE(d.on_idle(107, e));                  // stable 5 ms since 102
  EXPECT_EQ(e.buttons, 0x10);
  EXPECT_EQ(d.settle_timeout_ms(), -1);
}

TEST(KeyboardKnobSource, KeysBecomeKnobEvents) {
  const auto q = keyboard_events('q', 5);
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0].dial[0], 1);
  EXPECT_EQ(keyboard_events('F', 0).at(0).dial[3], -5);
  const auto click = keyboard_events(' ', 0);
  ASSERT_EQ(click.size(), 2u);
  EXPECT_EQ(click[0].buttons, 0x10);
  EXPECT_EQ(click[1].buttons, 0);
  EXPECT_TRUE(keyboard_events('x', 0).empty());
  EXPECT_EQ(keyboard_events('t', 0).at(0).zoom, 1);  // zoom closer / back
  EXPECT_EQ(keyboard_events('G', 0).at(0).zoom, -5);

  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  LogCapture log;
  auto c = linen_controller(log);
  KeyboardKnobSource source(fds[0], log.sink());
  source.start(c->sink());
  ASSERT_EQ(::write(fds[1], "w1", 2), 2);
  ::close(fds[1]);
  ASSERT_TRUE(wait_until([&] { return log.contains("input closed"); })) << log.all();
  source.stop();
  ::close(fds[0]);
  EXPECT_EQ(c->positions().brightness_steps, (std::array<int, 2>{1, 1}));
  EXPECT_EQ(c->positions().selection, ThreadSelection::warp);
}
