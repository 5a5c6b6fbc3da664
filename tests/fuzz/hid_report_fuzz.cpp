// libFuzzer target for HID input. The input is a stream of reports as hidraw would
// deliver them ([length byte][bytes]…). Each report is decoded on its own (a report that
// decodes must encode back to the same bytes), then the whole stream goes through the real HID
// backend (HidKnobSource, with a transport that serves it) into the knob mapper: whatever the
// panel sends, the appearance the renderer gets stays finite and inside the knobs' limits.
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <vector>

#include "firmware/hid_report.h"
#include "panel/hid_knob_source.h"
#include "panel/knob_mapping.h"

namespace {

using namespace weft::input;
namespace fw = weft::firmware;

using Report = std::vector<std::uint8_t>;

// Serves the reports once, then reports an unplug and signals that the stream is used up.
class StreamDevice final : public HidDevice {
public:
  StreamDevice(const std::vector<Report>& reports, std::mutex& m, std::condition_variable& cv, bool& done)
      : reports_(reports), m_(m), cv_(cv), done_(done) {}
  int read(std::uint8_t* buffer, std::size_t capacity, int) override {
    if (next_ == reports_.size()) {
      std::lock_guard lock(m_);
      done_ = true;
      cv_.notify_all();
      return -1;
    }
    const Report& r = reports_[next_++];
    const std::size_t n = std::min(capacity, r.size());
    if (n > 0) std::memcpy(buffer, r.data(), n);
    return static_cast<int>(n);
  }
  std::string last_error() const override { return "end of fuzz input"; }

private:
  const std::vector<Report>& reports_;
  std::size_t next_ = 0;
  std::mutex& m_;
  std::condition_variable& cv_;
  bool& done_;
};

class StreamTransport final : public HidTransport {
public:
  StreamTransport(const std::vector<Report>& reports, std::mutex& m, std::condition_variable& cv, bool& done)
      : reports_(reports), m_(m), cv_(cv), done_(done) {}
  std::unique_ptr<HidDevice> open(std::uint16_t, std::uint16_t, std::string& why) override {
    if (opened_) {
      why = "unplugged";
      return nullptr;
    }
    opened_ = true;
    return std::make_unique<StreamDevice>(reports_, m_, cv_, done_);
  }

private:
  const std::vector<Report>& reports_;
  bool opened_ = false;
  std::mutex& m_;
  std::condition_variable& cv_;
  bool& done_;
};

void check_appearance(const AppearanceState& a) {
  for (const ThreadAppearance& t : a.thread) {
    for (float c : t.albedo)
      if (!std::isfinite(c) || c < 0.0f || c > 1.0f) __builtin_trap();
    if (!std::isfinite(t.gamma_scale) || t.gamma_scale < 0.24f || t.gamma_scale > 4.01f) __builtin_trap();
  }
  if (!std::isfinite(a.env_rotation_deg) || a.env_rotation_deg < 0.0f || a.env_rotation_deg >= 360.0f)
    __builtin_trap();
  if (a.preset_index > 1) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<Report> reports;
  for (std::size_t i = 0; i < size;) {
    const std::size_t n = std::min<std::size_t>(data[i] % 65, size - i - 1);
    reports.emplace_back(data + i + 1, data + i + 1 + n);
    i += 1 + n;
  }
  for (const Report& r : reports) {
    fw::PanelReport decoded;
    if (fw::decode_report(r.data(), r.size(), decoded) == fw::ReportError::ok) {
      std::uint8_t again[fw::kReportSize];
      if (fw::encode_report(decoded, again, sizeof again) != r.size() || std::memcmp(again, r.data(), r.size()) != 0)
        __builtin_trap();
    }
  }

  KnobMapper mapper({{"linen_plain", {{{0.06, 0.24, 0.3}, {0.06, 0.24, 0.3}}}},
                     {"velvet", {{{0.015, 0.006, 0.0}, {0.015, 0.006, 0.0}}}}});
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  {
    HidSourceOptions options;
    options.read_timeout_ms = 1;
    HidKnobSource source(options, std::make_unique<StreamTransport>(reports, m, cv, done), [](weft::LogPriority, const std::string&) {});
    source.start([&](const KnobEvent& e) {  // runs on the source's thread only
      mapper.apply(e);
      check_appearance(mapper.appearance());
    });
    std::unique_lock lock(m);
    cv.wait(lock, [&] { return done; });
  }  // stops and joins the source
  check_appearance(mapper.appearance());
  return 0;
}
