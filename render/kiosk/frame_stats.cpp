#include "kiosk/frame_stats.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace weft {

void RecentSamples::push(double x) {
  constexpr size_t kKeep = 4096;
  if (values_.size() >= 2 * kKeep) values_.erase(values_.begin(), values_.end() - kKeep);
  values_.push_back(x);
}

double RecentSamples::median(size_t skip) const {
  std::vector<double> v(values_.begin() + std::min(skip, values_.size()), values_.end());
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

double RecentSamples::max() const { return values_.empty() ? 0.0 : *std::max_element(values_.begin(), values_.end()); }

long resident_set_kib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::atol(line.c_str() + 6);
  return 0;
}

}  // namespace weft
