// libFuzzer target for the bundle loader: any input must either verify or raise a
// BundleError; nothing may crash, read out of bounds (ASan) or hand out a span that breaks the
// format's invariants. Each input is tried as is, and again with its checksums recomputed so the
// mutations reach the structural checks that lie behind the CRCs.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "bundle/bundle_reader.h"
#include "support/bundle_reseal.h"

namespace {

using weft::bundle::BundleError;
using weft::bundle::BundleReader;
using weft::bundle::ElementType;

template <class T>
void check_array(const BundleReader& r, const weft::bundle::SectionInfo& s) {
  const std::span<const T> a = r.array<T>(s.name);
  if (a.size() * sizeof(T) != s.size) __builtin_trap();
}

void exercise(std::span<const std::byte> input) {
  try {
    const BundleReader r = BundleReader::view(input, "fuzz input");
    unsigned sum = 0;
    for (const auto& s : r.sections()) {
      if (s.offset % weft::bundle::kAlignment != 0 || s.offset > input.size() ||
          s.size > input.size() - s.offset)
        __builtin_trap();
      for (std::byte b : r.raw(s.name)) sum += unsigned(b);  // every handed-out byte, under ASan
      try {
        switch (s.type) {
          case ElementType::U8: check_array<std::uint8_t>(r, s); break;
          case ElementType::U16: check_array<std::uint16_t>(r, s); break;
          case ElementType::U32: check_array<std::uint32_t>(r, s); break;
          case ElementType::I32: check_array<std::int32_t>(r, s); break;
          case ElementType::F32: check_array<float>(r, s); break;
          case ElementType::F64: check_array<double>(r, s); break;
          case ElementType::F16:  // no C++ type: its consumers decode the raw bytes
            if (r.raw(s.name).size() != s.size) __builtin_trap();
            break;
          case ElementType::Json:
            if (r.json(s.name).size() != s.size) __builtin_trap();
            break;
        }
      } catch (const BundleError&) {
        // Only an input buffer that is not aligned for the type may refuse a typed view.
      }
    }
    static volatile unsigned sink;
    sink = sum;
    (void)sink;
  } catch (const BundleError&) {
    // The expected outcome for almost every input.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exercise(std::as_bytes(std::span(data, size)));
  if (size >= weft::bundle::kHeaderSize) {
    std::vector<std::byte> resealed(size);
    std::memcpy(resealed.data(), data, size);
    weft::bundle::testing::reseal(resealed);
    exercise(resealed);
  }
  return 0;
}
