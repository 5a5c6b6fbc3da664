#include "kiosk/kiosk.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "gpu/egl_context.h"
#include "gpu/kms_display.h"
#include "gl/offscreen_target.h"
#include "image/image.h"
#include "image/tone_map.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_light_probe.h"
#include "kiosk/knob_appearance.h"
#include "kiosk/knob_sources.h"
#include "kiosk/camera_zoom.h"
#include "kiosk/turntable.h"
#include "scene/weave_scale.h"
#include "journal/journal_log.h"
#include "methods/registry.h"
#include "panel/knob_state_file.h"
#include "panel/panel_config.h"

namespace weft {
namespace {

// Every line goes to stderr, which systemd sends to the journal (with its priority).
void log_info(const std::string& s) { log_line("weft run", LogPriority::info, s); }
void log_warning(const std::string& s) { log_line("weft run", LogPriority::warning, s); }
void log_error(const std::string& s) { log_line("weft run", LogPriority::error, s); }

// The resolved weave for close-ups; a renderer that cannot draw it (a see-through method draws
// none; a cloth mesh without UVs) shows the fabric level, as at a distance.
void show_weave(gpu::SceneRenderer& r, const Scene& scene) {
  try {
    r.set_weave(true);
  } catch (const std::exception& e) {
    log_warning("scene '" + scene.name + "': no close-up weave (" + e.what() + "); the fabric level is shown up close");
  }
}

// The scene's close-up for the zoom knob (its closeup_camera, or one where a repeat spans 24 pixels).
Camera closeup_of(const Scene& scene, const std::vector<Fabric>& cloth, int height) {
  std::map<std::string, Fabric> fabrics;
  size_t c = 0;
  for (const auto& o : scene.objects)
    if (o.is_cloth() && c < cloth.size()) fabrics.emplace(o.fabric, cloth[c++]);
  return closeup_camera(scene, fabrics, height);
}

constexpr auto kTickPeriod = std::chrono::microseconds(16667);
// Time constant of the exposure easing in after a lighting change (a probe update, the
// environment knob): quick enough to follow the room, slow enough not to flicker.
constexpr double kExposureAdaptSeconds = 0.7;

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// The preset the bundle's (last) cloth object wears: where the fabric knob starts.
// The fabric the knobs dress: the last cloth object's (a chair's cushions); cloth in other
// fabrics keeps its own.
std::string knob_fabric(const SceneBundle& sb) {
  std::string fabric;
  for (const auto& o : sb.scene.cloth_objects()) fabric = o.fabric;
  return fabric;
}

// The preset the knobs start from: the one they dress.
uint32_t default_preset(const SceneBundle& sb) {
  const auto at = sb.fabrics.find(knob_fabric(sb));
  return at != sb.fabrics.end() ? uint32_t(std::distance(sb.fabrics.begin(), at)) : 0;
}

std::vector<Fabric> preset_list(const SceneBundle& sb) {
  std::vector<Fabric> presets;
  for (const auto& [name, f] : sb.fabrics) presets.push_back(f);
  return presets;
}

std::vector<Fabric> cloth_fabrics(const SceneBundle& sb) {
  std::vector<Fabric> fabrics;
  for (const auto& o : sb.scene.cloth_objects()) fabrics.push_back(sb.fabrics.at(o.fabric));
  return fabrics;
}

// The knobs' view of two preset lists agrees: same names, same colours, same order.
bool same_knob_presets(const std::vector<input::PresetLook>& a, const std::vector<input::PresetLook>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || a[i].albedo != b[i].albedo) return false;
  return true;
}

std::string preset_names(const std::vector<input::PresetLook>& looks) {
  std::string s;
  for (const auto& l : looks) s += (s.empty() ? "" : ", ") + l.name;
  return s;
}

}  // namespace

