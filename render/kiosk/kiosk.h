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
//   open_display      KMS, else (display auto) headless
//   start_knobs       knob controller (state restored from STATE_DIR/knobs.json), knob sources
//   start_renderer    scene renderer, offscreen target, tone mapper (KMS)
//   start_probe       the light probe, when asked for
//   show_first_frame  first frame, then READY=1 to systemd
//   listen_to_knobs   the knob sources' threads start
//   tick …            poll knobs, light and bundle, redraw if the view, knobs, light or scene
//                     changed, WATCHDOG=1, a stats line every stats_every seconds
//   shut_down         sources stopped, knob state saved, screenshot, the exit line, STOPPING=1
//
// One tick per display refresh: vsync on KMS, a 60 Hz timer headless. Lighting changes after
// the first frame are prepared on a worker thread; the frame keeps its light until they are done.
//
// Content updates: when the bundle file is replaced (atomically, or written in place and closed),
// a worker thread reads and verifies it; the loop builds its GPU resources, a worker prepares its
// lighting, and the loop swaps it in (then a worker saves it as the last good copy). Until then, and
// for good when the new file is refused (corrupt, truncated, unusable: a journal error naming the
// file and why), the scene shown stays. Knob positions carry over when the new bundle has the same
// fabric presets and its cloth wears the same one; otherwise they reset to its preset (logged).
//
// Test-only fault injection: WEFT_FAULT_HANG_AFTER_TICKS=N makes the loop hang after N ticks (no
// frames, no watchdog pings), as a stuck driver would; the watchdog test uses it.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "runtime/iwasaki_bundle.h"
#include "runtime/scene_bundle.h"
#include "bundle/bundle_fallback.h"
#include "core/fabric.h"
#include "gpu/scene_renderer.h"
#include "kiosk/bundle_watcher.h"
#include "kiosk/frame_stats.h"
#include "kiosk/kiosk_bundle.h"
#include "kiosk/latest_request_worker.h"
#include "kiosk/service_notifier.h"
#include "panel/appearance_state.h"
#include "panel/knob_controller.h"
#include "panel/knob_source.h"

namespace weft {

namespace gpu {
class EglContext;
class KmsDisplay;
class OffscreenTarget;
}  // namespace gpu
class KioskLightProbe;

struct KioskConfig {
  std::string bundle;                     // scene bundle (weft bake)
  std::string state_dir = "/var/lib/weft";  // knob state and the last good bundle
  std::string display = "auto";           // auto (KMS, else headless), kms or headless
  long frames = 0;                        // ticks to run; 0 = until stop
  double turntable = 6.0;                 // camera turn, degrees per second about the target's +Z
  double zoom = 0.0;                      // the camera's way to the scene's close-up, 0 … 1, before the zoom knob's
  // Knob source: hid, gpio, keyboard, sim:SCRIPT or none (kiosk/knob_sources.h); empty: the
  // panel config's "sources" (default hid).
  std::string panel = "hid";
  std::string panel_config;               // JSON: hid ids, gpio lines, sources
  double sim_speed = 1.0;                 // sim: scripts play this many times faster
  std::string screenshot;                 // PNG of the last frame, tone-mapped; empty: none
  std::vector<int> size{640, 480};        // headless frame size
  // auto: the registry's kiosk rung whose traits fit the bundle (kiosk/kiosk_bundle.h, kiosk_method):
  // per vertex with the weighting tables (the same accuracy as per pixel on the showroom meshes at a
  // tenth to a twentieth of the cost; docs/research/iwasaki.md), see-through for a sheer.
  std::string method = "auto";
  // Tone mapping (image/tone_map.h): exposure metered on the cloth whenever the lighting changes
  // (not on knob edits: a darker fabric shows darker), eased in over kExposureAdaptSeconds, plus
  // this bias in EV. `exposure` multiplies on top: the same as a bias of log2(exposure) EV.
  double exposure_bias = 0.0;
  double exposure = 1.0;
  double stats_every = 300;               // seconds between stats lines; 0: none
  std::string probe = "none";             // none, camera[:ID] or mock:MAP.exr[,MAP.exr...]
  double probe_switch_s = 0;              // mock probe with several maps: seconds between switches
};

class Kiosk {
public:
  explicit Kiosk(KioskConfig config);
  ~Kiosk();
  Kiosk(const Kiosk&) = delete;
  Kiosk& operator=(const Kiosk&) = delete;

  // Returns 0 after a clean stop, 1 when display kms finds no display. Throws KioskConfigError
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
  void listen_to_knobs();
  void arm_fault_injection();
  void tick();
  void shut_down();

