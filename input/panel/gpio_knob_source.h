#pragma once
// Encoders wired to GPIO: waits for both-edge line events on its own thread and decodes them
// with the firmware core (GpioPanelDecoder). An absent chip is logged and retried with back-off.
#include <atomic>
#include <thread>

#include "panel/gpio_lines.h"
#include "panel/knob_source.h"
#include "panel/retry_backoff.h"

namespace weft::input {

class GpioKnobSource final : public KnobSource {
public:
  GpioKnobSource(GpioPanelConfig config, GpioOpener opener, LogSink log, Backoff backoff = {});
  ~GpioKnobSource() override;

  std::string describe() const override;
  void start(KnobSink sink) override;
  void stop() override;

  bool running_lines() const { return open_.load(); }
  uint64_t open_failures() const { return open_failures_.load(); }

private:
  void run(KnobSink sink);

  GpioPanelConfig config_;
  GpioOpener opener_;
  LogSink log_;
  Backoff backoff_;
  StopSignal stop_;
  std::thread thread_;
  std::atomic<bool> open_{false};
  std::atomic<uint64_t> open_failures_{0};
};

}  // namespace weft::input
