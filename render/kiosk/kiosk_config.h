#pragma once
// What `weft run` is asked to do (its flags, weft.conf through the service), and the check of
// the values that can be checked before anything starts.
#include <string>
#include <vector>

namespace weft {

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
  // Temporal reuse of the per-vertex passes while only the turntable moves the camera
  // (gpu::SceneRenderer::set_vertex_refresh): each frame recomputes 1/shares of the cloth's
  // vertices, where shares is the larger of vertex_refresh and the frames the turntable takes to
  // turn vertex_refresh_deg; a kept value is carried on along the line through its last two
  // computations to the frame's time (gpu::SceneRenderer::set_clock), and vertices seen nearly
  // edge-on are recomputed every frame (the degrees apply only to a method that does this:
  // ClothMethod::reuse_follows_camera). A knob, lighting or zoom change recomputes all at once.
  // vertex_refresh 1 with vertex_refresh_deg 0: all, every frame.
  int vertex_refresh = 1;
  double vertex_refresh_deg = 1.6;
  // The broad lobes' quadrature alone (gpu::SceneRenderer::set_broad_lobe_refresh), whose radiance
  // changes slowly with the view, is recomputed for every vertex at least once per this many degrees
  // of turntable (each frame the share its turn calls for); 0: every frame.
  double broad_lobe_refresh_deg = 6.0;
  // The weave layer's terms up close over a per-vertex rung (kiosk/weave_terms_governor.h): auto
  // (each float lit per pixel while the frames that show threads take at most weave_budget_ms,
  // else the per-vertex table), pixel or table.
  std::string weave_terms = "auto";
  double weave_budget_ms = 40.0;
  double stats_every = 300;               // seconds between stats lines; 0: none
  // The per-stage frame profile (gl/frame_profile.h) in the stats lines and the last line:
  // off, auto (GPU timestamps where the driver has them), gpu or cpu.
  std::string profile = "off";
  std::string probe = "none";             // none, camera[:ID] or mock:MAP.exr[,MAP.exr...]
  double probe_switch_s = 0;              // mock probe with several maps: seconds between switches
  std::string status_file;                // the health file (kiosk/kiosk_status_file.h); empty: none
  // The label (kiosk/kiosk_label.h): the dressed fabric's name, colourway and composition in a
  // corner, fading out while the knobs are idle. Off unless asked for; weft.service turns it on.
  std::string label = "off";              // on or off
  std::string label_position = "bottom-left";  // bottom-left, bottom-right, top-left or top-right
  int label_size = 32;                    // the name's size in pixels (the em); also the margin
  // After this many seconds without a knob change the look eases back to the bundle's start
  // (kiosk/idle_return.h); 0: it stays as the knobs left it.
  double idle_return_s = 0;
  // Daily screen-off period in local time, "HH:MM-HH:MM" (kiosk/screen_schedule.h); "": never.
  std::string screen_off;
  double label_idle_s = 8;                // shown this long after start or a knob change, then fades; 0: never fades
  std::string label_font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // label::kDefaultFontFile

  // The screen (kiosk/kiosk_display.h): which connector, in which mode, turned for a portrait
  // screen; and how long the kiosk may go without one before it reports it (kiosk/screen_wait.h).
  std::string connector;       // "HDMI-A-1"; empty: the first connected
  std::string mode;            // WxH or WxH@R; empty or "preferred": the monitor's preferred mode
  int rotation = 0;            // degrees clockwise: 0, 90, 180 or 270
  double display_wait_s = 60;  // seconds without a screen before the report; 0: never
};

// Throws KioskConfigError (kiosk/kiosk_config_error.h) naming the flag of the first bad value.
void check_kiosk_config(const KioskConfig& c);

}  // namespace weft
