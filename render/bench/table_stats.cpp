#include "bench/table_stats.h"

#include "runtime/weighting_tables.h"
#include "bench/number_text.h"

namespace weft::bench {

size_t table_bytes(const ShadingData& d) {
  size_t b = 0;
  for (const auto& [name, t] : d.tables) b += t.bytes();
  return b;
}

size_t visibility_bytes(const ShadingData& d) {
  size_t b = 0;
  for (const auto& [i, v] : d.visibility) b += sizeof(float) * (v.mean.size() + v.basis.size() + v.coefficients.size());
  return b;
}

size_t mask_bytes(const ShadingData& d) {
  size_t b = 0;
  for (const auto& [i, m] : d.masks) b += sizeof(m.words[0]) * m.words.size();
  return b;
}

std::string tables_summary(const ShadingData& d) {
  std::string s;
  for (const auto& [name, t] : d.tables) {
    const TableSummary m = summarize(t);
    s += (s.empty() ? "" : "; ") + name + ": " + std::to_string(t.tangent_samples[0]) + "+" +
         std::to_string(t.tangent_samples[1]) + " samples, " + std::to_string(t.level_count()) + " levels, rank " +
         fmt(m.mean_rank, 3) + " (mean), " + fmt(t.bytes() / 1e6, 3) + " MB";
  }
  return s;
}

}  // namespace weft::bench
