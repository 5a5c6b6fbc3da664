// The uhid panel's conversation with the kernel, checked on a socket pair standing in for
// /dev/uhid (message boundaries kept, like the character device): what it creates, when it
// considers itself opened, the input reports, the answers to requests, the unplug. The last test
// does the same against the real /dev/uhid and reads the report back through hidapi (hidraw);
// it runs where uhid is available (root, `modprobe uhid`: the kiosk VM test runs it in its guest).
#include <gtest/gtest.h>
#include <linux/uhid.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "firmware/hid_report.h"
#include "panel/hid_transport.h"
#include "sim/uhid_panel.h"

namespace {

using weft::sim::UhidError;
using weft::sim::UhidIdentity;
using weft::sim::UhidPanel;

struct Pair {
  int ours = -1, kernel = -1;  // `ours` goes to the panel, `kernel` plays the kernel's side
  Pair() {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, fds) == 0) {
      ours = fds[0];
      kernel = fds[1];
    }
  }
  ~Pair() {
    if (kernel >= 0) ::close(kernel);
  }
  // One event the panel wrote, and how many bytes it had.
  uhid_event receive(ssize_t* size = nullptr) {
    uhid_event ev{};
    const ssize_t n = ::recv(kernel, &ev, sizeof ev, MSG_DONTWAIT);
    if (size) *size = n;
    EXPECT_GE(n, static_cast<ssize_t>(sizeof ev.type)) << "no event from the panel";
    return ev;
  }
  void send(uint32_t type, uint32_t request_id = 0) {
    uhid_event ev{};
    ev.type = type;
    if (type == UHID_GET_REPORT) ev.u.get_report.id = request_id;
    if (type == UHID_SET_REPORT) ev.u.set_report.id = request_id;
    ASSERT_EQ(::send(kernel, &ev, sizeof ev, 0), static_cast<ssize_t>(sizeof ev));
  }
};

UhidIdentity ids(uint16_t vid, uint16_t pid) {
  UhidIdentity id;
  id.vendor_id = vid;
  id.product_id = pid;
  return id;
}

TEST(UhidPanel, CreatesTheDeviceWithThePanelsDescriptorAndIds) {
  Pair p;
  ASSERT_GE(p.ours, 0);
  UhidPanel panel(p.ours, ids(0x1234, 0xabcd));
  const uhid_event ev = p.receive();
  ASSERT_EQ(ev.type, UHID_CREATE2);
  const auto& c = ev.u.create2;
  EXPECT_EQ(c.bus, 0x03);  // BUS_USB, as the real panel
  EXPECT_EQ(c.vendor, 0x1234u);
  EXPECT_EQ(c.product, 0xabcdu);
  EXPECT_STREQ(reinterpret_cast<const char*>(c.name), "Weft knob panel (simulated)");
  ASSERT_EQ(c.rd_size, weft::firmware::kReportDescriptorSize);
  EXPECT_EQ(std::memcmp(c.rd_data, weft::firmware::kReportDescriptor, c.rd_size), 0);
}

TEST(UhidPanel, IsOpenedOnlyAfterTheKernelSaysSo) {
  Pair p;
  UhidPanel panel(p.ours, ids(1, 2));
  p.receive();
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_FALSE(panel.wait_until_opened(60));
  EXPECT_GE(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(60));
  p.send(UHID_START);  // bound to a driver, but no reader yet
  EXPECT_FALSE(panel.wait_until_opened(30));
  p.send(UHID_OPEN);
  EXPECT_TRUE(panel.wait_until_opened(1000));
  p.send(UHID_CLOSE);
  EXPECT_FALSE(panel.wait_until_opened(30));
}

TEST(UhidPanel, SendsInputReportsAsTheyAreOnTheWire) {
  Pair p;
  UhidPanel panel(p.ours, ids(1, 2));
  p.receive();
  weft::firmware::PanelReport r;
  r.sequence = 7;
  r.dial[2] = -3;
  r.buttons = 0x11;
  r.time_ms = 0x1234;
  uint8_t bytes[weft::firmware::kReportSize];
  ASSERT_EQ(weft::firmware::encode_report(r, bytes, sizeof bytes), sizeof bytes);
  panel.send_report(bytes, sizeof bytes);
  ssize_t n = 0;
  const uhid_event ev = p.receive(&n);
  ASSERT_EQ(ev.type, UHID_INPUT2);
  ASSERT_EQ(ev.u.input2.size, sizeof bytes);
  EXPECT_EQ(std::memcmp(ev.u.input2.data, bytes, sizeof bytes), 0);
  EXPECT_EQ(n, static_cast<ssize_t>(sizeof ev.type + 2 + sizeof bytes));  // only the used part
}

