#include "core/weave_layout.h"

#include <cmath>

namespace weft {

namespace {
double fraction(double x) { return x - std::floor(x); }

int default_rows(double warp_share) {
  const double minority = std::min(warp_share, 1.0 - warp_share);
  if (minority >= 0.4) return 2;
  if (minority >= 0.2) return 4;
  return 5;
}
}  // namespace

WeaveLayout::WeaveLayout(const Fabric& fabric) {
  const double a1 = fabric.threads[0].coverage, a2 = fabric.threads[1].coverage;
  width_ = std::min(a1 + a2, 1.0);
  warp_share_ = width_ > 0.0 ? a1 / (a1 + a2) : 0.5;
  rows_ = fabric.weave.rows > 0 ? fabric.weave.rows : default_rows(warp_share_);
  if (fabric.weave.rows > 0) shift_ = fabric.weave.shift;
  else shift_ = rows_ == 5 ? 2 : 1;
}

WeaveSample WeaveLayout::at(double s, double t) const {
  WeaveSample out;
  if (width_ <= 0.0) return out;
  const double tr = fraction(t) * rows_;
  const double row = std::min(std::floor(tr), double(rows_ - 1));
  const double tau = tr - row;  // 0..1 across the row, along t
  const double x = fraction(s - row * shift_ / rows_);
  if (x < warp_share_) {
    const double across = tau - 0.5;
    if (std::abs(across) >= 0.5 * width_) return out;
    out.thread = 0;
    out.arc = x / warp_share_;
    out.across = across / width_;
  } else {
    const double across = (x - warp_share_) / (1.0 - warp_share_) - 0.5;
    if (std::abs(across) >= 0.5 * width_) return out;
    out.thread = 1;
    out.arc = tau;
    out.across = across / width_;
  }
  return out;
}

double weave_tilt(const Fabric& fabric, const WeaveSample& w) {
  const TangentCurve& curve = fabric.threads.at(w.thread).curve;
  return curve.tilt_at(w.arc * curve.total_length());
}

glm::dvec2 weave_repeat_cm(const Fabric& fabric) {
  const WeaveLayout layout(fabric);
  return {layout.rows() / fabric.weave.picks_per_cm, layout.rows() / fabric.weave.ends_per_cm};
}

}  // namespace weft
