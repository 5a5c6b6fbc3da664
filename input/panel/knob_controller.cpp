#include "panel/knob_controller.h"

#include "panel/knob_state_file.h"

namespace weft::input {

KnobController::KnobController(KnobMapper mapper, KnobControllerOptions options, LogSink log)
    : mapper_(std::move(mapper)), options_(std::move(options)), log_(log ? std::move(log) : stderr_log()) {
  channel_.publish(mapper_.appearance());
  if (!options_.state_file.empty()) saver_ = std::thread([this] { saver_loop(); });
}

KnobController::~KnobController() {
  {
    std::lock_guard lock(m_);
    stopping_ = true;
  }
  cv_.notify_all();
  if (saver_.joinable()) saver_.join();
  flush();
}

void KnobController::restore() {
  std::lock_guard lock(m_);
  if (options_.state_file.empty()) {
    KnobPositions p;
    p.preset = options_.default_preset;
    mapper_.set_positions(p);
  } else {
    const auto r = restore_knob_state(options_.state_file, mapper_.presets(), options_.default_preset, mapper_.colourway_names());
    log_(r.unusable ? LogPriority::warning : LogPriority::info, r.message);
    mapper_.set_positions(r.positions);
  }
  dirty_ = false;
  channel_.publish(mapper_.appearance());
}

KnobSink KnobController::sink() {
  return [this](const KnobEvent& e) { on_event(e); };
}

void KnobController::on_event(const KnobEvent& event) {
  std::lock_guard lock(m_);
  if (!mapper_.apply(event)) return;
  channel_.publish(mapper_.appearance());
  dirty_ = true;
  last_change_ = std::chrono::steady_clock::now();
  cv_.notify_all();
}

KnobPositions KnobController::positions() const {
  std::lock_guard lock(m_);
  return mapper_.positions();
}

uint64_t KnobController::saves() const {
  std::lock_guard lock(m_);
  return saves_;
}

void KnobController::flush() {
  std::unique_lock lock(m_);
  save_locked(lock);
}

void KnobController::save_locked(std::unique_lock<std::mutex>& lock) {
  if (!dirty_ || options_.state_file.empty()) return;
  const std::string text = knob_state_text(mapper_.positions(), mapper_.presets(), mapper_.colourway_names());
  dirty_ = false;
  // Disk I/O outside the lock: a slow SD card must not hold up knob events.
  lock.unlock();
  std::string why;
  bool ok;
  {
    std::lock_guard writing(write_m_);  // one writer of the temp file at a time
    ok = write_file_atomically(options_.state_file, text, why);
  }
  lock.lock();
  if (ok) {
    ++saves_;
  } else {
    dirty_ = true;  // try again later
    log_(LogPriority::warning, "could not save knob state (" + why + "); will retry");
  }
}

void KnobController::saver_loop() {
  std::unique_lock lock(m_);
  while (!stopping_) {
    if (!dirty_) {
      cv_.wait(lock, [&] { return stopping_ || dirty_; });
      continue;
    }
    const auto due = last_change_ + options_.save_delay;
    if (std::chrono::steady_clock::now() < due) {
      cv_.wait_until(lock, due);
      continue;
    }
    save_locked(lock);
    if (dirty_) cv_.wait_for(lock, options_.save_delay);  // failed: back off
  }
}

}  // namespace weft::input
