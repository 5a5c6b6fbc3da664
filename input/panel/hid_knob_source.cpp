#include "panel/hid_knob_source.h"

#include <cstdio>

namespace weft::input {
namespace {

std::string vid_pid(uint16_t vid, uint16_t pid) {
  char s[16];
  std::snprintf(s, sizeof s, "%04x:%04x", vid, pid);
  return s;
}

std::string seconds(std::chrono::milliseconds d) {
  char s[32];
  std::snprintf(s, sizeof s, "%.2g s", d.count() / 1000.0);
  return s;
}

// Log the first few malformed reports, then only every 1000th, so garbage cannot flood the journal.
bool worth_logging(uint64_t count) { return count <= 5 || count % 1000 == 0; }

}  // namespace

HidKnobSource::HidKnobSource(HidSourceOptions options, std::unique_ptr<HidTransport> transport, LogSink log)
    : options_(options), transport_(std::move(transport)), log_(log ? std::move(log) : stderr_log()) {}

HidKnobSource::~HidKnobSource() { stop(); }

std::string HidKnobSource::describe() const {
  return "USB knob panel " + vid_pid(options_.vendor_id, options_.product_id);
}

void HidKnobSource::start(KnobSink sink) {
  stop();
  stop_.clear();
  thread_ = std::thread([this, sink = std::move(sink)] { run(sink); });
}

void HidKnobSource::stop() {
  stop_.request();
  if (thread_.joinable()) thread_.join();
}

HidSourceStats HidKnobSource::stats() const {
  return {reports_.load(), malformed_.load(), lost_.load(), connects_.load(), disconnects_.load()};
}

void HidKnobSource::run(KnobSink sink) {
  const std::string name = describe();
  Backoff backoff = options_.backoff;
  bool announced_absent = false;
  std::unique_ptr<HidDevice> device;
  uint8_t buffer[64];
  while (!stop_.requested()) {
    if (!device) {
      std::string why;
      device = transport_->open(options_.vendor_id, options_.product_id, why);
      if (!device) {
        const auto wait = backoff.next();
        if (!announced_absent) {
          log_(LogPriority::warning, name + " not found (" + why + "); will keep looking, retrying every " +
               seconds(wait) + " up to " + seconds(backoff.longest));
          announced_absent = true;
        }
        if (stop_.wait_for(wait)) break;
        continue;
      }
      backoff.succeeded();
      announced_absent = false;
      have_sequence_ = false;
      ++connects_;
      connected_ = true;
      log_(LogPriority::info, name + " connected");
    }
    const int n = device->read(buffer, sizeof buffer, options_.read_timeout_ms);
    if (n < 0) {
      log_(LogPriority::warning, name + " read failed (" + device->last_error() +
           "): unplugged? closing it and looking for it again");
      device.reset();
      connected_ = false;
      ++disconnects_;
      if (stop_.wait_for(backoff.next())) break;
      continue;
    }
    if (n > 0) handle_report(buffer, n, sink);
  }
  connected_ = false;
}

void HidKnobSource::handle_report(const uint8_t* bytes, int size, const KnobSink& sink) {
  firmware::PanelReport report;
  const auto error = firmware::decode_report(bytes, static_cast<size_t>(size), report);
  if (error != firmware::ReportError::ok) {
    const uint64_t count = ++malformed_;
    if (worth_logging(count))
      log_(LogPriority::warning, "dropped a malformed report (" + std::string(firmware::report_error_text(error)) + ", " +
           std::to_string(size) + " bytes); " + std::to_string(count) + " dropped so far");
    return;
  }
  if (have_sequence_ && report.sequence != next_sequence_)
    lost_ += static_cast<uint8_t>(report.sequence - next_sequence_);
  have_sequence_ = true;
  next_sequence_ = static_cast<uint8_t>(report.sequence + 1);
  // Unwrap the panel's 16-bit millisecond clock.
  time_ms_ = have_time_ ? time_ms_ + static_cast<uint16_t>(report.time_ms - last_time16_) : report.time_ms;
  last_time16_ = report.time_ms;
  have_time_ = true;
  ++reports_;
  KnobEvent e;
  for (int i = 0; i < kDialCount; ++i) e.dial[i] = report.dial[i];
  e.buttons = report.buttons;
  e.time_ms = time_ms_;
  sink(e);
}

}  // namespace weft::input
