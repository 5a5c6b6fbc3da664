#include "kiosk/weave_terms_governor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace weft {

std::optional<WeaveTermsGovernor::Mode> WeaveTermsGovernor::parse(const std::string& name) {
  if (name == "auto") return Mode::automatic;
  if (name == "pixel") return Mode::pixel;
  if (name == "table") return Mode::table;
  return std::nullopt;
}

WeaveTermsGovernor::WeaveTermsGovernor(Mode mode, double budget_ms)
    : mode_(mode), budget_ms_(budget_ms), pixel_(mode != Mode::table) {}

std::optional<std::string> WeaveTermsGovernor::frame(double ms, bool weave_drawn) {
  if (mode_ != Mode::automatic || !pixel_ || !weave_drawn || !std::isfinite(ms)) return std::nullopt;
  recent_.push_back(ms);
  if (recent_.size() > size_t(kJudged)) recent_.erase(recent_.begin());
  // The lower median (more than half of the frames over): of kJudged frames against the budget,
  // or already of kEarly against kEarlyFactor times it, so a GPU far too slow is not a slide show
  // for kJudged frames first.
  std::vector<double> sorted = recent_;
  std::nth_element(sorted.begin(), sorted.begin() + (sorted.size() - 1) / 2, sorted.end());
  const double median = sorted[(sorted.size() - 1) / 2];
  const bool full = recent_.size() == size_t(kJudged);
  if (!(full ? median > budget_ms_ : recent_.size() >= size_t(kEarly) && median > kEarlyFactor * budget_ms_)) return std::nullopt;
  pixel_ = false;
  char line[256];
  std::snprintf(line, sizeof line,
                "weave: frames with the threads shown take %.0f ms (median of %d) with each float lit per pixel, over "
                "the %.0f ms budget: the per-vertex table from now on (coarser up close; --weave-terms pixel keeps "
                "the per-pixel lighting)",
                median, int(recent_.size()), budget_ms_);
  return std::string(line);
}

}  // namespace weft
