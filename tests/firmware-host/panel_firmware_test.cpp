// The panel firmware core: decoder, debouncer, report encoding, descriptor, simulator bytes.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <vector>

#include "firmware/button_debouncer.h"
#include "firmware/hid_report.h"
#include "firmware/quadrature_decoder.h"
#include "sim/knob_script.h"
#include "sim/line_waveform.h"
#include "sim/panel_simulator.h"

using namespace weft::firmware;
using namespace weft::sim;

namespace {

// Feeds a state sequence, returns the total detents.
int feed(QuadratureDecoder& d, std::initializer_list<uint8_t> states) {
  int total = 0;
  for (uint8_t s : states) total += d.update(s);
  return total;
}

}  // namespace

TEST(QuadratureDecoder, FullCycleIsOneDetentEachWay) {
  QuadratureDecoder d;
  EXPECT_EQ(feed(d, {0b10, 0b00, 0b01, 0b11}), +1);  // 11→10→00→01→11 clockwise
  EXPECT_EQ(feed(d, {0b01, 0b00, 0b10, 0b11}), -1);
  EXPECT_EQ(d.illegal_steps(), 0u);
}

TEST(QuadratureDecoder, DetentOnlyCountsAtRest) {
  QuadratureDecoder d;
  EXPECT_EQ(d.update(0b10), 0);
  EXPECT_EQ(d.update(0b00), 0);
  EXPECT_EQ(d.update(0b01), 0);
  EXPECT_EQ(d.update(0b11), 1);
}

TEST(QuadratureDecoder, BounceCancels) {
  QuadratureDecoder d;
  // Chatter on B at rest, then chatter at every transition of a clockwise detent.
  EXPECT_EQ(feed(d, {0b10, 0b11, 0b10, 0b11}), 0);
  EXPECT_EQ(feed(d, {0b10, 0b11, 0b10, 0b00, 0b10, 0b00, 0b01, 0b00, 0b01, 0b11}), +1);
  EXPECT_EQ(d.illegal_steps(), 0u);
}

TEST(QuadratureDecoder, HalfTurnAndBackIsNothing) {
  QuadratureDecoder d;
  EXPECT_EQ(feed(d, {0b10, 0b00, 0b10, 0b11}), 0);
}

TEST(QuadratureDecoder, DoubleStepFollowsLastDirection) {
  QuadratureDecoder d;
  // 11→10 (+1), then 10→01 skips 00: counted +2 in the last direction, →11 (+1): one detent.
  EXPECT_EQ(feed(d, {0b10, 0b01, 0b11}), +1);
  EXPECT_EQ(d.illegal_steps(), 1u);
  // Counter-clockwise with a miss: 11→01 (−1), 01→10 (double, −2), 10→11 (−1).
  EXPECT_EQ(feed(d, {0b01, 0b10, 0b11}), -1);
  EXPECT_EQ(d.illegal_steps(), 2u);
}

TEST(QuadratureDecoder, DoubleStepWithoutDirectionIsIgnored) {
  QuadratureDecoder d;
  // Fresh decoder: 11→00 has no known direction, so it adds nothing; 00→01→11 adds +2 → rounds to 1.
  EXPECT_EQ(feed(d, {0b00, 0b01, 0b11}), +1);
  QuadratureDecoder e;
  // A lone double step out and back: nothing.
  EXPECT_EQ(feed(e, {0b00, 0b11}), 0);
  EXPECT_EQ(e.illegal_steps(), 2u);
}

TEST(ButtonDebouncer, AcceptsOnlyStableLevels) {
  ButtonDebouncer b(5);
  b.reset(false, 0);
  EXPECT_FALSE(b.update(true, 10));
  EXPECT_FALSE(b.update(false, 11));  // chatter restarts the clock
  EXPECT_FALSE(b.update(true, 12));
  EXPECT_FALSE(b.update(true, 16));
  EXPECT_TRUE(b.update(true, 17));    // held 5 ms since 12
  EXPECT_TRUE(b.update(false, 30));
  EXPECT_FALSE(b.update(false, 35));
}

