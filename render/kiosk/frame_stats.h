#pragma once
// The numbers the kiosk's stats lines report: recent timing samples (ms per frame,
// report→photon) and the process's resident memory.
#include <cstddef>
#include <vector>

namespace weft {

// The most recent samples only (between 4096 and 8192 of them): the kiosk runs for months.
class RecentSamples {
public:
  void push(double x);
  void clear() { values_.clear(); }
  size_t size() const { return values_.size(); }
  bool empty() const { return values_.empty(); }
  // The median of the samples kept, leaving out the oldest `skip`; 0 when none are left.
  double median(size_t skip = 0) const;
  double max() const;  // 0 when empty
  double last() const { return values_.empty() ? 0.0 : values_.back(); }  // the newest; 0 when empty

private:
  std::vector<double> values_;
};

// VmRSS of this process in KiB (/proc/self/status); 0 when unreadable.
long resident_set_kib();

}  // namespace weft