// A bundle read and verified off the render thread, waiting for its GPU resources.
struct Kiosk::LoadedBundle {
  BundleWatcher::Change change;
  bool unchanged = false;  // the same content as the bundle shown
  std::optional<bundle::BundleReader> reader;  // its bytes, saved as the last good copy once shown
  std::optional<KioskBundle> bundle;
  const methods::RuntimeMethod* method = nullptr;
  double read_ms = 0;
};

// Its renderer, built on the render thread, while a worker prepares its lighting.
struct Kiosk::PendingSwap {
  BundleWatcher::Change change;
  std::optional<bundle::BundleReader> reader;
  KioskBundle bundle;
  const methods::RuntimeMethod* method = nullptr;
  std::vector<Fabric> cloth_fabrics;
  SgLighting room_light;
  std::uint64_t light_version = 0;  // light_version_ when its lighting was asked for
  std::unique_ptr<gpu::SceneRenderer> renderer;
  std::future<gpu::SceneRenderer::PreparedLighting> lighting;  // after renderer: destroyed (waited for) first
  Clock::time_point lighting_start;
};

Kiosk::Kiosk(KioskConfig config) : config_(std::move(config)) {}

Kiosk::~Kiosk() = default;

int Kiosk::run(const std::atomic<bool>& stop) {
  boot_ = Clock::now();
  check_config();
  watch_bundle();
  load_bundle();
  if (!open_display()) return 1;
  start_knobs();
  start_renderer();
  start_probe();
  show_first_frame();
  listen_to_knobs();
  arm_fault_injection();
  loop_start_ = last_stats_ = Clock::now();
  rss_start_kib_ = resident_set_kib();
  while (!stop && (config_.frames <= 0 || ticks_ < config_.frames)) tick();
  shut_down();
  return 0;  // KmsDisplay's destructor puts the previous CRTC back
}

void Kiosk::check_config() {
  const KioskConfig& c = config_;
  if (c.display != "auto" && c.display != "kms" && c.display != "headless")
    throw KioskConfigError("--display: expected auto, kms or headless, got '" + c.display + "'");
  if (c.size.size() != 2 || c.size[0] < 8 || c.size[1] < 8 || c.size[0] > 8192 || c.size[1] > 8192)
    throw KioskConfigError("--size: expected WIDTH HEIGHT in [8, 8192]");
  if (!std::isfinite(c.exposure_bias) || std::abs(c.exposure_bias) > 20)
    throw KioskConfigError("--exposure-bias: EV in [-20, 20]");
  if (!(c.exposure > 0.0) || !std::isfinite(c.exposure))
    throw KioskConfigError("--exposure: a multiplier > 0 on the metered exposure (1: none; --exposure-bias takes EV)");
  if (!std::isfinite(c.turntable) || std::abs(c.turntable) > 360)
    throw KioskConfigError("--turntable: degrees per second in [-360, 360]");
  if (!(c.zoom >= 0.0 && c.zoom <= 1.0)) throw KioskConfigError("--zoom: the way to the close-up, in [0, 1]");
  if (c.method != "auto") try {
      methods::method(c.method);
    } catch (const std::invalid_argument& e) {
      throw KioskConfigError(std::string("--method: ") + e.what() + " or auto");
    }
  std::error_code ec;
  std::filesystem::create_directories(c.state_dir, ec);
  state_dir_ok_ = !ec;
  if (ec)
    log_warning("cannot create state directory " + c.state_dir + ": " + ec.message() + " (no last-good copy, no knob state)");
}

