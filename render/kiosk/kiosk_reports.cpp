// The kiosk's reports: the journal's stats lines with the frame profile, and the health status a
// fleet reads (kiosk/kiosk_status.h). Kiosk's own members, kept here so kiosk.cpp reads as its steps.
#include <cstdio>
#include <ctime>

#include <unistd.h>

#include "gpu/egl_context.h"
#include "kiosk/kiosk.h"
#include "kiosk/kiosk_light_probe.h"
#include "kiosk/kiosk_log.h"

namespace weft {

void Kiosk::start_profile() {
  if (config_.profile == "off" || profile_) return;
  const bool cpu = config_.profile == "cpu" || (config_.profile == "auto" && gpu::software_renderer());
  const gpu::TimerQueryFunctions timers = cpu ? gpu::TimerQueryFunctions{} : gpu::timer_query_functions();
  if (config_.profile == "gpu" && !timers.available())
    kiosk_log_warning("--profile gpu: the driver has no GPU timer queries (EXT_disjoint_timer_query); timing on the CPU");
  profile_ = std::make_unique<gpu::FrameProfile>(timers);
  kiosk_log_info(std::string("frame profile by ") + profile_->clock_name());
}

void Kiosk::log_stats(Clock::time_point now) {
  char line[256];
  std::snprintf(line, sizeof line,
                "stats: %ld ticks, %ld frames drawn, median %.2f ms/frame over the last %zu, RSS %ld KiB, "
                "%llu light-probe updates, lighting prepared off-thread %ld times (last %.0f ms)",
                ticks_, drawn_, since_stats_ms_.median(), since_stats_ms_.size(), resident_set_kib(),
                static_cast<unsigned long long>(probe_ ? probe_->updates() : 0), lighting_->prepared(),
                lighting_->last_ms());
  kiosk_log_info(line);
  if (profile_ && profile_->frames() > 0) {
    kiosk_log_info("frame profile: " + profile_->summary());
    profile_->reset();
  }
  last_stats_ = now;
  since_stats_ms_.clear();
}

KioskStatus Kiosk::status(const char* state) const {
  KioskStatus s;
  s.state = state;
  s.written = std::time(nullptr);
  s.uptime_s = std::chrono::duration<double>(Clock::now() - boot_).count();
  s.pid = long(getpid());
  s.bundle = shown_.file.empty() ? config_.bundle : shown_.file.string();  // before it is read: the one asked for
  s.last_good = shown_.is_last_good;
  if (scene_) s.scene = scene_->scene.name;
  if (method_) s.method = method_->name;
  s.display = display_ ? display_status() : "none";
  if (screen_off_) s.display += ", off by the schedule " + screen_schedule_.text();
  s.ticks = ticks_;
  s.drawn = drawn_;
  s.last_frame_ms = frame_ms_.last();
  s.probe = !probe_ ? "off" : probe_->updates() > 0 ? "fitted" : "waiting";
  s.probe_updates = probe_ ? probe_->updates() : 0;
  if (knobs_) s.panel = knobs_->sources();
  s.knob_changes = knob_changes_;
  if (swap_ && swap_->last_outcome().when != std::chrono::system_clock::time_point{}) {
    s.content_update_at = std::chrono::system_clock::to_time_t(swap_->last_outcome().when);
    s.content_update = swap_->last_outcome().result;
  }
  return s;
}

void Kiosk::write_status(const char* state) {
  if (status_) status_->write(status(state), Clock::now());
}

}  // namespace weft