TEST(HidReport, RoundTripAndWireLayout) {
  PanelReport r;
  r.sequence = 200;
  r.dial[0] = -3;
  r.dial[3] = 127;
  r.buttons = 0b10001;
  r.time_ms = 0x1234;
  uint8_t bytes[kReportSize];
  ASSERT_EQ(encode_report(r, bytes, sizeof bytes), kReportSize);
  const std::vector<uint8_t> expected{0x01, 200, 0xFD, 0, 0, 0x7F, 0x11, 0x34, 0x12};
  EXPECT_EQ(std::vector<uint8_t>(bytes, bytes + kReportSize), expected);
  PanelReport back;
  ASSERT_EQ(decode_report(bytes, kReportSize, back), ReportError::ok);
  EXPECT_EQ(back.sequence, 200);
  EXPECT_EQ(back.dial[0], -3);
  EXPECT_EQ(back.dial[3], 127);
  EXPECT_EQ(back.buttons, 0b10001);
  EXPECT_EQ(back.time_ms, 0x1234);
  EXPECT_EQ(encode_report(r, bytes, kReportSize - 1), 0u);
}

TEST(HidReport, RejectsMalformed) {
  const uint8_t good[kReportSize] = {1, 0, 1, 0, 0, 0, 0, 0, 0};
  PanelReport out;
  EXPECT_EQ(decode_report(good, 5, out), ReportError::too_short);
  EXPECT_EQ(decode_report(good, 0, out), ReportError::too_short);
  uint8_t longer[kReportSize + 1] = {1};
  EXPECT_EQ(decode_report(longer, sizeof longer, out), ReportError::too_long);
  uint8_t b[kReportSize];
  std::copy(good, good + kReportSize, b);
  b[0] = 2;
  EXPECT_EQ(decode_report(b, kReportSize, out), ReportError::wrong_report_id);
  b[0] = 1;
  b[4] = 0x80;
  EXPECT_EQ(decode_report(b, kReportSize, out), ReportError::dial_out_of_range);
  b[4] = 0;
  b[6] = 0x20;
  EXPECT_EQ(decode_report(b, kReportSize, out), ReportError::unused_buttons);
}

// A minimal HID descriptor walker (HID 1.11 §6.2.2): sums the Input bits per report ID and
// records the logical range of the dial field, independently of encode_report.
TEST(HidReport, DescriptorDescribesTheEncodedReport) {
  std::map<int, int> input_bits;
  int report_size = 0, report_count = 0, report_id = 0, depth = 0;
  long logical_min = 0, logical_max = 0;
  std::vector<std::pair<long, long>> relative_ranges;
  for (size_t i = 0; i < kReportDescriptorSize;) {
    const uint8_t prefix = kReportDescriptor[i];
    const int size = (prefix & 3) == 3 ? 4 : (prefix & 3);
    const int type = (prefix >> 2) & 3, tag = prefix >> 4;
    ASSERT_LE(i + 1 + size, kReportDescriptorSize);
    long value = 0;
    for (int k = 0; k < size; ++k) value |= static_cast<long>(kReportDescriptor[i + 1 + k]) << (8 * k);
    long signed_value = value;
    if (size == 1) signed_value = static_cast<int8_t>(value);
    if (size == 2) signed_value = static_cast<int16_t>(value);
    if (type == 1 && tag == 7) report_size = static_cast<int>(value);
    if (type == 1 && tag == 9) report_count = static_cast<int>(value);
    if (type == 1 && tag == 8) report_id = static_cast<int>(value);
    if (type == 1 && tag == 1) logical_min = signed_value;
    if (type == 1 && tag == 2) logical_max = size == 4 ? value : signed_value;
    if (type == 0 && tag == 8) {
      input_bits[report_id] += report_size * report_count;
      if (value & 4) relative_ranges.emplace_back(logical_min, logical_max);
    }
    if (type == 0 && tag == 10) ++depth;
    if (type == 0 && tag == 12) --depth;
    i += 1 + size;
  }
  EXPECT_EQ(depth, 0);
  ASSERT_EQ(input_bits.size(), 1u);
  EXPECT_EQ(input_bits.begin()->first, kReportId);
  EXPECT_EQ(input_bits.begin()->second, 8 * static_cast<int>(kReportSize - 1));
  ASSERT_EQ(relative_ranges.size(), 1u);
  EXPECT_EQ(relative_ranges[0], std::make_pair(-127L, 127L));
}

