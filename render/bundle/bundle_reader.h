#pragma once
// Opens a scene bundle by mmap, verifies everything before handing anything out (header,
// version, bounds, 64-byte alignment, canonical layout, zero padding, CRC-32C of the table and of
// every section), then gives typed spans straight into the mapping: nothing is parsed or copied.
// Any failure is a BundleError naming the header, the table or the section at fault.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bundle/bundle_error.h"
#include "bundle/bundle_format.h"

namespace weft::bundle {

struct SectionInfo {
  std::string name;
  ElementType type;
  std::vector<std::uint64_t> shape;  // rank entries; empty = one scalar
  std::uint64_t offset = 0;          // from the start of the file, multiple of 64
  std::uint64_t size = 0;            // bytes
  std::uint32_t crc = 0;             // CRC-32C of the payload
  std::uint64_t element_count() const;
};

class BundleReader {
public:
  // Maps and verifies a bundle file. The mapping lives as long as any copy of the reader.
  static BundleReader open(const std::filesystem::path& file);
  // Reads a bundle file into memory the reader owns, then verifies it. Unlike a mapping, the
  // copy is immune to the file being rewritten or truncated in place while it is in use (a
  // mapped page past a new end of file faults): the kiosk reads bundles this way.
  static BundleReader read(const std::filesystem::path& file);
  // Verifies a bundle already in memory, without copying: `bytes` must outlive the reader.
  // `origin` names it in errors.
  static BundleReader view(std::span<const std::byte> bytes, std::string origin);

  const std::string& origin() const { return origin_; }
  std::span<const std::byte> bytes() const { return bytes_; }
  std::uint32_t format_version() const { return kFormatVersion; }
  const std::vector<SectionInfo>& sections() const { return sections_; }
  bool has(std::string_view name) const { return find(name) != nullptr; }
  // The named section's description; BundleError (naming it) when absent.
  const SectionInfo& section(std::string_view name) const;

  // Typed view of an array section; BundleError when absent or of another element type.
  template <class T>
  std::span<const T> array(std::string_view name) const {
    const SectionInfo& s = expect_type(name, element_type_of<T>::value, alignof(T));
    return {reinterpret_cast<const T*>(bytes_.data() + s.offset), s.element_count()};
  }
  // The text of a Json section (not parsed here: its consumer reads it into its own struct).
  std::string_view json(std::string_view name) const;
  // The payload bytes of any section.
  std::span<const std::byte> raw(std::string_view name) const;

private:
  BundleReader() = default;
  const SectionInfo* find(std::string_view name) const;
  const SectionInfo& expect_type(std::string_view name, ElementType type, std::size_t align) const;
  BundleError error(std::string_view section, const std::string& detail) const;

  std::shared_ptr<const void> keep_alive_;  // the mapping, when the reader owns one
  std::span<const std::byte> bytes_;
  std::string origin_;
  std::vector<SectionInfo> sections_;
};

}  // namespace weft::bundle
