#pragma once
// What an in-memory iwasaki bundle holds, as the bench reports it: bytes of the weighting
// tables and of the visibility PCA as stored in a bundle, and a one-line summary per fabric.
#include <cstddef>
#include <string>

#include "runtime/shading_data.h"

namespace weft::bench {

size_t table_bytes(const ShadingData& d);
size_t visibility_bytes(const ShadingData& d);
// The per-vertex visibility masks (only the mask methods read them).
size_t mask_bytes(const ShadingData& d);
// "linen_plain: 3+3 samples, 9 levels, rank 7.1 (mean), 0.42 MB" per fabric, joined by "; ".
std::string tables_summary(const ShadingData& d);

}  // namespace weft::bench
