#include "kiosk/kiosk_label.h"

#include <algorithm>
#include <cmath>

#include "kiosk/kiosk_log.h"
#include "kiosk/knob_presets.h"

namespace weft {

double label_opacity(double since_change_s, double idle_s) {
  if (idle_s <= 0 || since_change_s <= idle_s) return 1.0;
  const double t = std::min((since_change_s - idle_s) / kLabelFadeSeconds, 1.0);
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

LabelText label_text(const Fabric& shown, const std::string& colourway) {
  return {shown.display_name.empty() ? shown.name : shown.display_name, colourway, shown.composition};
}

LabelText label_text(const SceneBundle& sb, std::size_t preset, std::uint32_t colourway) {
  if (sb.fabrics.empty()) return {};
  const auto worn = std::next(sb.fabrics.begin(), std::ptrdiff_t(std::min(preset, sb.fabrics.size() - 1)));
  const auto& ways = sb.scene.colourways;
  LabelText t = label_text(worn->second, colourway < ways.size() ? ways[colourway].name : "");
  const std::string dressed = knob_fabric(sb);
  if (dressed != worn->first) return t;
  for (const auto& o : sb.scene.cloth_objects())
    if (o.fabric == dressed) {
      if (!o.display_name.empty()) t.title = o.display_name;
      if (!o.composition.empty()) t.composition = o.composition;
      break;
    }
  return t;
}

KioskLabel::KioskLabel(const KioskConfig& c)
    : idle_s_(c.label_idle_s), corner_(*label::parse_corner(c.label_position)), size_px_(c.label_size) {
  try {
    title_font_ = std::make_unique<label::LabelFont>(c.label_font, size_px_);
    // The colourway and composition lines smaller than the name, never below what reads.
    detail_font_ = std::make_unique<label::LabelFont>(c.label_font, std::max(8, int(std::lround(0.7 * size_px_))));
    overlay_ = std::make_unique<label::LabelOverlay>();
  } catch (const label::LabelFontError& e) {
    kiosk_log_warning(std::string("label off: ") + e.what());
    title_font_.reset();
    detail_font_.reset();
  }
}

KioskLabel::~KioskLabel() = default;

void KioskLabel::show(const LabelText& text) {
  restart_ = true;
  if (!overlay_ || (text == text_ && drawn_opacity_ >= 0)) return;
  text_ = text;
  const int padding = std::max(4, size_px_ / 3);
  overlay_->set_image(label::rasterise_lines(
      {{text.title, title_font_.get()}, {text.colourway, detail_font_.get()}, {text.composition, detail_font_.get()}}, padding));
  drawn_opacity_ = -1;  // the next frame shows the new text
}

float KioskLabel::opacity(Clock::time_point now) const {
  return float(label_opacity(std::chrono::duration<double>(now - changed_at_).count(), idle_s_));
}

bool KioskLabel::changed(Clock::time_point now) const {
  return overlay_ && overlay_->width() > 0 && (restart_ ? 1.0f : opacity(now)) != drawn_opacity_;
}

void KioskLabel::present(Clock::time_point now) { drawn_opacity_ = restart_ ? 1.0f : opacity(now); }

void KioskLabel::presented(Clock::time_point now) {
  if (restart_) changed_at_ = now;
  restart_ = false;
}

void KioskLabel::draw(int frame_width, int frame_height) const {
  if (!overlay_ || drawn_opacity_ <= 0) return;
  const label::Box box = label::place_box(corner_, size_px_, frame_width, frame_height, overlay_->width(), overlay_->height());
  overlay_->draw(box, drawn_opacity_);
}

}  // namespace weft
