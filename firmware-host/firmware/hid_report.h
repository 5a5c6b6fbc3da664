#pragma once
// The knob panel's USB HID input report: its descriptor, encoding and decoding.
// Format: firmware-host/REPORT_FORMAT.md. No heap, no OS calls.
#include <cstddef>
#include <cstdint>

namespace weft::firmware {

inline constexpr uint16_t kPanelVendorId = 0x1209;   // pid.codes open-source vendor ID
inline constexpr uint16_t kPanelProductId = 0x57EF;  // "Weft" panel (placeholder until assigned)
inline constexpr int kDialCount = 4;
inline constexpr int kButtonCount = 5;               // 4 dial pushes + reset
inline constexpr uint8_t kReportId = 0x01;
inline constexpr size_t kReportSize = 9;             // bytes on the wire, report ID included
inline constexpr uint8_t kUsedButtonMask = (1u << kButtonCount) - 1u;

struct PanelReport {
  uint8_t sequence = 0;            // +1 per report, wraps 255 → 0
  int8_t dial[kDialCount] = {};    // detents since the previous report, −127..127, + = clockwise
  uint8_t buttons = 0;             // bit i set = button i held down (debounced)
  uint16_t time_ms = 0;            // firmware clock (ms, wraps) when the report was built
};

enum class ReportError : uint8_t {
  ok,
  too_short,       // fewer than kReportSize bytes
  too_long,        // more than kReportSize bytes
  wrong_report_id, // first byte is not kReportId
  dial_out_of_range,  // −128 is outside the descriptor's logical range
  unused_buttons,  // a bit above kButtonCount is set
};
const char* report_error_text(ReportError e);

// The HID report descriptor the panel presents (vendor-defined application collection).
extern const uint8_t kReportDescriptor[];
extern const size_t kReportDescriptorSize;

// Writes the report (ID first) into `out`; returns kReportSize, or 0 if `capacity` is too small.
size_t encode_report(const PanelReport& report, uint8_t* out, size_t capacity);
// Parses `size` bytes as received from hidraw (report ID first). On error `out` is untouched.
ReportError decode_report(const uint8_t* bytes, size_t size, PanelReport& out);

}  // namespace weft::firmware