  // Parts of a tick.
  bool poll_knobs();             // applies a new knob state; true when there was one
  void poll_light();             // the probe's newest fit, handed to the lighting worker
  bool take_prepared_lighting(); // true when the worker's lighting was uploaded
  bool poll_bundle();            // true when a new bundle was swapped in this tick
  void apply_knob_state(const input::AppearanceState& state);
  void relight(const SgLighting& sgs);
  void draw_frame(double turn_deg);
  // The cloth of the frame just drawn into target_ (its lower-left width × height) →
  // exposure_target_ (and exposure_ when none is shown yet).
  void meter_exposure(int width, int height);
  // The bundle as baked (its fabrics, the light set) on a quarter-size frame → exposure_ at once.
  void meter_as_baked();
  double exposure_bias_ev() const;
  // Content updates: a verified bundle's renderer is built, its lighting prepared, then swapped in.
  struct LoadedBundle;
  struct PendingSwap;
  void start_swap(LoadedBundle loaded);
  bool finish_swap();  // true once the pending bundle is the one shown
  void log_swap_shown();
  void make_knob_controller(const SceneBundle& sb);
  input::MappingConfig mapping_;  // the panel config's choices (a dial given to the zoom)
  void reset_knobs(const SceneBundle& sb, const std::string& why);
  void log_stats(Clock::time_point now);

  KioskConfig config_;
  ServiceNotifier notifier_;
  Clock::time_point boot_;
  bool state_dir_ok_ = true;

  // The bundle shown.
  struct Shown {
    std::filesystem::path file;  // the file it came from
    bool is_last_good = false;   // the last good copy, because the primary was unusable
    std::string primary_error;
  } shown_;
  std::atomic<std::uint64_t> shown_fingerprint_{0};
  std::optional<SceneBundle> scene_;
  std::shared_ptr<const IwasakiBundleData> iwasaki_;
  const methods::RuntimeMethod* method_ = nullptr;  // from the registry: --method, or the bundle's best

  // The display.
  std::unique_ptr<gpu::KmsDisplay> kms_;
  std::unique_ptr<gpu::EglContext> headless_;
  int width_ = 0, height_ = 0;

  // The knobs: every fabric in the bundle is a preset the fabric knob selects. They dress the
  // cloth objects baked in the last cloth object's fabric (a chair's cushions); other cloth
  // objects keep their own (its body).
  std::vector<Fabric> presets_;
  std::unique_ptr<input::KnobController> controller_;  // replaced (render thread) when a new bundle's presets differ
  std::mutex controller_m_;                             // the sources' events vs that replacement
  std::atomic<int64_t> last_report_ns_{0};  // the newest HID report's arrival (steady_clock ns)
  std::vector<std::unique_ptr<input::KnobSource>> sources_;
  input::AppearanceState knobs_;
  uint64_t knob_version_ = ~0ull;

  // The renderer and what it draws into.
  std::vector<Fabric> cloth_fabrics_;  // the fabric of each cloth object
  std::unique_ptr<gpu::SceneRenderer> renderer_;
  // Renderers of bundles swapped out, kept until no lighting request made for them is running.
  std::vector<std::unique_ptr<gpu::SceneRenderer>> retired_;
  std::unique_ptr<gpu::OffscreenTarget> target_;
  std::unique_ptr<gpu::ToneMapper> tonemap_;  // KMS only

  // The light: the bundle's SGs or the probe's latest fit, turned by the environment knob.
  SgLighting room_light_;
  std::unique_ptr<KioskLightProbe> probe_;
  float light_rotation_ = -1;  // degrees; < 0 until the knobs first set it
  std::atomic<long> lighting_prepared_{0};
  std::atomic<double> last_prepare_ms_{0};
  // Requests name the renderer they are for: one that comes back for a renderer swapped out is dropped.
  struct LightingRequest {
    const gpu::SceneRenderer* renderer;
    SgLighting sgs;
  };
  struct LightingResult {
    const gpu::SceneRenderer* renderer;
    gpu::SceneRenderer::PreparedLighting lighting;
  };
  std::unique_ptr<LatestRequestWorker<LightingRequest, LightingResult>> lighting_;
  std::uint64_t light_version_ = 0;  // counts relight() calls
  bool first_frame_shown_ = false;

  // Exposure: metered at boot and after each lighting change, shown exposure_ easing towards
  // the target.
  bool meter_next_ = false;
  double exposure_ = 0.0, exposure_target_ = 0.0;  // 0 until the first metering
  Clock::time_point exposure_step_;
  // Content updates.
  std::unique_ptr<BundleWatcher> watcher_;
  std::unique_ptr<LatestRequestWorker<BundleWatcher::Change, LoadedBundle>> loader_;
  std::unique_ptr<PendingSwap> pending_;
  std::optional<BundleWatcher::Change> swapped_;  // the change just swapped in, until its frame is drawn
  std::future<void> saving_;  // the last good copy of the bundle swapped in
  double swap_read_ms_ = 0, swap_gpu_ms_ = 0, swap_light_ms_ = 0;
  long bundles_swapped_ = 0;

  // The loop.
  long hang_after_ = -1;
  Clock::time_point loop_start_, last_stats_;
  double shown_turn_ = 0;
  // The zoom knob: the close-up of the scene shown, the knobs' zoom, the zoom shown (eased).
  Camera closeup_;
  double zoom_target_ = 0, zoom_shown_ = 0, zoom_drawn_ = 0;
  Clock::time_point zoom_step_;
  long ticks_ = 0, drawn_ = 0;
  long rss_start_kib_ = 0;
  RecentSamples frame_ms_, since_stats_ms_, latency_ms_;
};

}  // namespace weft
