#pragma once
// The USB knob panel through hidapi: finds it by VID/PID, reads reports on its own thread with
// a timeout, re-enumerates with back-off after an unplug, drops and counts malformed reports,
// and counts reports lost in transit from gaps in the sequence counter.
#include <atomic>
#include <memory>
#include <thread>

#include "panel/hid_transport.h"
#include "panel/knob_source.h"
#include "panel/retry_backoff.h"

namespace weft::input {

struct HidSourceOptions {
  uint16_t vendor_id = firmware::kPanelVendorId;
  uint16_t product_id = firmware::kPanelProductId;
  int read_timeout_ms = 100;  // bounds how long stop() waits
  Backoff backoff;
};

struct HidSourceStats {
  uint64_t reports = 0;      // accepted
  uint64_t malformed = 0;    // dropped
  uint64_t lost = 0;         // missing sequence numbers
  uint64_t connects = 0;
  uint64_t disconnects = 0;  // read errors (unplug)
};

class HidKnobSource final : public KnobSource {
public:
  HidKnobSource(HidSourceOptions options, std::unique_ptr<HidTransport> transport, LogSink log);
  ~HidKnobSource() override;

  std::string describe() const override;
  void start(KnobSink sink) override;
  void stop() override;

  HidSourceStats stats() const;
  bool connected() const { return connected_.load(); }

private:
  void run(KnobSink sink);
  void handle_report(const uint8_t* bytes, int size, const KnobSink& sink);

  HidSourceOptions options_;
  std::unique_ptr<HidTransport> transport_;
  LogSink log_;
  StopSignal stop_;
  std::thread thread_;
  std::atomic<bool> connected_{false};
  std::atomic<uint64_t> reports_{0}, malformed_{0}, lost_{0}, connects_{0}, disconnects_{0};
  // Reader-thread state.
  bool have_sequence_ = false;
  uint8_t next_sequence_ = 0;
  bool have_time_ = false;
  uint16_t last_time16_ = 0;
  uint32_t time_ms_ = 0;  // the panel's 16-bit clock, unwrapped
};

}  // namespace weft::input