TEST(UhidPanel, AnswersReportRequestsAtOnceWithAnError) {
  Pair p;
  UhidPanel panel(p.ours, ids(1, 2));
  p.receive();
  p.send(UHID_GET_REPORT, 41);
  p.send(UHID_SET_REPORT, 42);
  p.send(UHID_OPEN);
  ASSERT_TRUE(panel.wait_until_opened(1000));
  const uhid_event get = p.receive();
  ASSERT_EQ(get.type, UHID_GET_REPORT_REPLY);
  EXPECT_EQ(get.u.get_report_reply.id, 41u);
  EXPECT_NE(get.u.get_report_reply.err, 0);
  const uhid_event set = p.receive();
  ASSERT_EQ(set.type, UHID_SET_REPORT_REPLY);
  EXPECT_EQ(set.u.set_report_reply.id, 42u);
  EXPECT_NE(set.u.set_report_reply.err, 0);
}

TEST(UhidPanel, DestroyUnplugsOnceAndLaterReportsFail) {
  Pair p;
  {
    UhidPanel panel(p.ours, ids(1, 2));
    p.receive();
    panel.destroy();
    EXPECT_EQ(p.receive().type, UHID_DESTROY);
    const uint8_t bytes[weft::firmware::kReportSize] = {1};
    EXPECT_THROW(panel.send_report(bytes, sizeof bytes), UhidError);
    EXPECT_NO_THROW(panel.destroy());
  }
  uhid_event ev{};
  EXPECT_EQ(::recv(p.kernel, &ev, sizeof ev, MSG_DONTWAIT), 0) << "a second destroy, or the fd left open";
}

TEST(UhidPanel, TheDestructorUnplugs) {
  Pair p;
  { UhidPanel panel(p.ours, ids(1, 2)); }
  EXPECT_EQ(p.receive().type, UHID_CREATE2);
  EXPECT_EQ(p.receive().type, UHID_DESTROY);
}

TEST(UhidPanel, AMissingDeviceFileIsAClearError) {
  try {
    UhidPanel::open("/nonexistent/uhid", ids(1, 2));
    FAIL() << "no error";
  } catch (const UhidError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/uhid"), std::string::npos) << e.what();
  }
}

// The real thing: the kernel creates a hidraw device that hidapi finds by VID/PID and reads.
TEST(UhidPanel, RealUhidDeviceIsReadThroughHidapi) {
  if (::access("/dev/uhid", R_OK | W_OK) != 0) GTEST_SKIP() << "no usable /dev/uhid here (root and `modprobe uhid`)";
  // An id pair of its own so a kiosk running beside the test does not grab this device.
  const UhidIdentity id = ids(weft::firmware::kPanelVendorId, 0x57f0);
  auto panel = UhidPanel::open("/dev/uhid", id);
  auto transport = weft::input::make_hidapi_transport();
  std::unique_ptr<weft::input::HidDevice> dev;
  std::string why;
  for (int i = 0; i < 100 && !dev; ++i) {  // the kernel binds hid-generic and adds hidraw shortly
    dev = transport->open(id.vendor_id, id.product_id, why);
    if (!dev) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(dev) << "hidapi never found the uhid panel: " << why;
  ASSERT_TRUE(panel.wait_until_opened(5000));
  weft::firmware::PanelReport r;
  r.sequence = 3;
  r.dial[0] = 5;
  uint8_t bytes[weft::firmware::kReportSize];
  weft::firmware::encode_report(r, bytes, sizeof bytes);
  panel.send_report(bytes, sizeof bytes);
  uint8_t got[64];
  const int n = dev->read(got, sizeof got, 5000);
  ASSERT_EQ(n, static_cast<int>(sizeof bytes)) << dev->last_error();
  EXPECT_EQ(std::memcmp(got, bytes, sizeof bytes), 0);
  panel.destroy();  // unplugged: the reader sees an error, as with a pulled USB cable
  EXPECT_LT(dev->read(got, sizeof got, 2000), 0);
}

}  // namespace
