#include "panel/keyboard_knob_source.h"

#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstring>

namespace weft::input {

std::vector<KnobEvent> keyboard_events(char key, uint32_t time_ms) {
  static constexpr char kUp[] = "qwer", kDown[] = "asdf";
  const int detents = std::isupper(static_cast<unsigned char>(key)) ? 5 : 1;
  const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(key)));
  for (int d = 0; d < kDialCount; ++d) {
    if (lower == kUp[d] || lower == kDown[d]) {
      KnobEvent e;
      e.dial[d] = lower == kUp[d] ? detents : -detents;
      e.time_ms = time_ms;
      return {e};
    }
  }
  if (lower == 't' || lower == 'g') {  // zoom: closer / back
    KnobEvent e;
    e.zoom = lower == 't' ? detents : -detents;
    e.time_ms = time_ms;
    return {e};
  }
  if (lower == 'c') {  // the next colourway
    KnobEvent e;
    e.colourway = 1;
    e.time_ms = time_ms;
    return {e};
  }
  int button = -1;
  if (key >= '1' && key <= '4') button = key - '1';
  if (key == '0' || key == ' ') button = 4;
  if (button < 0) return {};
  KnobEvent press, release;
  press.buttons = static_cast<uint8_t>(1u << button);
  press.time_ms = release.time_ms = time_ms;
  return {press, release};
}

KeyboardKnobSource::KeyboardKnobSource(int fd, LogSink log) : fd_(fd), log_(log ? std::move(log) : stderr_log()) {}

KeyboardKnobSource::~KeyboardKnobSource() { stop(); }

void KeyboardKnobSource::start(KnobSink sink) {
  stop();
  stop_.clear();
  thread_ = std::thread([this, sink = std::move(sink)] { run(sink); });
}

void KeyboardKnobSource::stop() {
  stop_.request();
  if (thread_.joinable()) thread_.join();
}

void KeyboardKnobSource::run(KnobSink sink) {
  termios saved{};
  const bool tty = isatty(fd_) && tcgetattr(fd_, &saved) == 0;
  if (tty) {
    termios raw = saved;
    raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);
    tcsetattr(fd_, TCSANOW, &raw);
  }
  const auto t0 = std::chrono::steady_clock::now();
  while (!stop_.requested()) {
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, 100);
    if (r < 0) {
      log_(LogPriority::warning, std::string("keyboard knobs: cannot read input: ") + std::strerror(errno));
      break;
    }
    if (r == 0) continue;
    char buf[64];
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n <= 0) {
      log_(LogPriority::info, "keyboard knobs: input closed; keyboard control off");
      break;
    }
    const auto ms = static_cast<uint32_t>(
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0).count());
    for (ssize_t i = 0; i < n; ++i)
      for (const KnobEvent& e : keyboard_events(buf[i], ms)) sink(e);
  }
  if (tty) tcsetattr(fd_, TCSANOW, &saved);
}

}  // namespace weft::input