// Watched before it is read: a replacement made while the kiosk boots is seen (and read once
// the loop runs, unless it is the content already shown).
void Kiosk::watch_bundle() {
  try {
    watcher_ = std::make_unique<BundleWatcher>(config_.bundle);
    log_info("watching " + watcher_->directory().string() + " for a new " + watcher_->bundle().filename().string() +
             " (content updates without a restart)");
  } catch (const std::exception& e) {
    log_warning(std::string("content updates are not watched (") + e.what() + "); a new bundle needs a restart");
    return;
  }
  loader_ = std::make_unique<LatestRequestWorker<BundleWatcher::Change, LoadedBundle>>([this](const BundleWatcher::Change& c) {
    const auto t0 = Clock::now();
    LoadedBundle out;
    out.change = c;
    const bundle::BundleReader reader = bundle::BundleReader::read(config_.bundle);
    if (bundle_fingerprint(reader) == shown_fingerprint_.load()) {
      out.unchanged = true;
      return out;
    }
    KioskBundle b = read_kiosk_bundle(reader, config_.method);
    out.method = &kiosk_method(config_.method, b, config_.bundle);
    out.reader = reader;
    out.bundle = std::move(b);
    out.read_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    return out;
  });
}

void Kiosk::load_bundle() {
  notifier_.status("loading bundle " + config_.bundle);
  bundle::FallbackOptions fo;
  // The weighting tables are read in the accept step too: a bundle whose tables do not read (a
  // section missing, a shape that does not match the mesh) falls back like a corrupt one.
  std::optional<KioskBundle> read;
  fo.accept = [&](const bundle::BundleReader& r) { read = read_kiosk_bundle(r, config_.method); };
  fo.log = stderr_sink("weft run");
  fo.read_into_memory = true;  // the file may be rewritten in place while the kiosk runs
  std::optional<bundle::OpenedBundle> opened;
  try {
    opened.emplace(bundle::open_bundle_with_fallback(config_.bundle, config_.state_dir, fo));
  } catch (const bundle::BundleError& e) {
    log_error(std::string("no usable bundle: ") + e.what());
    notifier_.status("no usable bundle (see journal)");
    throw;
  }
  if (!read) read = read_kiosk_bundle(opened->bundle, config_.method);
  shown_ = {opened->file, opened->is_last_good, opened->primary_error};
  // A last good copy shown does not count as the primary's content: the primary, once fixed, is.
  shown_fingerprint_ = opened->is_last_good ? 0 : read->fingerprint;
  method_ = &kiosk_method(config_.method, *read, opened->file);
  scene_ = std::move(read->scene);
  iwasaki_ = read->iwasaki;
  (shown_.is_last_good ? log_warning : log_info)("bundle " + shown_.file.string() +
           (shown_.is_last_good ? " (LAST GOOD COPY: " + shown_.primary_error + ")" : "") + ": scene '" +
           scene_->scene.name + "', " + std::to_string(scene_->scene.objects.size()) + " objects, " +
           std::to_string(scene_->sgs.size()) + " SGs" +
           (read->baked_for.empty() ? "" : "; the bake measured " + read->baked_for + " for it") + "; drawing " +
           method_->name);
}

bool Kiosk::open_display() {
  width_ = config_.size[0];
  height_ = config_.size[1];
  if (config_.display != "headless") {
    try {
      kms_ = std::make_unique<gpu::KmsDisplay>();
      width_ = kms_->width();
      height_ = kms_->height();
      log_info("display " + kms_->description());
    } catch (const std::exception& e) {
      if (config_.display == "kms") {
        log_error(std::string("no display: ") + e.what());
        notifier_.status(std::string("no display: ") + e.what());
        return false;
      }
      log_warning(std::string("no KMS display (") + e.what() + "); running headless");
    }
  }
  if (!kms_) {
    headless_ = std::make_unique<gpu::EglContext>(gpu::EglContext::headless());
    log_info("headless " + std::to_string(width_) + "x" + std::to_string(height_) + " on " + headless_->renderer());
  }
  return true;
}

void Kiosk::make_knob_controller(const SceneBundle& sb) {
  presets_ = preset_list(sb);
  input::KnobControllerOptions ko;
  ko.state_file = state_dir_ok_ ? std::filesystem::path(config_.state_dir) / "knobs.json" : std::filesystem::path();
  ko.default_preset = default_preset(sb);
  controller_ = std::make_unique<input::KnobController>(input::KnobMapper(preset_looks(presets_), mapping_), ko, stderr_sink("weft run"));
}

