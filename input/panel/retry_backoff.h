#pragma once
// Exponential back-off between attempts to find a device (hidapi 0.13 has no hotplug, so an
// unplugged panel is found again by re-enumerating). Also the interruptible wait the device
// threads sleep in, so stop() is prompt.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>

namespace weft::input {

struct Backoff {
  std::chrono::milliseconds first{250};
  std::chrono::milliseconds longest{5000};
  std::chrono::milliseconds current = first;

  std::chrono::milliseconds next() {
    const auto d = current;
    current = std::min(current * 2, longest);
    return d;
  }
  void succeeded() { current = first; }
};

// A stop flag that sleeping threads wake up for.
class StopSignal {
public:
  void request() {
    std::lock_guard lock(m_);
    stop_ = true;
    cv_.notify_all();
  }
  void clear() {
    std::lock_guard lock(m_);
    stop_ = false;
  }
  bool requested() const {
    std::lock_guard lock(m_);
    return stop_;
  }
  // Sleeps up to `d`; returns true if stop was requested.
  bool wait_for(std::chrono::milliseconds d) {
    std::unique_lock lock(m_);
    return cv_.wait_for(lock, d, [&] { return stop_; });
  }

private:
  mutable std::mutex m_;
  std::condition_variable cv_;
  bool stop_ = false;
};

}  // namespace weft::input
