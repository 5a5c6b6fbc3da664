#pragma once
// Which terms the weave layer takes up close over a per-vertex rung
// (gpu::SceneRenderer::set_weave_pixel_terms), by what this GPU affords: each float's lighting per
// pixel (within 8 % of the resolved reference where a repeat spans 16 px or more) while the frames
// that draw the layer stay within the budget, else the per-vertex table (no light per pixel, a
// fraction of the cost, far coarser up close). Judged on the median of the last kJudged frames
// that drew the layer, so a frame's hiccup (a zoom step recomputing every kept value) does not
// decide it (of the first kEarly already where it is kEarlyFactor times the budget); once the
// table is taken it stays for the run: the GPU does not get faster.
#include <optional>
#include <string>
#include <vector>

namespace weft {

class WeaveTermsGovernor {
public:
  enum class Mode { automatic, pixel, table };
  static constexpr int kJudged = 8, kEarly = 3;
  static constexpr double kEarlyFactor = 4.0;
  // "auto", "pixel" or "table"; nullopt for anything else.
  static std::optional<Mode> parse(const std::string& name);
  WeaveTermsGovernor(Mode mode, double budget_ms);
  bool pixel_terms() const { return pixel_; }
  // One frame drawn with pixel_terms() as they were: its time, and whether it drew the layer
  // (gpu::SceneRenderer::weave_drawn). Returns a line for the journal when the terms change.
  std::optional<std::string> frame(double ms, bool weave_drawn);

private:
  Mode mode_;
  double budget_ms_;
  bool pixel_;
  std::vector<double> recent_;  // the last kJudged layer frames, oldest first
};

}  // namespace weft
