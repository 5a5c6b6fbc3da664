#pragma once
// The edge source under the GPIO backend: the real one is libgpiod (v1 API, both-edge line
// events); tests substitute their own to feed the simulator's edges or fail on purpose.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "panel/gpio_panel_decoder.h"

namespace weft::input {

struct GpioEdge {
  unsigned offset = 0;
  int level = 0;        // after the edge
  uint64_t time_ns = 0; // kernel timestamp (CLOCK_MONOTONIC on Linux ≥ 5.7)
};

class GpioLines {
public:
  enum class Wait { edges, timeout, error };
  virtual ~GpioLines() = default;
  virtual std::vector<std::pair<unsigned, int>> levels() = 0;
  // Waits up to `timeout_ms` for edges; appends them to `out` in time order.
  virtual Wait wait(int timeout_ms, std::vector<GpioEdge>& out) = 0;
  virtual uint64_t now_ns() = 0;
  virtual std::string last_error() const = 0;
};

// Requests the configured lines; nullptr and `why` when the chip or a line is unavailable.
using GpioOpener = std::function<std::unique_ptr<GpioLines>(const GpioPanelConfig&, std::string& why)>;
std::unique_ptr<GpioLines> open_gpiod_lines(const GpioPanelConfig& config, std::string& why);

}  // namespace weft::input
