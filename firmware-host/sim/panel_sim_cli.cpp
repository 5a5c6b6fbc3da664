#include "sim/panel_sim_cli.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>

#include "sim/panel_simulator.h"

namespace {

const char* kUsage =
    "usage: weft-panel-sim [options] [SCRIPT|-]\n"
    "Runs the knob panel's firmware core on a scripted hand and prints the HID input reports\n"
    "it sends (report format: firmware-host/REPORT_FORMAT.md). Reads stdin when SCRIPT is - or\n"
    "absent.\n"
    "\n"
    "options:\n"
    "  --format hex|timed|binary  hex: one report per line as hex bytes (default);\n"
    "                             timed: the same prefixed with the host receive time in ms;\n"
    "                             binary: the raw 9-byte reports back to back on stdout\n"
    "  --edges                    print the contact edges instead (time_us line level)\n"
    "  --scan-us N                firmware line scan period (default 1000)\n"
    "  --poll-ms N                USB interrupt polling interval (default 8)\n"
    "  --debounce-ms N            button debounce time (default 5)\n"
    "  --uhid                     instead of printing: create the panel as a real HID device\n"
    "                             through the kernel's uhid (root; modprobe uhid), wait until a\n"
    "                             host opens it (hidraw), send the reports at their times, keep\n"
    "                             it plugged for --hold-ms, then unplug it (destroy)\n"
    "  --uhid-path PATH           the uhid device (default /dev/uhid)\n"
    "  --panel-config FILE        the kiosk's panel config: take the USB VID/PID from its \"hid\"\n"
    "                             section (default 1209:57ef, the panel's own)\n"
    "  --open-timeout-ms N        how long --uhid waits for a host to open it (default 30000)\n"
    "  --hold-ms N                how long --uhid stays plugged after the last report (default 1000)\n"
    "  -h, --help                 this text\n"
    "\n"
    "script (one command per line, times in ms, # comments):\n"
    "  wait <ms> | at <ms>\n"
    "  turn <dial 0-3> <+-detents> [every <ms>]     (default 80 ms per detent)\n"
    "  press <button 0-4> | release <button> | click <button> [hold <ms>]\n"
    "  bounce <count> [<period_ms>]                 contact chatter on later edges\n"
    "  glitch <dial> <a|b> [<width_ms>]             a lone spike on one line\n"
    "example:\n"
    "  printf 'turn 0 +3\\nbounce 2 0.4\\nclick 4\\n' | weft-panel-sim --format timed\n"
    "exit status: 0 ok, 1 uhid failure (no /dev/uhid, nobody opened the panel), 2 bad usage or\n"
    "bad script\n";

bool parse_uint(const char* s, unsigned long& out) {
  char* end = nullptr;
  out = std::strtoul(s, &end, 10);
  return end && *end == 0 && *s != 0 && *s != '-';
}

// Plays the reports in real time on a uhid panel: the script's clock starts once a host has the
// device open, so no report is sent into a device nobody reads.
int play_on_uhid(const weft::sim::SimResult& result, const std::string& uhid_path, const weft::sim::UhidIdentity& id,
                 unsigned long open_timeout_ms, unsigned long hold_ms) {
  using Clock = std::chrono::steady_clock;
  try {
    const auto t0 = Clock::now();
    auto panel = weft::sim::UhidPanel::open(uhid_path, id);
    std::fprintf(stderr, "weft-panel-sim: created %04x:%04x on %s\n", id.vendor_id, id.product_id, uhid_path.c_str());
    if (!panel.wait_until_opened(static_cast<int>(open_timeout_ms))) {
      std::fprintf(stderr, "weft-panel-sim: nobody opened the panel within %lu ms\n", open_timeout_ms);
      return 1;
    }
    const auto start = Clock::now();
    std::fprintf(stderr, "weft-panel-sim: opened by a host after %.0f ms\n",
                 std::chrono::duration<double, std::milli>(start - t0).count());
    for (const auto& r : result.reports) {
      std::this_thread::sleep_until(start + std::chrono::microseconds(r.time_us));
      panel.send_report(r.bytes.data(), r.bytes.size());
    }
    std::fprintf(stderr, "weft-panel-sim: sent %zu reports\n", result.reports.size());
    std::this_thread::sleep_for(std::chrono::milliseconds(hold_ms));
    panel.destroy();
    std::fprintf(stderr, "weft-panel-sim: unplugged\n");
  } catch (const weft::sim::UhidError& e) {
    std::fprintf(stderr, "weft-panel-sim: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace

int weft::sim::panel_sim_main(int argc, char** argv, const PanelConfigReader& read_panel_config) {
  std::string format = "hex", path = "-";
  bool edges_only = false, uhid = false;
  std::string uhid_path = "/dev/uhid", panel_config;
  unsigned long open_timeout_ms = 30000, hold_ms = 1000;
  weft::sim::SimOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "weft-panel-sim: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    auto number = [&](const char* name, unsigned long lo, unsigned long hi) {
      unsigned long v = 0;
      const char* s = value(name);
      if (!parse_uint(s, v) || v < lo || v > hi) {
        std::fprintf(stderr, "weft-panel-sim: %s wants an integer %lu..%lu, got '%s'\n", name, lo, hi, s);
        std::exit(2);
      }
      return v;
    };
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (arg == "--format") {
      format = value("--format");
      if (format != "hex" && format != "timed" && format != "binary") {
        std::fprintf(stderr, "weft-panel-sim: --format must be hex, timed or binary\n");
        return 2;
      }
    } else if (arg == "--edges") {
      edges_only = true;
    } else if (arg == "--uhid") {
      uhid = true;
    } else if (arg == "--uhid-path") {
      uhid_path = value("--uhid-path");
    } else if (arg == "--panel-config") {
      panel_config = value("--panel-config");
    } else if (arg == "--open-timeout-ms") {
      open_timeout_ms = number("--open-timeout-ms", 0, 3600000);
    } else if (arg == "--hold-ms") {
      hold_ms = number("--hold-ms", 0, 3600000);
    } else if (arg == "--scan-us") {
      options.scan_us = static_cast<uint32_t>(number("--scan-us", 1000, 100000));
      if (options.scan_us % 1000 != 0) {
        std::fprintf(stderr, "weft-panel-sim: --scan-us must be whole milliseconds (the firmware clock)\n");
        return 2;
      }
    } else if (arg == "--poll-ms") {
      options.poll_us = static_cast<uint32_t>(number("--poll-ms", 1, 255)) * 1000;
    } else if (arg == "--debounce-ms") {
      options.firmware.debounce_ms = static_cast<uint16_t>(number("--debounce-ms", 0, 1000));
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      std::fprintf(stderr, "weft-panel-sim: unknown option '%s' (see --help)\n", arg.c_str());
      return 2;
    } else {
      path = arg;
    }
  }
  weft::sim::UhidIdentity id;
  id.vendor_id = weft::firmware::kPanelVendorId;
  id.product_id = weft::firmware::kPanelProductId;
  if (!panel_config.empty()) {
    try {
      id = read_panel_config(panel_config);
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "weft-panel-sim: %s\n", e.what());
      return 2;
    }
  }
  std::stringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
  } else {
    std::ifstream f(path);
    if (!f) {
      std::fprintf(stderr, "weft-panel-sim: cannot open script '%s'\n", path.c_str());
      return 2;
    }
    text << f.rdbuf();
  }
  try {
    const auto actions = weft::sim::parse_knob_script(text.str());
    const auto edges = weft::sim::line_edges(actions);
    if (edges_only) {
      for (const auto& e : edges) std::printf("%llu %d %d\n", (unsigned long long)e.time_us, e.line, e.level);
      return 0;
    }
    const auto result = weft::sim::simulate_panel(edges, options);
    if (uhid) return play_on_uhid(result, uhid_path, id, open_timeout_ms, hold_ms);
    for (const auto& r : result.reports) {
      if (format == "binary") {
        std::fwrite(r.bytes.data(), 1, r.bytes.size(), stdout);
        continue;
      }
      if (format == "timed") std::printf("%10.3f ", r.time_us / 1000.0);
      for (size_t i = 0; i < r.bytes.size(); ++i) std::printf(i ? " %02x" : "%02x", r.bytes[i]);
      std::printf("\n");
    }
    for (int d = 0; d < weft::firmware::kDialCount; ++d)
      if (result.illegal_steps[d])
        std::fprintf(stderr, "weft-panel-sim: dial %d: %u missed-state (double) steps decoded\n", d,
                     result.illegal_steps[d]);
  } catch (const weft::sim::ScriptError& e) {
    std::fprintf(stderr, "weft-panel-sim: %s\n", e.what());
    return 2;
  }
  return 0;
}
