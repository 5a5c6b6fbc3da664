#pragma once
// Where knob events meet the picture: applies events from any number of sources to one
// KnobMapper (serialised by a mutex that only input threads take), publishes each change to the
// AppearanceChannel the renderer reads without blocking, and saves the positions once the knobs
// have been still for `save_delay` (flash wears; a shopper turns a knob in bursts).
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <thread>

#include "panel/appearance_channel.h"
#include "panel/knob_mapping.h"
#include "panel/knob_source.h"

namespace weft::input {

struct KnobControllerOptions {
  std::filesystem::path state_file;   // empty: no persistence
  uint32_t default_preset = 0;
  std::chrono::milliseconds save_delay{1000};
};

class KnobController {
public:
  KnobController(KnobMapper mapper, KnobControllerOptions options, LogSink log);
  ~KnobController();  // saves pending changes

  // Restores the saved positions (or falls back to the preset, logging why) and publishes them.
  void restore();
  // The sink to give to sources; safe to call from several source threads.
  KnobSink sink();
  void on_event(const KnobEvent& event);
  // Writes the state now if it changed since the last save.
  void flush();

  const AppearanceChannel& channel() const { return channel_; }
  KnobPositions positions() const;
  uint64_t saves() const;

private:
  void saver_loop();
  void save_locked(std::unique_lock<std::mutex>& lock);

  KnobMapper mapper_;
  KnobControllerOptions options_;
  LogSink log_;
  AppearanceChannel channel_;
  mutable std::mutex m_;
  std::mutex write_m_;  // taken without m_ held
  std::condition_variable cv_;
  bool dirty_ = false;
  bool stopping_ = false;
  uint64_t saves_ = 0;
  std::chrono::steady_clock::time_point last_change_{};
  std::thread saver_;
};

}  // namespace weft::input