void Kiosk::start_knobs() {
  input::PanelConfig panel;
  if (!config_.panel_config.empty()) {
    try {
      panel = input::parse_panel_config(read_config_file(config_.panel_config, "--panel-config"), config_.panel_config);
    } catch (const input::PanelConfigError& e) {
      throw KioskConfigError(e.what());
    }
  }
  mapping_.zoom_dial = panel.zoom_dial;
  make_knob_controller(*scene_);
  controller_->restore();
  const input::LogSink log = stderr_sink("weft run");

  KnobSourceOptions so;
  so.sim_speed = config_.sim_speed;
  so.last_report_ns = &last_report_ns_;
  so.log = log;
  const bool from_panel_config = config_.panel.empty();
  try {
    sources_ = make_knob_sources(from_panel_config ? panel.sources : std::vector<std::string>{config_.panel}, panel, so).sources;
  } catch (const UnknownKnobSourceError& e) {
    if (from_panel_config)
      throw KioskConfigError(config_.panel_config + ": sources: expected hid, gpio, keyboard, sim:SCRIPT or none, got '" +
                             e.name() + "'");
    throw KioskConfigError("--panel: expected hid, gpio, keyboard, sim:SCRIPT or none, got '" + e.name() + "'");
  }
}

void Kiosk::start_renderer() {
  const SceneBundle& sb = *scene_;
  cloth_fabrics_ = cloth_fabrics(sb);
  closeup_ = closeup_of(sb.scene, cloth_fabrics_, height_);
  renderer_ = std::make_unique<gpu::SceneRenderer>(sb.scene, cloth_fabrics_, *method_, 16, iwasaki_);
  renderer_->set_backdrop(gpu::Backdrop::showroom);
  show_weave(*renderer_, sb.scene);
  target_ = std::make_unique<gpu::OffscreenTarget>(width_, height_);
  if (kms_) tonemap_ = std::make_unique<gpu::ToneMapper>();
}

void Kiosk::start_probe() {
  room_light_ = scene_->sgs;
  if (config_.probe != "none") {
    probe_ = std::make_unique<KioskLightProbe>(config_.probe, config_.probe_switch_s, scene_->sgs,
                                               [](LogPriority p, const std::string& s) { log_line("weft run", p, "light probe: " + s); });
    log_info("light probe " + config_.probe + " started; the bundle's SGs stay until its first fit");
  }
  lighting_ = std::make_unique<LatestRequestWorker<LightingRequest, LightingResult>>([this](const LightingRequest& q) {
    const auto t0 = Clock::now();
    LightingResult r{q.renderer, q.renderer->prepare_lighting(q.sgs)};
    last_prepare_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    ++lighting_prepared_;
    return r;
  });
}

void Kiosk::show_first_frame() {
  // The exposure is metered first on the bundle as baked (its own fabrics under its own light,
  // a quarter-size frame), so that a knob state restored at boot shows the picture it showed
  // when the knobs were turned (knob edits never re-meter).
  renderer_->set_lighting(scene_->sgs);
  meter_as_baked();
  poll_knobs();
  if (light_rotation_ < 0) renderer_->set_lighting(scene_->sgs);
  zoom_shown_ = zoom_drawn_ = zoom_target_;  // a kiosk started zoomed in (--zoom) shows it at once
  draw_frame(0);
  drawn_ = 1;
  first_frame_shown_ = true;
  const double boot_ms = std::chrono::duration<double, std::milli>(Clock::now() - boot_).count();
  const std::string where = kms_ ? kms_->description() : "headless";
  char line[256];
  std::snprintf(line, sizeof line, "first frame after %.0f ms (%dx%d, %s, %s)", boot_ms, width_, height_, where.c_str(),
                method_->name.c_str());
  log_info(line);
  notifier_.ready(std::string("showing '") + scene_->scene.name + "'" +
                  (shown_.is_last_good ? " from the LAST GOOD bundle" : "") + " on " + where);
  if (notifier_.watchdog_enabled())
    log_info("watchdog every " + std::to_string(notifier_.watchdog_interval().count() / 1000) + " ms");
}

