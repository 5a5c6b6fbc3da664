#pragma once
// Runs the panel firmware on simulated lines: samples the edges at the firmware's scan rate,
// polls for a report at the USB interrupt interval, and returns the exact bytes the panel sends.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "firmware/hid_report.h"
#include "firmware/panel_firmware.h"
#include "sim/line_waveform.h"

namespace weft::sim {

struct SimOptions {
  uint32_t scan_us = 1000;   // firmware line scan (1 kHz timer)
  uint32_t poll_us = 8000;   // USB full-speed interrupt endpoint, bInterval 8
  uint32_t tail_ms = 50;     // keep running after the last edge so debouncing settles
  firmware::FirmwareConfig firmware;
};

struct TimedReport {
  uint64_t time_us = 0;  // when the host received it (the poll)
  std::array<uint8_t, firmware::kReportSize> bytes{};
};

struct SimResult {
  std::vector<TimedReport> reports;
  std::array<uint32_t, firmware::kDialCount> illegal_steps{};
};

SimResult simulate_panel(const std::vector<LineEdge>& edges, const SimOptions& options = {});
// parse_knob_script → line_edges → simulate_panel.
SimResult simulate_script(const std::string& script, const SimOptions& options = {});

}  // namespace weft::sim
