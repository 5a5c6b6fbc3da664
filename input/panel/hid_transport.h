#pragma once
// The byte source under the HID backend: the real one is hidapi (hidraw); tests substitute
// their own to feed simulator reports, garbage, read errors and absent devices.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace weft::input {

class HidDevice {
public:
  virtual ~HidDevice() = default;
  // Like hid_read_timeout: bytes read (report ID first), 0 on timeout, −1 on error.
  virtual int read(uint8_t* buffer, size_t capacity, int timeout_ms) = 0;
  // Why the last read failed.
  virtual std::string last_error() const = 0;
};

class HidTransport {
public:
  virtual ~HidTransport() = default;
  // Opens the first device with this VID/PID; nullptr (and `why`) when there is none.
  virtual std::unique_ptr<HidDevice> open(uint16_t vendor_id, uint16_t product_id, std::string& why) = 0;
};

// hidapi over hidraw. Call only from one thread (the HID source's).
std::unique_ptr<HidTransport> make_hidapi_transport();

}  // namespace weft::input