void Kiosk::listen_to_knobs() {
  for (auto& s : sources_) {
    log_info("listening to " + s->describe());
    s->start([this](const input::KnobEvent& e) {
      std::lock_guard lock(controller_m_);
      controller_->on_event(e);
    });
  }
}

void Kiosk::arm_fault_injection() {
  if (const char* h = std::getenv("WEFT_FAULT_HANG_AFTER_TICKS")) {
    hang_after_ = std::atol(h);
    log_warning("FAULT INJECTION: the frame loop hangs after " + std::to_string(hang_after_) + " ticks");
  }
}

void Kiosk::tick() {
  ++ticks_;
  if (ticks_ == hang_after_)
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // a stuck loop: no frames, no pings
  const auto tick_start = Clock::now();
  const double turn = config_.turntable * std::chrono::duration<double>(tick_start - loop_start_).count();
  const int64_t report_ns = last_report_ns_.load();
  const bool knobs_changed = poll_knobs();
  poll_light();
  const bool light_changed = take_prepared_lighting();
  const bool scene_changed = poll_bundle();
  zoom_shown_ = ease_zoom(zoom_shown_, zoom_target_, std::chrono::duration<double>(tick_start - zoom_step_).count());
  zoom_step_ = tick_start;
  const bool view_changed = std::abs(turn - shown_turn_) > 1e-4 || zoom_shown_ != zoom_drawn_;
  const bool adapting = std::abs(std::log(exposure_ / exposure_target_)) > 0.01;  // still easing in
  const bool redraw = knobs_changed || light_changed || scene_changed || view_changed || adapting;
  if (redraw) {
    draw_frame(turn);
    shown_turn_ = turn;
    zoom_drawn_ = zoom_shown_;
    ++drawn_;
    if (scene_changed) log_swap_shown();
    if (knobs_changed && report_ns != 0)
      latency_ms_.push(double(Clock::now().time_since_epoch().count() - report_ns) / 1e6);
  }
  notifier_.tick();
  if (config_.stats_every > 0 && tick_start - last_stats_ >= std::chrono::duration<double>(config_.stats_every))
    log_stats(tick_start);
  // On KMS a drawn frame already waited for vsync.
  if (!kms_ || !redraw) std::this_thread::sleep_until(tick_start + kTickPeriod);
}

void Kiosk::shut_down() {
  for (auto& s : sources_) s->stop();
  probe_.reset();
  controller_->flush();
  if (!config_.screenshot.empty()) {
    target_->bind();
    try {
      write_png(gpu::read_linear_image(width_, height_), config_.screenshot, exposure_);
      log_info("screenshot " + config_.screenshot);
    } catch (const std::exception& e) {
      log_warning(std::string("screenshot failed: ") + e.what());
    }
  }
  char line[256];
  std::snprintf(line, sizeof line,
                "stopping after %ld ticks, %ld frames drawn; median %.2f ms/frame; %zu knob changes shown, "
                "report->photon median %.1f ms max %.1f ms; RSS %ld -> %ld KiB",
                ticks_, drawn_, frame_ms_.median(1), latency_ms_.size(), latency_ms_.median(), latency_ms_.max(),
                rss_start_kib_, resident_set_kib());
  log_info(line);
  notifier_.stopping("stopping");
}

bool Kiosk::poll_knobs() {
  if (controller_->channel().version() == knob_version_) return false;
  uint64_t v = 0;
  if (!controller_->channel().read(knobs_, &v)) return false;  // writer mid-update: next tick
  knob_version_ = v;
  apply_knob_state(knobs_);
  return true;
}

void Kiosk::poll_light() {
  if (!probe_ || !probe_->acquire()) return;
  room_light_ = probe_->lighting();
  relight(rotated_about_z(room_light_, std::max(light_rotation_, 0.0f)));
}