TEST(KnobScript, ParsesAndRejectsWithLineNumbers) {
  const auto a = parse_knob_script("# hand\nturn 1 -2 every 40\nwait 10\nclick 4 hold 30\n");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].target, 1);
  EXPECT_EQ(a[0].detents, -2);
  EXPECT_EQ(a[0].duration_us, 40000u);
  EXPECT_EQ(a[1].kind, KnobAction::Kind::press);
  EXPECT_EQ(a[1].start_us, 90000u);
  EXPECT_EQ(a[2].kind, KnobAction::Kind::release);
  EXPECT_EQ(a[2].start_us, 120000u);
  try {
    parse_knob_script("turn 0 +1\nturn 7 +1\n");
    FAIL() << "dial 7 accepted";
  } catch (const ScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_knob_script("spin 0 1\n"), ScriptError);
  EXPECT_THROW(parse_knob_script("wait -5\n"), ScriptError);
  EXPECT_THROW(parse_knob_script("wait 10\nat 5\n"), ScriptError);
  EXPECT_THROW(parse_knob_script("press 5\n"), ScriptError);
  EXPECT_THROW(line_edges(parse_knob_script("bounce 5 1\nturn 0 +1 every 8\n")), ScriptError);
}

TEST(LineWaveform, OneDetentIsFourGrayTransitions) {
  const auto edges = line_edges(parse_knob_script("turn 0 +1 every 8\n"));
  ASSERT_EQ(edges.size(), 4u);
  // From rest 11 clockwise: B falls (10), A falls (00), B rises (01), A rises (11).
  const std::vector<std::pair<int, int>> expected{{1, 0}, {0, 0}, {1, 1}, {0, 1}};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(edges[i].line, expected[i].first);
    EXPECT_EQ(edges[i].level, expected[i].second);
    EXPECT_EQ(edges[i].time_us, 1000u + 2000u * i);
  }
}

// The exact bytes for a short script, worked out by hand from the timing rules:
// a detent every 80 ms completes at its fourth transition (70 ms in), the 1 kHz scan sees it at
// the next ms, and the 8 ms poll sends it; the reset click is debounced 5 ms.
TEST(PanelSimulator, ExactReportsForAScript) {
  const auto result = simulate_script("turn 0 +2\nturn 3 -1 every 40\nclick 4\n");
  std::vector<std::vector<uint8_t>> got;
  std::vector<uint64_t> at;
  for (const auto& r : result.reports) {
    got.emplace_back(r.bytes.begin(), r.bytes.end());
    at.push_back(r.time_us / 1000);
  }
  const std::vector<std::vector<uint8_t>> expected{
      {1, 0, 1, 0, 0, 0, 0, 72, 0},      // dial 0 +1 at 72 ms
      {1, 1, 1, 0, 0, 0, 0, 152, 0},     // dial 0 +1 at 152 ms
      {1, 2, 0, 0, 0, 0xFF, 0, 200, 0},  // dial 3 −1: 160 + 35 = 195 ms → poll 200
      {1, 3, 0, 0, 0, 0, 0x10, 208, 0},  // reset pressed at 200, stable at 205 → poll 208
      {1, 4, 0, 0, 0, 0, 0, 0x20, 1},    // released at 280, stable 285 → poll 288 = 0x120
  };
  EXPECT_EQ(got, expected);
  EXPECT_EQ(at, (std::vector<uint64_t>{72, 152, 200, 208, 288}));
}

