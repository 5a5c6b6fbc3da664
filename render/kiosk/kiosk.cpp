#include "kiosk/kiosk.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>

#include "gpu/egl_context.h"
#include "gpu/kms_display.h"
#include "gl/offscreen_target.h"
#include "image/image.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_light_probe.h"
#include "kiosk/knob_appearance.h"
#include "kiosk/knob_sources.h"
#include "kiosk/turntable.h"
#include "journal/journal_log.h"
#include "panel/panel_config.h"

namespace weft {
namespace {

// Every line goes to stderr, which systemd sends to the journal (with its priority).
void log_info(const std::string& s) { log_line("weft run", LogPriority::info, s); }
void log_warning(const std::string& s) { log_line("weft run", LogPriority::warning, s); }
void log_error(const std::string& s) { log_line("weft run", LogPriority::error, s); }

constexpr auto kTickPeriod = std::chrono::microseconds(16667);

}  // namespace

Kiosk::Kiosk(KioskConfig config) : config_(std::move(config)) {}

Kiosk::~Kiosk() = default;

int Kiosk::run(const std::atomic<bool>& stop) {
  boot_ = Clock::now();
  check_config();
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
  if (!std::isfinite(c.turntable) || std::abs(c.turntable) > 360)
    throw KioskConfigError("--turntable: degrees per second in [-360, 360]");
  if (c.method != "auto") try {
      gpu::parse_method(c.method);
    } catch (const std::invalid_argument& e) {
      throw KioskConfigError(std::string("--method: ") + e.what() + " or auto");
    }
  std::error_code ec;
  std::filesystem::create_directories(c.state_dir, ec);
  state_dir_ok_ = !ec;
  if (ec)
    log_warning("cannot create state directory " + c.state_dir + ": " + ec.message() + " (no last-good copy, no knob state)");
}

void Kiosk::load_bundle() {
  notifier_.status("loading bundle " + config_.bundle);
  bundle::FallbackOptions fo;
  // Seed 000's tables are read in the accept step too: a bundle whose tables do not read (a
  // section missing, a shape that does not match the mesh) falls back like a corrupt one.
  fo.accept = [this](const bundle::BundleReader& r) {
    scene_ = read_scene_bundle(r);
    iwasaki_.reset();
    if (has_iwasaki_sections(r) && config_.method != "sgpoint") {
      std::map<size_t, size_t> vertices;
      for (size_t i = 0; i < scene_->scene.objects.size(); ++i) vertices[i] = scene_->scene.objects[i].mesh.positions.size();
      iwasaki_ = std::make_shared<IwasakiBundleData>(read_iwasaki_sections(r, vertices));
    }
  };
  fo.log = stderr_sink("weft run");
  try {
    opened_.emplace(bundle::open_bundle_with_fallback(config_.bundle, config_.state_dir, fo));
  } catch (const bundle::BundleError& e) {
    log_error(std::string("no usable bundle: ") + e.what());
    notifier_.status("no usable bundle (see journal)");
    throw;
  }
  if (!scene_) fo.accept(opened_->bundle);
  bool sheer = false;  // a cloth object shown as a sheer (an optical thickness of its fabric's or its own)
  for (const auto& o : scene_->scene.objects)
    if (o.material == Material::cloth)
      sheer = sheer || object_fabric(o, scene_->fabrics.at(o.fabric)).optical_thickness > 0.0;
  method_ = &gpu::parse_method(config_.method != "auto" ? config_.method
                               : iwasaki_               ? (sheer ? "sheer_vertex" : "iwasaki_vertex")
                                                        : "sgpoint");
  if (gpu::uses_seed000_tables(*method_) && !iwasaki_)
    throw KioskConfigError("--method " + method_->name + ": bundle " + opened_->file.string() +
                           " has no seed 000 tables (weft bake without --no-tables)");
  (opened_->is_last_good ? log_warning : log_info)("bundle " + opened_->file.string() +
           (opened_->is_last_good ? " (LAST GOOD COPY: " + opened_->primary_error + ")" : "") + ": scene '" +
           scene_->scene.name + "', " + std::to_string(scene_->scene.objects.size()) + " objects, " +
           std::to_string(scene_->sgs.size()) + " SGs");
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

void Kiosk::start_knobs() {
  const SceneBundle& sb = *scene_;
  std::vector<std::string> preset_names;
  for (const auto& [name, f] : sb.fabrics) {
    preset_names.push_back(name);
    presets_.push_back(f);
  }
  uint32_t default_preset = 0;
  for (const auto& o : sb.scene.objects)
    if (o.material == Material::cloth)
      default_preset = uint32_t(std::find(preset_names.begin(), preset_names.end(), o.fabric) - preset_names.begin());
  input::PanelConfig panel;
  if (!config_.panel_config.empty()) {
    try {
      panel = input::parse_panel_config(read_config_file(config_.panel_config, "--panel-config"), config_.panel_config);
    } catch (const input::PanelConfigError& e) {
      throw KioskConfigError(e.what());
    }
  }
  input::KnobControllerOptions ko;
  ko.state_file = state_dir_ok_ ? std::filesystem::path(config_.state_dir) / "knobs.json" : std::filesystem::path();
  ko.default_preset = default_preset;
  const input::LogSink log = stderr_sink("weft run");
  controller_ = std::make_unique<input::KnobController>(input::KnobMapper(preset_looks(presets_)), ko, log);
  controller_->restore();

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
  for (const auto& o : sb.scene.objects)
    if (o.material == Material::cloth) cloth_fabrics_.push_back(sb.fabrics.at(o.fabric));
  renderer_ = std::make_unique<gpu::SceneRenderer>(sb.scene, cloth_fabrics_, *method_, 16, iwasaki_);
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
  lighting_ = std::make_unique<LatestRequestWorker<SgLighting, gpu::SceneRenderer::PreparedLighting>>(
      [this](const SgLighting& sgs) {
        const auto t0 = Clock::now();
        auto prepared = renderer_->prepare_lighting(sgs);
        last_prepare_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        ++lighting_prepared_;
        return prepared;
      });
}

void Kiosk::show_first_frame() {
  poll_knobs();
  if (light_rotation_ < 0) renderer_->set_lighting(scene_->sgs);
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
                  (opened_->is_last_good ? " from the LAST GOOD bundle" : "") + " on " + where);
  if (notifier_.watchdog_enabled())
    log_info("watchdog every " + std::to_string(notifier_.watchdog_interval().count() / 1000) + " ms");
}

void Kiosk::listen_to_knobs() {
  for (auto& s : sources_) {
    log_info("listening to " + s->describe());
    s->start(controller_->sink());
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
  const bool view_changed = std::abs(turn - shown_turn_) > 1e-4;
  const bool redraw = knobs_changed || light_changed || view_changed;
  if (redraw) {
    draw_frame(turn);
    shown_turn_ = turn;
    ++drawn_;
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
      write_png(gpu::read_linear_image(width_, height_), config_.screenshot, config_.exposure);
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
  try {
    if (auto prepared = lighting_->take()) {
      renderer_->set_lighting(*prepared);
      return true;
    }
  } catch (const std::exception& e) {
    log_warning(std::string("lighting: ") + e.what() + "; keeping the light shown");
  }
  return false;
}

void Kiosk::apply_knob_state(const input::AppearanceState& s) {
  const Fabric f = apply_knobs(presets_.at(std::min<size_t>(s.preset_index, presets_.size() - 1)), s);
  try {
    for (size_t c = 0; c < cloth_fabrics_.size(); ++c) renderer_->set_fabric(c, f);
  } catch (const gpu::GpuError& e) {  // e.g. a preset the bundle baked no tables for
    log_warning(std::string("knobs: ") + e.what() + "; keeping the fabric shown");
  }
  if (s.env_rotation_deg != light_rotation_) {
    relight(rotated_about_z(room_light_, s.env_rotation_deg));
    light_rotation_ = s.env_rotation_deg;
  }
}

// Before the first frame the lighting is set here and now; after it, on the worker.
void Kiosk::relight(const SgLighting& sgs) {
  if (first_frame_shown_)
    lighting_->request(sgs);
  else
    renderer_->set_lighting(sgs);
}

void Kiosk::draw_frame(double turn_deg) {
  const auto t0 = Clock::now();
  target_->bind();
  renderer_->draw(turned_about_z(scene_->scene.camera, turn_deg), width_, height_);
  if (kms_) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width_, height_);
    tonemap_->draw(target_->colour_texture(), float(config_.exposure));
    kms_->present();
  } else {
    glFinish();
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  frame_ms_.push(ms);
  since_stats_ms_.push(ms);
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
