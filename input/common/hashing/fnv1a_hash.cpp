#include "hashing/fnv1a_hash.h"

#include <cstdio>

namespace weft {

std::uint64_t fnv1a64(const void* bytes, std::size_t n, std::uint64_t h) {
  const auto* b = static_cast<const unsigned char*>(bytes);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= b[i];
    h *= kFnv1a64Prime;
  }
  return h;
}

std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

InputHash& InputHash::add(std::string_view bytes) {
  const std::uint64_t n = bytes.size();
  h_ = fnv1a64(&n, sizeof n, h_);
  h_ = fnv1a64(bytes.data(), bytes.size(), h_);
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

}  // namespace weft
