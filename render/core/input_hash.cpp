#include "core/input_hash.h"

#include <cstdio>

namespace weft {

void InputHash::mix(const void* p, std::size_t n) {
  const auto* b = static_cast<const unsigned char*>(p);
  for (std::size_t i = 0; i < n; ++i) {
    h_ ^= b[i];
    h_ *= 0x100000001b3ull;  // the FNV-1a 64 prime (1099511628211)
  }
}

InputHash& InputHash::add(std::string_view bytes) {
  const std::uint64_t n = bytes.size();
  mix(&n, sizeof n);
  mix(bytes.data(), bytes.size());
  return *this;
}

InputHash& InputHash::add_number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return add(buf);
}

InputHash& InputHash::add_integer(std::uint64_t x) {
  return add(std::string_view(reinterpret_cast<const char*>(&x), sizeof x));
}

std::string InputHash::hex() const {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
  return buf;
}

}  // namespace weft
