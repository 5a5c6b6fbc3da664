#include "firmware/hid_report.h"

namespace weft::firmware {

// Vendor-defined usage page so no OS driver claims the panel as a mouse or joystick; the host
// reads it through hidraw. Button bits use the Button page for readability in descriptor dumps.
const uint8_t kReportDescriptor[] = {
    0x06, 0x00, 0xFF,        // Usage Page (Vendor Defined 0xFF00)
    0x09, 0x01,              // Usage (0x01: knob panel)
    0xA1, 0x01,              // Collection (Application)
    0x85, kReportId,         //   Report ID (1)
    0x09, 0x02,              //   Usage (0x02: sequence counter)
    0x15, 0x00,              //   Logical Minimum (0)
    0x26, 0xFF, 0x00,        //   Logical Maximum (255)
    0x75, 0x08,              //   Report Size (8)
    0x95, 0x01,              //   Report Count (1)
    0x81, 0x02,              //   Input (Data, Variable, Absolute)
    0x09, 0x03,              //   Usage (0x03: dial detents)
    0x15, 0x81,              //   Logical Minimum (−127)
    0x25, 0x7F,              //   Logical Maximum (127)
    0x75, 0x08,              //   Report Size (8)
    0x95, kDialCount,        //   Report Count (4)
    0x81, 0x06,              //   Input (Data, Variable, Relative)
    0x05, 0x09,              //   Usage Page (Button)
    0x19, 0x01,              //   Usage Minimum (1)
    0x29, 0x08,              //   Usage Maximum (8)
    0x15, 0x00,              //   Logical Minimum (0)
    0x25, 0x01,              //   Logical Maximum (1)
    0x75, 0x01,              //   Report Size (1)
    0x95, 0x08,              //   Report Count (8)
    0x81, 0x02,              //   Input (Data, Variable, Absolute)
    0x06, 0x00, 0xFF,        //   Usage Page (Vendor Defined 0xFF00)
    0x09, 0x04,              //   Usage (0x04: firmware time, ms)
    0x15, 0x00,              //   Logical Minimum (0)
    0x27, 0xFF, 0xFF, 0x00, 0x00,  // Logical Maximum (65535; 4-byte form so it is not −1)
    0x75, 0x10,              //   Report Size (16)
    0x95, 0x01,              //   Report Count (1)
    0x81, 0x02,              //   Input (Data, Variable, Absolute)
    0xC0,                    // End Collection
};
const size_t kReportDescriptorSize = sizeof(kReportDescriptor);

const char* report_error_text(ReportError e) {
  switch (e) {
    case ReportError::ok: return "ok";
    case ReportError::too_short: return "report too short";
    case ReportError::too_long: return "report too long";
    case ReportError::wrong_report_id: return "unknown report ID";
    case ReportError::dial_out_of_range: return "dial delta -128 is out of range";
    case ReportError::unused_buttons: return "unused button bits set";
  }
  return "unknown error";
}

size_t encode_report(const PanelReport& r, uint8_t* out, size_t capacity) {
  if (capacity < kReportSize) return 0;
  out[0] = kReportId;
  out[1] = r.sequence;
  for (int i = 0; i < kDialCount; ++i) out[2 + i] = static_cast<uint8_t>(r.dial[i]);
  out[6] = r.buttons;
  out[7] = static_cast<uint8_t>(r.time_ms & 0xFFu);  // little endian, as HID fields are
  out[8] = static_cast<uint8_t>(r.time_ms >> 8);
  return kReportSize;
}

ReportError decode_report(const uint8_t* bytes, size_t size, PanelReport& out) {
  if (size < kReportSize) return ReportError::too_short;
  if (size > kReportSize) return ReportError::too_long;
  if (bytes[0] != kReportId) return ReportError::wrong_report_id;
  PanelReport r;
  r.sequence = bytes[1];
  for (int i = 0; i < kDialCount; ++i) {
    if (bytes[2 + i] == 0x80) return ReportError::dial_out_of_range;
    r.dial[i] = static_cast<int8_t>(bytes[2 + i]);
  }
  r.buttons = bytes[6];
  if (r.buttons & ~kUsedButtonMask) return ReportError::unused_buttons;
  r.time_ms = static_cast<uint16_t>(bytes[7] | (bytes[8] << 8));
  out = r;
  return ReportError::ok;
}

}  // namespace weft::firmware