bool Kiosk::take_prepared_lighting() {
  bool uploaded = false;
  try {
    if (auto prepared = lighting_->take()) {
      // Requests run in order: once one made for the renderer shown is done, none for a retired one runs.
      if (prepared->renderer == renderer_.get()) {
        renderer_->set_lighting(prepared->lighting);
        retired_.clear();
        meter_next_ = true;
        uploaded = true;
      }
    }
  } catch (const std::exception& e) {
    log_warning(std::string("lighting: ") + e.what() + "; keeping the light shown");
  }
  if (!retired_.empty() && lighting_->idle()) retired_.clear();
  return uploaded;
}

bool Kiosk::poll_bundle() {
  if (!watcher_) return false;
  if (auto change = watcher_->poll()) {
    log_info("bundle " + config_.bundle + " changed (" + change->events + "); reading it");
    loader_->request(*change);
  }
  if (pending_) return finish_swap();
  std::optional<LoadedBundle> loaded;
  try {
    loaded = loader_->take();
  } catch (const std::exception& e) {
    log_error(std::string("content update refused: ") + e.what() + "; still showing '" + scene_->scene.name +
              "' from " + shown_.file.string());
    notifier_.status("showing '" + scene_->scene.name + "'; the new bundle was refused (see journal)");
    return false;
  }
  if (!loaded) return false;
  if (loaded->unchanged) {
    log_info("bundle " + config_.bundle + " holds the content shown; nothing to swap");
    return false;
  }
  start_swap(std::move(*loaded));
  return false;
}

// The new bundle's GPU resources, built here (the GL context is this thread's), then its lighting
// on a worker: the loop keeps drawing the scene shown meanwhile.
void Kiosk::start_swap(LoadedBundle loaded) {
  const auto t0 = Clock::now();
  auto p = std::make_unique<PendingSwap>();
  p->change = loaded.change;
  p->reader = std::move(loaded.reader);
  p->bundle = std::move(*loaded.bundle);
  p->method = loaded.method;
  p->cloth_fabrics = cloth_fabrics(p->bundle.scene);
  // The probe's room light outlives the bundle; without a probe fit the new bundle's SGs light it.
  p->room_light = probe_ && probe_->updates() > 0 ? room_light_ : p->bundle.scene.sgs;
  try {
    p->renderer = std::make_unique<gpu::SceneRenderer>(p->bundle.scene.scene, p->cloth_fabrics, *p->method, 16, p->bundle.iwasaki);
    p->renderer->set_backdrop(gpu::Backdrop::showroom);
    show_weave(*p->renderer, p->bundle.scene.scene);
  } catch (const std::exception& e) {
    log_error("content update refused: bundle " + config_.bundle + ": cannot draw it: " + e.what() + "; still showing '" +
              scene_->scene.name + "' from " + shown_.file.string());
    return;
  }
  swap_read_ms_ = loaded.read_ms;
  swap_gpu_ms_ = ms_since(t0);
  p->light_version = light_version_;
  p->lighting_start = Clock::now();
  const gpu::SceneRenderer* r = p->renderer.get();
  p->lighting = std::async(std::launch::async, [r, sgs = rotated_about_z(p->room_light, std::max(light_rotation_, 0.0f))] {
    return r->prepare_lighting(sgs);
  });
  pending_ = std::move(p);
}

