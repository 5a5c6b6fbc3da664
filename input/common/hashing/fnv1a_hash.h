#pragma once
// FNV-1a 64, the one fingerprint of the product (not cryptographic):
//   fnv1a64_hex    of a byte string: the knob state file's checksum (panel/knob_state_file.h);
//   InputHash      of a sequence of inputs, each length-prefixed so that boundaries count: keys
//                  cached renders (measure/reference_cache.h, measure/selection_views.h) and tells
//                  a bundle's content apart from another's (kiosk/kiosk_bundle.h).
// The two differ (the length prefixes), so each keeps the values it has always had.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace weft {

inline constexpr std::uint64_t kFnv1a64OffsetBasis = 0xcbf29ce484222325ull;  // 14695981039346656037
inline constexpr std::uint64_t kFnv1a64Prime = 0x100000001b3ull;             // 1099511628211

// `h` with the bytes mixed in, one at a time.
std::uint64_t fnv1a64(const void* bytes, std::size_t n, std::uint64_t h = kFnv1a64OffsetBasis);
std::string hex64(std::uint64_t v);  // 16 lowercase hex digits
inline std::string fnv1a64_hex(std::string_view bytes) { return hex64(fnv1a64(bytes.data(), bytes.size())); }

class InputHash {
public:
  InputHash& add(std::string_view bytes);
  InputHash& add_number(double x);          // as its shortest exact decimal text ("%.17g")
  InputHash& add_integer(std::uint64_t x);  // its 8 bytes
  std::uint64_t value() const { return h_; }
  std::string hex() const { return hex64(h_); }

private:
  std::uint64_t h_ = kFnv1a64OffsetBasis;
};

}  // namespace weft
