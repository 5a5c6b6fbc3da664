#pragma once
// A fingerprint of a sequence of inputs: FNV-1a 64 over byte strings, each length-prefixed so
// that boundaries count. Keys cached renders (bench/reference_cache.h, bake/selection_views.h)
// and tells a bundle's content apart from another's (kiosk/kiosk_bundle.h). Not cryptographic.
#include <cstdint>
#include <string>
#include <string_view>

namespace weft {

class InputHash {
public:
  InputHash& add(std::string_view bytes);
  InputHash& add_number(double x);         // as its shortest exact decimal text ("%.17g")
  InputHash& add_integer(std::uint64_t x);  // its 8 bytes
  std::uint64_t value() const { return h_; }
  std::string hex() const;  // 16 lowercase hex digits

private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;  // the FNV-1a 64 offset basis (14695981039346656037)
  void mix(const void* p, std::size_t n);
};

}  // namespace weft
