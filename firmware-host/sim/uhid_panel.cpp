#include "sim/uhid_panel.h"

#include <fcntl.h>
#include <linux/uhid.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "firmware/hid_report.h"

namespace weft::sim {
namespace {

constexpr uint16_t kBusUsb = 0x03;  // BUS_USB: the real panel's bus, so hosts treat both alike

std::string errno_text(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

}  // namespace

UhidPanel UhidPanel::open(const std::string& uhid_path, const UhidIdentity& id) {
  const int fd = ::open(uhid_path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0)
    throw UhidError("cannot open " + uhid_path + ": " + std::strerror(errno) +
                    (errno == ENOENT ? " (is the uhid module loaded?)" : ""));
  return UhidPanel(fd, id);
}

UhidPanel::UhidPanel(int fd, const UhidIdentity& id) : fd_(fd) {
  uhid_event ev{};
  ev.type = UHID_CREATE2;
  auto& c = ev.u.create2;
  std::strncpy(reinterpret_cast<char*>(c.name), id.name.c_str(), sizeof c.name - 1);
  std::strncpy(reinterpret_cast<char*>(c.phys), "weft-panel-sim", sizeof c.phys - 1);
  static_assert(sizeof c.rd_data >= 64, "descriptor buffer");
  c.rd_size = static_cast<uint16_t>(firmware::kReportDescriptorSize);
  std::memcpy(c.rd_data, firmware::kReportDescriptor, firmware::kReportDescriptorSize);
  c.bus = kBusUsb;
  c.vendor = id.vendor_id;
  c.product = id.product_id;
  c.version = 0x0100;
  try {
    write_event(&ev, sizeof ev, "UHID_CREATE2");
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

UhidPanel::UhidPanel(UhidPanel&& o) noexcept : fd_(o.fd_), open_count_(o.open_count_), started_(o.started_) {
  o.fd_ = -1;
}

UhidPanel::~UhidPanel() {
  try {
    destroy();
  } catch (const UhidError&) {
    // Closing the descriptor below unplugs the device anyway.
  }
  if (fd_ >= 0) ::close(fd_);
}

void UhidPanel::destroy() {
  if (fd_ < 0) return;
  const int fd = fd_;
  uhid_event ev{};
  ev.type = UHID_DESTROY;
  fd_ = -1;  // whatever happens, this panel is gone
  open_count_ = 0;
  const ssize_t n = ::write(fd, &ev, sizeof ev.type);
  const int err = errno;
  ::close(fd);
  if (n != static_cast<ssize_t>(sizeof ev.type)) {
    errno = err;
    throw UhidError(errno_text("UHID_DESTROY"));
  }
}

void UhidPanel::write_event(const void* event, size_t size, const char* what) {
  if (fd_ < 0) throw UhidError(std::string(what) + ": the panel was destroyed");
  const ssize_t n = ::write(fd_, event, size);
  if (n < 0) throw UhidError(errno_text(what));
  if (static_cast<size_t>(n) != size) throw UhidError(std::string(what) + ": short write");
}

void UhidPanel::handle_events(int timeout_ms) {
  pollfd p{fd_, POLLIN, 0};
  int r = ::poll(&p, 1, timeout_ms);
  while (r > 0) {
    if (!(p.revents & POLLIN)) throw UhidError("uhid: the device file reported an error");
    uhid_event ev{};
    const ssize_t n = ::read(fd_, &ev, sizeof ev);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      throw UhidError(errno_text("reading uhid events"));
    }
    if (n < static_cast<ssize_t>(sizeof ev.type)) throw UhidError("uhid: the device file closed");
    switch (ev.type) {
      case UHID_START: started_ = true; break;
      case UHID_STOP: started_ = false; break;
      case UHID_OPEN: ++open_count_; break;
      case UHID_CLOSE: open_count_ = open_count_ > 0 ? open_count_ - 1 : 0; break;
      case UHID_GET_REPORT: {
        // The panel has no feature reports; answer at once so the host does not wait its 5 s.
        uhid_event reply{};
        reply.type = UHID_GET_REPORT_REPLY;
        reply.u.get_report_reply.id = ev.u.get_report.id;
        reply.u.get_report_reply.err = EIO;
        write_event(&reply, sizeof reply, "UHID_GET_REPORT_REPLY");
        break;
      }
      case UHID_SET_REPORT: {
        uhid_event reply{};
        reply.type = UHID_SET_REPORT_REPLY;
        reply.u.set_report_reply.id = ev.u.set_report.id;
        reply.u.set_report_reply.err = EIO;
        write_event(&reply, sizeof reply, "UHID_SET_REPORT_REPLY");
        break;
      }
      default: break;  // UHID_OUTPUT: the panel has no output reports
    }
    r = ::poll(&p, 1, 0);
  }
  if (r < 0 && errno != EINTR) throw UhidError(errno_text("poll on uhid"));
}

bool UhidPanel::wait_until_opened(int timeout_ms) {
  using Clock = std::chrono::steady_clock;
  const auto end = Clock::now() + std::chrono::milliseconds(timeout_ms);
  handle_events(0);  // a CLOSE may already be waiting
  while (!opened()) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(end - Clock::now()).count();
    if (left <= 0) return false;
    handle_events(static_cast<int>(left));
  }
  return true;
}

void UhidPanel::send_report(const uint8_t* bytes, size_t size) {
  if (fd_ < 0) throw UhidError("UHID_INPUT2: the panel was destroyed");
  handle_events(0);
  uhid_event ev{};
  ev.type = UHID_INPUT2;
  if (size > sizeof ev.u.input2.data) throw UhidError("UHID_INPUT2: report too long");
  ev.u.input2.size = static_cast<uint16_t>(size);
  std::memcpy(ev.u.input2.data, bytes, size);
  // Only the used part of the event goes to the kernel, as uhid allows.
  write_event(&ev, offsetof(uhid_event, u.input2.data) + size, "UHID_INPUT2");
}

}  // namespace weft::sim