bool Kiosk::finish_swap() {
  if (pending_->lighting.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  std::unique_ptr<PendingSwap> p = std::move(pending_);
  try {
    p->renderer->set_lighting(p->lighting.get());
  } catch (const std::exception& e) {
    log_error("content update refused: bundle " + config_.bundle + ": cannot light it: " + e.what() + "; still showing '" +
              scene_->scene.name + "' from " + shown_.file.string());
    return false;
  }
  swap_light_ms_ = ms_since(p->lighting_start);
  // The knobs' fabric slots: the preset list the fabric knob steps through, and the preset the
  // scene's cloth starts from. While both match, the shopper's turns stay meaningful.
  const std::vector<input::PresetLook> old_looks = preset_looks(presets_);
  const std::vector<input::PresetLook> new_looks = preset_looks(preset_list(p->bundle.scene));
  const uint32_t old_default = default_preset(*scene_), new_default = default_preset(p->bundle.scene);
  std::string knobs_differ;
  if (!same_knob_presets(old_looks, new_looks))
    knobs_differ = "the fabric presets differ: [" + preset_names(old_looks) + "] -> [" + preset_names(new_looks) + "]";
  else if (old_default != new_default)
    knobs_differ = "the cloth wears '" + new_looks.at(new_default).name + "' instead of '" + old_looks.at(old_default).name + "'";

  retired_.push_back(std::move(renderer_));
  renderer_ = std::move(p->renderer);
  cloth_fabrics_ = std::move(p->cloth_fabrics);
  method_ = p->method;
  iwasaki_ = p->bundle.iwasaki;
  room_light_ = p->room_light;
  scene_ = std::move(p->bundle.scene);
  closeup_ = closeup_of(scene_->scene, cloth_fabrics_, height_);
  shown_ = {config_.bundle, false, ""};
  shown_fingerprint_ = p->bundle.fingerprint;
  swapped_ = p->change;
  // The bundle shown becomes the last good copy, written (and fsynced) off the render thread.
  if (state_dir_ok_) {
    if (saving_.valid()) saving_.wait();  // the previous one, rarely still running
    saving_ = std::async(std::launch::async, [this, reader = std::move(*p->reader)] {
      bundle::save_as_last_good(reader, config_.bundle, config_.state_dir, stderr_sink("weft run"));
    });
  }

  if (knobs_differ.empty())
    log_info("knob state carried over (the same fabric presets and the same fabric on the cloth)");
  else
    reset_knobs(*scene_, knobs_differ);
  // A new scene is metered as at boot, before the knobs dress it.
  meter_as_baked();
  // The knobs onto the new renderer: the same positions, or the reset ones.
  knob_version_ = ~0ull;
  if (!poll_knobs()) apply_knob_state(knobs_);
  if (light_version_ != p->light_version) relight(rotated_about_z(room_light_, std::max(light_rotation_, 0.0f)));
  return true;
}

void Kiosk::reset_knobs(const SceneBundle& sb, const std::string& why) {
  std::lock_guard lock(controller_m_);
  controller_.reset();  // saves what the old presets' knobs had pending
  make_knob_controller(sb);
  const uint32_t preset = default_preset(sb);
  log_warning("knob state reset to preset '" + preset_looks(presets_).at(preset).name + "' (" + why + ")");
  const auto file = std::filesystem::path(config_.state_dir) / "knobs.json";
  if (state_dir_ok_) {
    input::KnobPositions start;
    start.preset = preset;
    std::string error;
    if (!input::write_file_atomically(file, input::knob_state_text(start, preset_looks(presets_)), error))
      log_warning("could not save the reset knob state (" + error + ")");
  }
  controller_->restore();
}

void Kiosk::log_swap_shown() {
  ++bundles_swapped_;
  const double total_ms = ms_since(swapped_->first_event);
  char line[512];
  std::snprintf(line, sizeof line,
                "bundle %s shown %.0f ms after it changed: scene '%s', %zu objects, %zu SGs, %s (read and verified "
                "%.0f ms, GPU resources %.0f ms, lighting %.0f ms)",
                config_.bundle.c_str(), total_ms, scene_->scene.name.c_str(), scene_->scene.objects.size(),
                scene_->sgs.size(), method_->name.c_str(), swap_read_ms_, swap_gpu_ms_, swap_light_ms_);
  log_info(line);
  notifier_.status("showing '" + scene_->scene.name + "' on " + (kms_ ? kms_->description() : std::string("headless")));
  swapped_.reset();
}

void Kiosk::apply_knob_state(const input::AppearanceState& s) {
  const Fabric f = apply_knobs(presets_.at(std::min<size_t>(s.preset_index, presets_.size() - 1)), s);
  try {
    const std::string dressed = knob_fabric(*scene_);
    size_t c = 0;
    for (const auto& o : scene_->scene.cloth_objects()) {
      if (o.fabric == dressed) renderer_->set_fabric(c, f);
      ++c;
    }
  } catch (const gpu::GpuError& e) {  // e.g. a preset the bundle baked no tables for
    log_warning(std::string("knobs: ") + e.what() + "; keeping the fabric shown");
  }
  zoom_target_ = std::clamp(config_.zoom + double(s.zoom), 0.0, 1.0);
  if (s.env_rotation_deg != light_rotation_) {
    // Before the first frame a turned light is set at once: meter the first frame under it
    // (afterwards the worker's hand-over asks for metering: take_prepared_lighting).
    if (!first_frame_shown_ && s.env_rotation_deg != 0) meter_next_ = true;
    relight(rotated_about_z(room_light_, s.env_rotation_deg));
    light_rotation_ = s.env_rotation_deg;
  }
}

// Before the first frame the lighting is set here and now; after it, on the worker.
void Kiosk::relight(const SgLighting& sgs) {
  ++light_version_;
  if (first_frame_shown_)
    lighting_->request({renderer_.get(), sgs});
  else
    renderer_->set_lighting(sgs);
}

void Kiosk::draw_frame(double turn_deg) {
  const auto t0 = Clock::now();
  target_->bind();
  renderer_->draw(turned_about_z(dolly(scene_->scene.camera, closeup_, zoom_shown_), turn_deg), width_, height_);
  if (meter_next_) meter_exposure(width_, height_);
  const auto now = Clock::now();
  exposure_ = adapt_exposure(exposure_, exposure_target_, std::chrono::duration<double>(now - exposure_step_).count(),
                             kExposureAdaptSeconds);
  exposure_step_ = now;
  if (kms_) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width_, height_);
    tonemap_->draw(target_->colour_texture(), float(exposure_));
    kms_->present();
  } else {
    glFinish();
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  frame_ms_.push(ms);
  since_stats_ms_.push(ms);
}

