#pragma once
// The on-disk layout of a scene bundle (BUNDLE_FORMAT.md is the prose version of this file):
// byte offsets of every header and section-table field, element types, and little-endian
// field access. Shared by the writer, the reader and the fuzz target's checksum re-sealer.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace weft::bundle {

static_assert(std::endian::native == std::endian::little,
              "bundles are little-endian and hand out typed spans in place");

inline constexpr std::string_view kMagic = "WEFTBNDL";  // 8 bytes, no terminator on disk
inline constexpr std::uint32_t kFormatVersion = 1;
inline constexpr std::uint64_t kAlignment = 64;    // every section payload starts on this
inline constexpr std::uint32_t kHeaderSize = 64;
inline constexpr std::uint32_t kEntrySize = 96;    // one section-table entry
inline constexpr std::size_t kNameBytes = 32;      // NUL-padded name field
inline constexpr std::size_t kMaxNameLength = kNameBytes - 1;
inline constexpr std::uint32_t kMaxRank = 4;
inline constexpr std::uint32_t kMaxSections = 4096;

// Header, at offset 0.
namespace header_at {
inline constexpr std::size_t magic = 0;            // char[8] "WEFTBNDL"
inline constexpr std::size_t format_version = 8;   // u32
inline constexpr std::size_t header_size = 12;     // u32 = 64
inline constexpr std::size_t section_count = 16;   // u32
inline constexpr std::size_t entry_size = 20;      // u32 = 96
inline constexpr std::size_t table_offset = 24;    // u64 = 64
inline constexpr std::size_t total_size = 32;      // u64: the file's exact size
inline constexpr std::size_t table_crc = 40;       // u32: CRC-32C of the whole section table
inline constexpr std::size_t flags = 44;           // u32 = 0 (reserved)
inline constexpr std::size_t reserved = 48;        // 12 zero bytes
inline constexpr std::size_t header_crc = 60;      // u32: CRC-32C of header bytes [0, 60)
}  // namespace header_at

// One section-table entry, at table_offset + i * kEntrySize.
namespace entry_at {
inline constexpr std::size_t name = 0;             // char[32], NUL-padded, at least one NUL
inline constexpr std::size_t element_type = 32;    // u32 ElementType
inline constexpr std::size_t rank = 36;            // u32, 0..4 (0 = one scalar)
inline constexpr std::size_t shape = 40;           // u64[4], unused dimensions 0
inline constexpr std::size_t offset = 72;          // u64, multiple of 64
inline constexpr std::size_t size = 80;            // u64 payload bytes
inline constexpr std::size_t crc = 88;             // u32 CRC-32C of the payload
inline constexpr std::size_t reserved = 92;        // u32 = 0
}  // namespace entry_at

enum class ElementType : std::uint32_t {
  U8 = 1,
  U16 = 2,
  U32 = 3,
  I32 = 4,
  F32 = 5,
  F64 = 6,
  Json = 7,  // UTF-8 JSON text (rank 1, shape = byte count); parsed by its consumer
  F16 = 8,   // IEEE 754 binary16: large float tables where 11 significant bits are plenty
};

// Bytes per element, or 0 for a value that is not an ElementType.
constexpr std::size_t element_size(ElementType t) {
  switch (t) {
    case ElementType::U8: return 1;
    case ElementType::U16: return 2;
    case ElementType::U32: return 4;
    case ElementType::I32: return 4;
    case ElementType::F32: return 4;
    case ElementType::F64: return 8;
    case ElementType::Json: return 1;
    case ElementType::F16: return 2;
  }
  return 0;
}

constexpr std::string_view element_type_name(ElementType t) {
  switch (t) {
    case ElementType::U8: return "u8";
    case ElementType::U16: return "u16";
    case ElementType::U32: return "u32";
    case ElementType::I32: return "i32";
    case ElementType::F32: return "f32";
    case ElementType::F64: return "f64";
    case ElementType::Json: return "json";
    case ElementType::F16: return "f16";
  }
  return "invalid";
}

// The element type a C++ array type is stored as.
template <class T> struct element_type_of;
template <> struct element_type_of<std::uint8_t> { static constexpr ElementType value = ElementType::U8; };
template <> struct element_type_of<std::uint16_t> { static constexpr ElementType value = ElementType::U16; };
template <> struct element_type_of<std::uint32_t> { static constexpr ElementType value = ElementType::U32; };
template <> struct element_type_of<std::int32_t> { static constexpr ElementType value = ElementType::I32; };
template <> struct element_type_of<float> { static constexpr ElementType value = ElementType::F32; };
template <> struct element_type_of<double> { static constexpr ElementType value = ElementType::F64; };

// Section names: 1..31 characters of [A-Za-z0-9_.:/-], so they print cleanly in errors.
constexpr bool is_valid_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.' || c == ':' || c == '/' || c == '-';
}
constexpr bool is_valid_section_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameLength) return false;
  for (char c : name)
    if (!is_valid_name_char(c)) return false;
  return true;
}

constexpr std::uint64_t align_up(std::uint64_t x, std::uint64_t a) { return (x + a - 1) / a * a; }

// Little-endian field access (the host is little-endian, see the static_assert above, but the
// fields are read byte-wise so that unaligned header fields are never dereferenced).
inline std::uint32_t load_u32(const std::byte* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | std::uint32_t(p[i]);
  return v;
}
inline std::uint64_t load_u64(const std::byte* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | std::uint64_t(p[i]);
  return v;
}
inline void store_u32(std::byte* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = std::byte((v >> (8 * i)) & 0xFFu);
}
inline void store_u64(std::byte* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = std::byte((v >> (8 * i)) & 0xFFu);
}

}  // namespace weft::bundle
