#pragma once
// The kiosk (`weft run`): one baked scene bundle shown fullscreen (DRM/KMS) or on a headless
// offscreen target, its look turned by the knob panel, its light by an optional camera probe.
//
//   Kiosk kiosk(config);
//   return kiosk.run(stop);   // stop: set by SIGTERM/SIGINT
//
// run() boots, then loops until `stop` is set or `frames` ticks have run:
//   check_config      flag values, the state directory
//   watch_bundle      inotify on the bundle's directory (content updates, kiosk/bundle_watcher.h)
//   load_bundle       the bundle, or the last good copy (bundle/bundle_fallback.h); the method
//   open_display      KMS (with or without a screen yet), else (display auto) headless (kiosk/kiosk_display.h)
//   start_knobs       knob controller (state restored from STATE_DIR/knobs.json), knob sources
//                     (kiosk/kiosk_knobs.h)
//   start_renderer    scene renderer (kiosk/kiosk_renderer.h), offscreen target
//   start_probe       the light probe, when asked for
//   show_first_frame  first frame, then READY=1 to systemd
//   knobs_->listen    the knob sources' threads start
//   tick …            follow the screen (plugged, unplugged: kiosk_screen.cpp), poll knobs, light and bundle, redraw if the view, knobs, light or scene
//                     changed (present again if only the label is fading: kiosk/kiosk_label.h),
//                     WATCHDOG=1, a stats line every stats_every seconds
//   shut_down         sources stopped, knob state saved, screenshot, the exit line, STOPPING=1
//
// The status file, when asked for (--status-file), is written after the first frame, every few
// seconds and on news from the loop, and at shutdown or when the kiosk cannot start.
//
// One tick per display refresh: vsync on KMS, a 60 Hz timer headless. Lighting changes after
// the first frame are prepared on a worker thread; the frame keeps its light until they are done.
//
// Content updates (kiosk/bundle_swap.h): when the bundle file is replaced, it is read, verified,
// built and lit beside the scene shown, then swapped in; a file refused leaves the scene shown.
// Knob positions carry over when the new bundle has the same fabric presets and its cloth wears
// the same one; otherwise they reset to its preset (logged). The exposure: kiosk/exposure_meter.h.
//
// Test-only fault injection: WEFT_FAULT_HANG_AFTER_TICKS=N makes the loop hang after N ticks (no
// frames, no watchdog pings), as a stuck driver would; the watchdog test uses it.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/shading_data.h"
#include "runtime/scene_bundle.h"
#include "core/fabric.h"
#include "gl/frame_profile.h"
#include "gpu/scene_renderer.h"
#include "kiosk/bundle_swap.h"
#include "kiosk/exposure_meter.h"
#include "kiosk/frame_stats.h"
#include "kiosk/kiosk_config.h"
#include "kiosk/kiosk_display.h"
#include "kiosk/kiosk_knobs.h"
#include "kiosk/kiosk_label.h"
#include "kiosk/kiosk_lighting.h"
#include "kiosk/kiosk_look_sink.h"
#include "kiosk/look_applier.h"
#include "kiosk/idle_return.h"
#include "kiosk/kiosk_status_file.h"
#include "kiosk/screen_schedule.h"
#include "kiosk/screen_wait.h"
#include "kiosk/service_notifier.h"
#include "kiosk/weave_terms_governor.h"

namespace weft {

namespace gpu {
class OffscreenTarget;
}  // namespace gpu
class KioskLightProbe;

class Kiosk {
public:
  explicit Kiosk(KioskConfig config);
  ~Kiosk();
  Kiosk(const Kiosk&) = delete;
  Kiosk& operator=(const Kiosk&) = delete;

  // Returns 0 after a clean stop, 1 when display kms finds no display, 3 when the display card
  // came or went (kiosk_display.h: the service starts the kiosk again on it). Throws KioskConfigError
  // for bad configuration (exit 2), bundle::BundleError when neither the bundle nor its last good
  // copy is usable.
  int run(const std::atomic<bool>& stop);

private:
  using Clock = std::chrono::steady_clock;

  void check_config();
  void watch_bundle();
  void load_bundle();
  bool open_display();  // false when display kms has none
  void start_knobs();
  void start_renderer();
  void start_probe();
  void show_first_frame();
  void arm_fault_injection();
  void tick();
  void shut_down();

  // What one tick's inputs changed (poll_inputs).
  struct TickNews {
    bool knobs = false;           // a new knob state was applied
    std::int64_t knob_report_ns = 0;  // when its panel report arrived (0: none timed)
    bool look_returning = false;  // the way home moved the look
    bool light = false;           // new lighting was uploaded
    bool scene = false;           // a new bundle was swapped in
    bool view = false;            // the turntable or the zoom moved
    bool woke = false;            // the screen schedule had the screen off until now
    bool asleep = false;          // the screen schedule has it off: nothing is drawn
    bool redraw() const { return !asleep && (knobs || look_returning || light || scene || view || woke); }
  };
  // Polls the kiosk's inputs once each, in this order: the screen (hotplug), the knobs, the way
  // home when idle, the light probe, the lighting worker, the bundle swap, the view, the screen
  // schedule. The order is part of the behaviour: a later input reads what an earlier one set this
  // tick (a bundle swapped in is lit with the light turn the knobs and the probe set).
  TickNews poll_inputs(Clock::time_point now, double turn_deg);

