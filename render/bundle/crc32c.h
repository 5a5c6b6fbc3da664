#pragma once
// CRC-32C (Castagnoli, reflected polynomial 0x82F63B78), the per-section checksum of a bundle.
// Own implementation rather than zlib: zlib's crc32 is the IEEE polynomial, and weft_bundle
// depends on nothing but the standard library so the fuzz build needs no other library.
#include <cstddef>
#include <cstdint>
#include <span>

namespace weft::bundle {

// Continues a CRC over more bytes; start with crc = 0. crc32c("123456789") == 0xE3069283.
std::uint32_t crc32c_extend(std::uint32_t crc, const void* data, std::size_t size);

inline std::uint32_t crc32c(std::span<const std::byte> bytes) {
  return crc32c_extend(0, bytes.data(), bytes.size());
}

}  // namespace weft::bundle
