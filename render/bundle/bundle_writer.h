#pragma once
// Builds a scene bundle from named, typed sections (arrays with shapes, JSON metadata) and writes
// it in the layout of BUNDLE_FORMAT.md. Sections are copied in, so the caller's buffers may go
// away; they are stored in the order they were added.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bundle/bundle_format.h"

namespace weft::bundle {

class BundleWriter {
public:
  // An array section. `shape` (at most 4 extents, row-major, last fastest) must multiply to
  // values.size(); an empty shape means one scalar. Throws std::invalid_argument on a bad name
  // (1..31 of [A-Za-z0-9_.:/-]), a duplicate name or a shape that does not fit.
  template <class T>
  void add_array(std::string_view name, std::span<const T> values, std::vector<std::uint64_t> shape) {
    add_raw(name, element_type_of<T>::value, std::move(shape), std::as_bytes(values));
  }
  // A one-dimensional array section.
  template <class T>
  void add_array(std::string_view name, std::span<const T> values) {
    add_array(name, values, {values.size()});
  }
  // A small JSON text section (fabric parameters, camera, settings). Not validated here:
  // the consumer parses it into its own struct, which is what makes it editable at runtime.
  void add_json(std::string_view name, std::string_view json_text);
  // Any section from its payload bytes; the checks of add_array apply.
  void add_raw(std::string_view name, ElementType type, std::vector<std::uint64_t> shape,
               std::span<const std::byte> payload);

  std::size_t section_count() const { return sections_.size(); }
  // The complete bundle file.
  std::vector<std::byte> to_bytes() const;
  // Writes the bundle atomically (temp file, fsync, rename, fsync of the directory).
  void write_file(const std::filesystem::path& file) const;

private:
  struct Section {
    std::string name;
    ElementType type;
    std::vector<std::uint64_t> shape;
    std::vector<std::byte> payload;
  };
  std::vector<Section> sections_;
};

}  // namespace weft::bundle
