#include "bundle/bundle_writer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "files/atomic_file.h"
#include "bundle/crc32c.h"

namespace weft::bundle {

void BundleWriter::add_json(std::string_view name, std::string_view json_text) {
  add_raw(name, ElementType::Json, {json_text.size()}, std::as_bytes(std::span(json_text)));
}

void BundleWriter::add_raw(std::string_view name, ElementType type, std::vector<std::uint64_t> shape,
                           std::span<const std::byte> payload) {
  const std::string where = "bundle section '" + std::string(name) + "': ";
  if (!is_valid_section_name(name))
    throw std::invalid_argument(where + "name must be 1.." + std::to_string(kMaxNameLength) +
                                " characters of [A-Za-z0-9_.:/-]");
  for (const Section& s : sections_)
    if (s.name == name) throw std::invalid_argument(where + "added twice");
  if (element_size(type) == 0) throw std::invalid_argument(where + "unknown element type");
  if (shape.size() > kMaxRank)
    throw std::invalid_argument(where + "rank " + std::to_string(shape.size()) + " exceeds " +
                                std::to_string(kMaxRank));
  if (type == ElementType::Json && shape.size() != 1)
    throw std::invalid_argument(where + "a json section has rank 1");
  std::uint64_t elements = 1, bytes = 0;
  bool overflow = false;
  for (std::uint64_t e : shape) overflow |= __builtin_mul_overflow(elements, e, &elements);
  overflow |= __builtin_mul_overflow(elements, element_size(type), &bytes);
  if (overflow || bytes != payload.size())
    throw std::invalid_argument(where + "shape holds " + std::to_string(elements) + " elements, the data " +
                                std::to_string(payload.size() / element_size(type)));
  sections_.push_back({std::string(name), type, std::move(shape),
                       std::vector<std::byte>(payload.begin(), payload.end())});
}

std::vector<std::byte> BundleWriter::to_bytes() const {
  const std::uint32_t count = static_cast<std::uint32_t>(sections_.size());
  if (count > kMaxSections)
    throw std::invalid_argument("bundle: more than " + std::to_string(kMaxSections) + " sections");
  const std::uint64_t table_end = kHeaderSize + std::uint64_t(count) * kEntrySize;
  std::vector<std::uint64_t> offsets;
  std::uint64_t end = table_end;
  for (const Section& s : sections_) {
    offsets.push_back(align_up(end, kAlignment));
    end = offsets.back() + s.payload.size();
  }

  std::vector<std::byte> file(end, std::byte{0});  // zero padding everywhere
  for (std::uint32_t i = 0; i < count; ++i) {
    const Section& s = sections_[i];
    std::byte* e = file.data() + kHeaderSize + std::uint64_t(i) * kEntrySize;
    std::memcpy(e + entry_at::name, s.name.data(), s.name.size());
    store_u32(e + entry_at::element_type, static_cast<std::uint32_t>(s.type));
    store_u32(e + entry_at::rank, static_cast<std::uint32_t>(s.shape.size()));
    for (std::size_t d = 0; d < s.shape.size(); ++d) store_u64(e + entry_at::shape + 8 * d, s.shape[d]);
    store_u64(e + entry_at::offset, offsets[i]);
    store_u64(e + entry_at::size, s.payload.size());
    store_u32(e + entry_at::crc, crc32c(s.payload));
    if (!s.payload.empty()) std::memcpy(file.data() + offsets[i], s.payload.data(), s.payload.size());
  }

  std::byte* h = file.data();
  std::memcpy(h + header_at::magic, kMagic.data(), kMagic.size());
  store_u32(h + header_at::format_version, kFormatVersion);
  store_u32(h + header_at::header_size, kHeaderSize);
  store_u32(h + header_at::section_count, count);
  store_u32(h + header_at::entry_size, kEntrySize);
  store_u64(h + header_at::table_offset, kHeaderSize);
  store_u64(h + header_at::total_size, end);
  store_u32(h + header_at::table_crc, crc32c(std::span(file).subspan(kHeaderSize, table_end - kHeaderSize)));
  store_u32(h + header_at::header_crc, crc32c(std::span(file).first(header_at::header_crc)));
  return file;
}

void BundleWriter::write_file(const std::filesystem::path& file) const {
  write_file_atomically(file, to_bytes());
}

}  // namespace weft::bundle