TEST(PanelSimulator, BounceAndGlitchesDoNotMoveTheDials) {
  const auto clean = simulate_script("turn 1 +3\nturn 1 -1\n");
  const auto bouncy = simulate_script("bounce 3 1\nturn 1 +3\nturn 1 -1\nglitch 1 a 2\nwait 20\nglitch 1 b 0.5\n");
  auto totals = [](const SimResult& r) {
    int sum = 0, n = 0;
    for (const auto& rep : r.reports) sum += static_cast<int8_t>(rep.bytes[3]), n += rep.bytes[3] != 0;
    return std::make_pair(sum, n);
  };
  EXPECT_EQ(totals(clean), std::make_pair(2, 4));
  EXPECT_EQ(totals(bouncy), std::make_pair(2, 4));
}

TEST(PanelSimulator, FastTurnsWithMissedStatesStillCount) {
  // 3 ms per detent with a 1 ms scan: many samples see two transitions at once.
  const auto r = simulate_script("turn 2 +10 every 3\nwait 100\nturn 2 -10 every 3\n");
  int sum_cw = 0, sum_ccw = 0;
  for (const auto& rep : r.reports) {
    const int d = static_cast<int8_t>(rep.bytes[4]);
    (d > 0 ? sum_cw : sum_ccw) += d;
  }
  EXPECT_GT(r.illegal_steps[2], 0u);
  EXPECT_EQ(sum_cw, 10);
  EXPECT_EQ(sum_ccw, -10);
}

TEST(PanelSimulator, ShortClickStillReported) {
  // Held 6 ms: debounced at 5 ms but released before the next poll could see it held.
  const auto r = simulate_script("at 1\nclick 2 hold 6\n");
  ASSERT_EQ(r.reports.size(), 2u);
  EXPECT_EQ(r.reports[0].bytes[6], 0x04);
  EXPECT_EQ(r.reports[1].bytes[6], 0x00);
}

TEST(PanelSimulator, SequenceCounterWraps) {
  std::string script;
  for (int i = 0; i < 300; ++i) script += "turn 0 +1 every 8\n";
  const auto r = simulate_script(script);
  int total = 0;
  for (size_t i = 0; i < r.reports.size(); ++i) {
    EXPECT_EQ(r.reports[i].bytes[1], static_cast<uint8_t>(i));
    total += static_cast<int8_t>(r.reports[i].bytes[2]);
  }
  EXPECT_EQ(total, 300);
  EXPECT_EQ(r.reports.size(), 300u);
}

TEST(PanelSimulator, MotionBeyondOneReportCarriesOver) {
  // A host that polls only every 2 s: 300 detents pile up and leave as 127 + 127 + 46.
  SimOptions options;
  options.poll_us = 2000000;
  options.tail_ms = 6000;
  const auto r = simulate_script("turn 0 +300 every 4\n", options);
  std::vector<int> deltas;
  for (const auto& rep : r.reports) deltas.push_back(static_cast<int8_t>(rep.bytes[2]));
  EXPECT_EQ(deltas, (std::vector<int>{127, 127, 46}));
}

// The udev rule grants the kiosk access by VID/PID; it must name the ids the firmware presents.
TEST(UdevRule, MatchesTheFirmwareIds) {
  std::ifstream in(std::string(WEFT_SOURCE_ASSETS) + "/../systemd/70-weft-panel.rules");
  ASSERT_TRUE(in) << "systemd/70-weft-panel.rules missing";
  std::string line, hidraw_rule;
  while (std::getline(in, line))
    if (line.rfind("SUBSYSTEM==\"hidraw\"", 0) == 0) hidraw_rule = line;
  char vid[8], pid[8];
  std::snprintf(vid, sizeof vid, "%04x", kPanelVendorId);
  std::snprintf(pid, sizeof pid, "%04x", kPanelProductId);
  EXPECT_NE(hidraw_rule.find(std::string("ATTRS{idVendor}==\"") + vid + "\""), std::string::npos) << hidraw_rule;
  EXPECT_NE(hidraw_rule.find(std::string("ATTRS{idProduct}==\"") + pid + "\""), std::string::npos) << hidraw_rule;
  EXPECT_NE(hidraw_rule.find("GROUP=\"weft\""), std::string::npos) << hidraw_rule;
}
