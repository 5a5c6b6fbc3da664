#include <gpiod.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "panel/gpio_lines.h"

namespace weft::input {
namespace {

constexpr const char* kConsumer = "weft-panel";

class GpiodLines final : public GpioLines {
public:
  GpiodLines(gpiod_chip* chip, gpiod_line_bulk bulk) : chip_(chip), bulk_(bulk) {}
  ~GpiodLines() override {
    gpiod_line_release_bulk(&bulk_);
    gpiod_chip_close(chip_);
  }
  std::vector<std::pair<unsigned, int>> levels() override {
    std::vector<std::pair<unsigned, int>> out;
    int values[GPIOD_LINE_BULK_MAX_LINES] = {};
    if (gpiod_line_get_value_bulk(&bulk_, values) != 0) return out;
    for (unsigned i = 0; i < bulk_.num_lines; ++i) out.emplace_back(gpiod_line_offset(bulk_.lines[i]), values[i]);
    return out;
  }
  Wait wait(int timeout_ms, std::vector<GpioEdge>& out) override {
    timespec ts{timeout_ms / 1000, (timeout_ms % 1000) * 1000000L};
    gpiod_line_bulk ready;
    const int r = gpiod_line_event_wait_bulk(&bulk_, &ts, &ready);
    if (r < 0) return error("waiting for line events");
    if (r == 0) return Wait::timeout;
    for (unsigned i = 0; i < ready.num_lines; ++i) {
      gpiod_line_event events[16];
      const int n = gpiod_line_event_read_multiple(ready.lines[i], events, 16);
      if (n < 0) return error("reading line events");
      for (int k = 0; k < n; ++k)
        out.push_back({gpiod_line_offset(ready.lines[i]), events[k].event_type == GPIOD_LINE_EVENT_RISING_EDGE,
                       static_cast<uint64_t>(events[k].ts.tv_sec) * 1000000000ull + events[k].ts.tv_nsec});
    }
    std::stable_sort(out.begin(), out.end(), [](const GpioEdge& a, const GpioEdge& b) { return a.time_ns < b.time_ns; });
    return Wait::edges;
  }
  uint64_t now_ns() override {
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<uint64_t>(ts.tv_sec) * 1000000000ull + ts.tv_nsec;
  }
  std::string last_error() const override { return error_; }

private:
  Wait error(const char* what) {
    error_ = std::string(what) + ": " + std::strerror(errno);
    return Wait::error;
  }
  gpiod_chip* chip_;
  gpiod_line_bulk bulk_;
  std::string error_;
};

}  // namespace

std::unique_ptr<GpioLines> open_gpiod_lines(const GpioPanelConfig& config, std::string& why) {
  gpiod_chip* chip = gpiod_chip_open_lookup(config.chip.c_str());
  if (!chip) {
    why = "cannot open GPIO chip '" + config.chip + "': " + std::strerror(errno);
    return nullptr;
  }
  const auto offsets = config.offsets();
  gpiod_line_bulk bulk;
  if (offsets.empty() || offsets.size() > GPIOD_LINE_BULK_MAX_LINES ||
      gpiod_chip_get_lines(chip, const_cast<unsigned*>(offsets.data()), offsets.size(), &bulk) != 0) {
    why = "GPIO chip '" + config.chip + "' lacks the configured lines: " + std::strerror(errno);
    gpiod_chip_close(chip);
    return nullptr;
  }
  gpiod_line_request_config request{kConsumer, GPIOD_LINE_REQUEST_EVENT_BOTH_EDGES,
                                    GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP};
  if (gpiod_line_request_bulk(&bulk, &request, nullptr) != 0) {
    why = "cannot request lines on '" + config.chip + "' (busy or no permission): " + std::strerror(errno);
    gpiod_chip_close(chip);
    return nullptr;
  }
  return std::make_unique<GpiodLines>(chip, bulk);
}

}  // namespace weft::input
