#include "sim/panel_simulator.h"

namespace weft::sim {

SimResult simulate_panel(const std::vector<LineEdge>& edges, const SimOptions& options) {
  SimResult result;
  firmware::PanelFirmware fw(options.firmware);
  firmware::PanelLines lines;  // all high: encoders at rest, buttons released
  fw.reset(lines, 0);
  const uint64_t end_us = (edges.empty() ? 0 : edges.back().time_us) + options.tail_ms * 1000ull;
  const uint64_t scan = options.scan_us ? options.scan_us : 1000;
  const uint64_t poll = options.poll_us ? options.poll_us : 8000;
  size_t next = 0;
  for (uint64_t t = 0; t <= end_us; t += scan) {
    for (; next < edges.size() && edges[next].time_us <= t; ++next) {
      const LineEdge& e = edges[next];
      uint8_t* byte = e.line < kFirstButtonLine ? (e.line % 2 == 0 ? &lines.a : &lines.b) : &lines.buttons;
      const int bit = e.line < kFirstButtonLine ? e.line / 2 : e.line - kFirstButtonLine;
      if (e.level) *byte = static_cast<uint8_t>(*byte | (1u << bit));
      else *byte = static_cast<uint8_t>(*byte & ~(1u << bit));
    }
    const uint32_t now_ms = static_cast<uint32_t>(t / 1000);
    fw.scan(lines, now_ms);
    if (t % poll == 0) {
      firmware::PanelReport report;
      if (fw.poll_report(now_ms, report)) {
        TimedReport r;
        r.time_us = t;
        firmware::encode_report(report, r.bytes.data(), r.bytes.size());
        result.reports.push_back(r);
      }
    }
  }
  for (int i = 0; i < firmware::kDialCount; ++i) result.illegal_steps[i] = fw.illegal_steps(i);
  return result;
}

SimResult simulate_script(const std::string& script, const SimOptions& options) {
  return simulate_panel(line_edges(parse_knob_script(script)), options);
}

}  // namespace weft::sim