double Kiosk::exposure_bias_ev() const { return config_.exposure_bias + std::log2(config_.exposure); }

void Kiosk::meter_as_baked() {
  target_->bind();
  const int mw = std::max(8, width_ / 4), mh = std::max(8, height_ / 4);
  renderer_->draw(scene_->scene.camera, mw, mh);
  exposure_ = 0.0;  // shown at once, not eased in from another scene's
  meter_exposure(mw, mh);
}

void Kiosk::meter_exposure(int width, int height) {
  std::vector<float> rgba(size_t(width) * height * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
  std::vector<glm::dvec3> cloth;
  cloth.reserve(rgba.size() / 4);
  for (size_t i = 0; i + 3 < rgba.size(); i += 4)
    if (gpu::is_cloth_alpha(rgba[i + 3])) cloth.emplace_back(rgba[i], rgba[i + 1], rgba[i + 2]);
  exposure_target_ = metered_exposure(log_average_luminance(cloth), exposure_bias_ev());
  if (exposure_ <= 0.0) exposure_ = exposure_target_;  // the first frame shows the metered exposure at once
  meter_next_ = false;
}

void Kiosk::log_stats(Clock::time_point now) {
  char line[256];
  std::snprintf(line, sizeof line,
                "stats: %ld ticks, %ld frames drawn, median %.2f ms/frame over the last %zu, RSS %ld KiB, "
                "%llu light-probe updates, lighting prepared off-thread %ld times (last %.0f ms)",
                ticks_, drawn_, since_stats_ms_.median(), since_stats_ms_.size(), resident_set_kib(),
                static_cast<unsigned long long>(probe_ ? probe_->updates() : 0), lighting_prepared_.load(),
                last_prepare_ms_.load());
  log_info(line);
  last_stats_ = now;
  since_stats_ms_.clear();
}

}  // namespace weft
