#pragma once
// The kiosk's label (--label on): the fabric the knobs dress, by the name a shopper reads, its
// colourway and composition, in a corner of the screen (render/label). Fully shown for
// --label-idle seconds after start and after every knob change, then faded out over
// kLabelFadeSeconds; while it fades the loop re-presents the frame (no scene redraw), once faded
// it costs nothing.
#include <chrono>
#include <memory>
#include <cstdint>
#include <string>

#include "core/fabric.h"
#include "kiosk/kiosk_config.h"
#include "runtime/scene_bundle.h"
#include "label/label_overlay.h"
#include "label/label_text.h"

namespace weft {

inline constexpr double kLabelFadeSeconds = 1.0;

// The label's opacity `since_change_s` seconds after the last change: 1 for idle_s, then down to
// 0 over kLabelFadeSeconds (smoothstep, no visible step at either end); idle_s 0: always 1.
double label_opacity(double since_change_s, double idle_s);

// What the label says. An empty line shows nothing; all empty: no label.
struct LabelText {
  std::string title;       // the fabric's display_name, else its name
  std::string colourway;   // the colourway's name; empty until fabrics have colourways
  std::string composition;
  bool operator==(const LabelText&) const = default;
};
LabelText label_text(const Fabric& shown, const std::string& colourway = "");
// The label for a bundle whose knobs select preset `preset` (its index in sb.fabrics): that
// fabric's text, with the display_name and composition the glTF gave the cloth object the knobs
// dress, where that object still wears the fabric it was baked in. Empty when sb has no fabric.
LabelText label_text(const SceneBundle& sb, std::size_t preset, std::uint32_t colourway = 0);

class KioskLabel {
public:
  using Clock = std::chrono::steady_clock;
  // Needs the GL context current. A font that cannot be used is one warning in the journal and
  // a label that draws nothing (usable() false); the kiosk runs on without it.
  explicit KioskLabel(const KioskConfig& config);
  ~KioskLabel();
  bool usable() const { return overlay_ != nullptr; }

  // The text to show (rasterised again only when it differs), fully visible again: its idle
  // time runs from when the next frame is on screen (presented(); the first frame can take
  // seconds).
  void show(const LabelText& text);
  // True when a frame presented at `now` would show the label otherwise than the last one did.
  bool changed(Clock::time_point now) const;
  // A frame is about to be presented at `now`: the label takes its opacity then (headless too,
  // where nothing is drawn until the screenshot).
  void present(Clock::time_point now);
  // That frame is on screen (KMS: flipped; headless: finished) at `now`.
  void presented(Clock::time_point now);
  // Blends the label, at the opacity of the last present(), over the bound frame_width ×
  // frame_height framebuffer (after tone mapping).
  void draw(int frame_width, int frame_height) const;

private:
  float opacity(Clock::time_point now) const;

  double idle_s_;
  label::Corner corner_;
  int size_px_;
  std::unique_ptr<label::LabelFont> title_font_, detail_font_;
  std::unique_ptr<label::LabelOverlay> overlay_;
  LabelText text_;
  Clock::time_point changed_at_{};
  bool restart_ = true;       // the next presented() starts the idle time
  float drawn_opacity_ = -1;  // < 0: nothing drawn yet
};

}  // namespace weft