  // Parts of a tick.
  void hang_if_injected();
  bool poll_knobs();             // applies a new knob state; true when there was one
  void poll_light();             // the probe's newest fit, handed to the lighting worker
  bool take_prepared_lighting(); // true when the worker's lighting was uploaded
  bool poll_bundle();            // true when a new bundle was swapped in this tick
  bool move_view(Clock::time_point now, double turn_deg);  // true when the view drawn is out of date
  void wait_for_next_tick(Clock::time_point tick_start, bool drew);
  void relight(const SgLighting& sgs);
  void draw_frame(double turn_deg);
  // The frame drawn last to the screen, with the label (if any) at its opacity now: after each
  // draw, and again alone while the label fades.
  void present(Clock::time_point now);
  KioskDisplay::Overlay label_overlay() const;  // empty without a label
  // The bundle as baked (its fabrics, the light set) on a quarter-size frame, shown at once.
  void meter_as_baked();
  void show_swapped(BundleSwap::Ready ready);  // a new bundle in place of the one shown
  void start_profile();  // --profile: the frame profile (kiosk_reports.cpp, with the two below)
  void log_stats(Clock::time_point now);
  // The status file (kiosk/kiosk_status_file.h): `state` now, or (update) when due or news.
  KioskStatus status(const char* state) const;
  void write_status(const char* state);
  // Nobody at the kiosk (kiosk_idle.cpp): the knobs eased home after --idle-return; the screen
  // powered down during --screen-off.
  bool return_when_idle(Clock::time_point now);  // true when the look shown changed
  bool screen_asleep(Clock::time_point now);      // true while the schedule has the screen off

  // The screen coming and going (kiosk_screen.cpp): hotplug followed each tick, the frame made
  // again at a new screen's size, the report when there has been none for --display-wait seconds.
  DisplaySettings display_settings() const;
  void follow_display(Clock::time_point now);
  void resize_frame();
  void report_screen(Clock::time_point now);
  std::string display_status() const;  // the status file's "display": drm:NAME, none since TIME, headless

  KioskConfig config_;
  ServiceNotifier notifier_;
  Clock::time_point boot_;
  std::string boot_stages_;  // "bundle 120, display 30, ..." ms: where the first frame's wait went
  void boot_stage(const char* name, Clock::time_point& since);
  bool state_dir_ok_ = true;

  // The bundle shown.
  struct Shown {
    std::filesystem::path file;  // the file it came from
    bool is_last_good = false;   // the last good copy, because the primary was unusable
    std::string primary_error;
  } shown_;
  std::optional<SceneBundle> scene_;
  std::shared_ptr<const ShadingData> shading_;
  const methods::RuntimeMethod* method_ = nullptr;  // from the registry: --method, or the bundle's best

  // The display (and the GL context everything below draws with).
  std::unique_ptr<KioskDisplay> display_;
  int width_ = 0, height_ = 0;  // the display's

  // The knobs: the bundle's fabric presets (kiosk/knob_presets.h), turned by the panel; their
  // looks (and the way home's) reach the renderer through look_applier_ (kiosk/look_applier.h).
  std::unique_ptr<KioskKnobs> knobs_;
  KioskLookSink look_sink_;
  LookApplier look_applier_;

  // The renderer and what it draws into.
  std::vector<Fabric> cloth_fabrics_;  // the base fabric of each cloth object, in the colourway worn
  std::unique_ptr<gpu::SceneRenderer> renderer_;
  std::unique_ptr<gpu::OffscreenTarget> target_;
  std::unique_ptr<gpu::FrameProfile> profile_;  // --profile: null when off
  std::unique_ptr<KioskLabel> label_;           // --label on with a usable font; else null

  // The light: the bundle's SGs or the probe's latest fit, turned by the environment knob.
  SgLighting room_light_;
  std::unique_ptr<KioskLightProbe> probe_;
  std::unique_ptr<KioskLighting> lighting_;  // prepares lighting changes off this thread
  std::uint64_t light_version_ = 0;  // counts relight() calls
  bool first_frame_shown_ = false;

  // Exposure: metered at boot and after each lighting change (never on a knob edit).
  ExposureMeter exposure_;
  bool non_finite_logged_ = false;  // this scene's cloth was metered with NaN pixels and the journal told
  void meter_frame(int width, int height);  // the exposure from the bound frame; NaN cloth logged once
  // Content updates; null when the bundle's directory cannot be watched.
  std::unique_ptr<BundleSwap> swap_;
  std::unique_ptr<StatusFile> status_;  // null: none asked for

  // The loop.
  long hang_after_ = -1;
  Clock::time_point loop_start_, last_stats_;
  double shown_turn_ = 0;
  double turn_per_frame_ = 0;  // degrees, smoothed over the frames drawn (the reuse shares follow it)
  // The zoom knob: the close-up of the scene shown, the zoom shown (eased to look_sink_'s target).
  Camera closeup_;
  glm::dvec3 pivot_{0.0};  // the turntable's (turntable.h)
  double zoom_shown_ = 0, zoom_drawn_ = 0;
  Clock::time_point zoom_step_;
  long ticks_ = 0, drawn_ = 0, knob_changes_ = 0;
  long rss_start_kib_ = 0;
  // Nobody there.
  IdleReturn idle_;
  ScreenSchedule screen_schedule_;
  bool screen_off_ = false, screen_checked_ = false;
  Clock::time_point screen_checked_at_;
  RecentSamples frame_ms_, since_stats_ms_, latency_ms_;
  WeaveTermsGovernor weave_terms_;  // the weave layer's terms up close, by what the GPU affords

  // The screen: how long it has been missing; set when the display card came or went.
  std::optional<ScreenWait> screen_wait_;
  bool restart_ = false;
};

}  // namespace weft
