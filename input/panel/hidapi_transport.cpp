#include <hidapi/hidapi.h>

#include <cwchar>

#include "panel/hid_transport.h"

namespace weft::input {
namespace {

std::string narrow(const wchar_t* w) {
  if (!w) return "unknown hidapi error";
  std::string s;
  for (; *w; ++w) s.push_back(*w < 128 ? static_cast<char>(*w) : '?');
  return s;
}

class HidapiDevice final : public HidDevice {
public:
  explicit HidapiDevice(hid_device* d) : d_(d) {}
  ~HidapiDevice() override { hid_close(d_); }
  int read(uint8_t* buffer, size_t capacity, int timeout_ms) override {
    return hid_read_timeout(d_, buffer, capacity, timeout_ms);
  }
  std::string last_error() const override { return narrow(hid_error(d_)); }

private:
  hid_device* d_;
};

class HidapiTransport final : public HidTransport {
public:
  HidapiTransport() : ok_(hid_init() == 0) {}
  ~HidapiTransport() override {
    if (ok_) hid_exit();
  }
  std::unique_ptr<HidDevice> open(uint16_t vid, uint16_t pid, std::string& why) override {
    if (!ok_) {
      why = "hidapi failed to initialise";
      return nullptr;
    }
    hid_device* d = hid_open(vid, pid, nullptr);
    if (!d) {
      why = narrow(hid_error(nullptr));
      return nullptr;
    }
    return std::make_unique<HidapiDevice>(d);
  }

private:
  bool ok_;
};

}  // namespace

std::unique_ptr<HidTransport> make_hidapi_transport() { return std::make_unique<HidapiTransport>(); }

}  // namespace weft::input
