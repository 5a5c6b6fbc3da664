#pragma once
// Test-only: recomputes the header, table and section checksums of a (possibly malformed) bundle
// image in place, so that tests and the fuzz target reach the structural checks that lie behind
// the checksums. Reads only what is inside `file`; anything out of range is left alone.
#include <cstddef>
#include <span>

#include "bundle/bundle_format.h"
#include "bundle/crc32c.h"

namespace weft::bundle::testing {

inline void reseal(std::span<std::byte> file) {
  if (file.size() < kHeaderSize) return;
  const std::uint64_t count = load_u32(file.data() + header_at::section_count);
  const std::uint64_t table_end = kHeaderSize + count * kEntrySize;
  if (count <= kMaxSections && table_end <= file.size()) {
    for (std::uint64_t i = 0; i < count; ++i) {
      std::byte* e = file.data() + kHeaderSize + i * kEntrySize;
      const std::uint64_t offset = load_u64(e + entry_at::offset);
      const std::uint64_t size = load_u64(e + entry_at::size);
      if (offset <= file.size() && size <= file.size() - offset)
        store_u32(e + entry_at::crc, crc32c(file.subspan(offset, size)));
    }
    store_u32(file.data() + header_at::table_crc, crc32c(file.subspan(kHeaderSize, table_end - kHeaderSize)));
  }
  store_u32(file.data() + header_at::header_crc, crc32c(file.first(header_at::header_crc)));
}

}  // namespace weft::bundle::testing
