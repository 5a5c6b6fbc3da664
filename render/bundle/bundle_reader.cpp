#include "bundle/bundle_reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>

#include "bundle/crc32c.h"

namespace weft::bundle {
namespace {

std::string hex32(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

std::string section_part(std::string_view name) { return "section '" + std::string(name) + "'"; }

bool all_zero(const std::byte* p, std::uint64_t n) {
  for (std::uint64_t i = 0; i < n; ++i)
    if (p[i] != std::byte{0}) return false;
  return true;
}

// Checked a*b; false on overflow.
bool multiply(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return false;
  out = a * b;
  return true;
}

// Everything is checked before anything is handed out; each check reads only bytes that an
// earlier check proved to be inside the file.
class Verifier {
public:
  Verifier(std::span<const std::byte> file, const std::string& origin) : f_(file), origin_(origin) {}

  std::vector<SectionInfo> run() {
    check_header();
    check_table_bounds_and_crc();
    std::vector<SectionInfo> sections = parse_entries();
    check_file_size(sections);
    check_padding(sections);
    check_payload_crcs(sections);
    return sections;
  }

private:
  [[noreturn]] void fail(const std::string& part, const std::string& section,
                         const std::string& detail) const {
    throw BundleError(origin_, part, section, detail);
  }
  [[noreturn]] void fail_header(const std::string& d) const { fail("header", "", d); }
  [[noreturn]] void fail_table(const std::string& d) const { fail("section table", "", d); }
  [[noreturn]] void fail_section(const std::string& name, const std::string& d) const {
    fail(section_part(name), name, d);
  }
  [[noreturn]] void fail_entry(std::uint32_t i, const std::string& d) const {
    fail_table("entry " + std::to_string(i) + ": " + d);
  }

  const std::byte* at(std::uint64_t offset) const { return f_.data() + offset; }

  void check_header() {
    const std::size_t n = f_.size();
    const std::size_t prefix = std::min<std::size_t>(n, kMagic.size());
    if (prefix > 0 && std::memcmp(f_.data(), kMagic.data(), prefix) != 0)
      fail_header("not a Weft bundle (the file does not start with \"WEFTBNDL\")");
    if (n < kHeaderSize)
      fail_header("truncated: the file is " + std::to_string(n) + " bytes, the header alone is " +
                  std::to_string(kHeaderSize));
    // The version comes before the checksum so that a bundle from another release says so,
    // even if that release laid the header out differently.
    const std::uint32_t version = load_u32(at(header_at::format_version));
    if (version != kFormatVersion)
      fail_header("format version " + std::to_string(version) + ", this build reads version " +
                  std::to_string(kFormatVersion) + " (re-bake the scene with this weft)");
    const std::uint32_t stored = load_u32(at(header_at::header_crc));
    const std::uint32_t computed = crc32c_extend(0, f_.data(), header_at::header_crc);
    if (stored != computed)
      fail_header("checksum mismatch (stored " + hex32(stored) + ", computed " + hex32(computed) +
                  "): the header is corrupt");
    if (load_u32(at(header_at::header_size)) != kHeaderSize ||
        load_u32(at(header_at::entry_size)) != kEntrySize ||
        load_u64(at(header_at::table_offset)) != kHeaderSize ||
        load_u32(at(header_at::flags)) != 0 || !all_zero(at(header_at::reserved), 12))
      fail_header("header size, entry size, table offset or reserved fields differ from version " +
                  std::to_string(kFormatVersion) + "'s fixed values");
    count_ = load_u32(at(header_at::section_count));
    total_ = load_u64(at(header_at::total_size));
    if (count_ > kMaxSections)
      fail_header(std::to_string(count_) + " sections, more than the limit of " +
                  std::to_string(kMaxSections));
  }

  void check_table_bounds_and_crc() {
    table_end_ = kHeaderSize + std::uint64_t(count_) * kEntrySize;
    if (f_.size() < table_end_)
      fail_table("truncated: the file ends at byte " + std::to_string(f_.size()) +
                 ", the table of " + std::to_string(count_) + " sections needs bytes [64, " +
                 std::to_string(table_end_) + ")");
    const std::uint32_t stored = load_u32(at(header_at::table_crc));
    const std::uint32_t computed = crc32c_extend(0, at(kHeaderSize), table_end_ - kHeaderSize);
    if (stored != computed)
      fail_table("checksum mismatch (stored " + hex32(stored) + ", computed " + hex32(computed) +
                 "): the table is corrupt");
  }

  std::vector<SectionInfo> parse_entries() {
    std::vector<SectionInfo> sections;
    sections.reserve(count_);
    std::uint64_t end = table_end_;  // end of the previous payload
    for (std::uint32_t i = 0; i < count_; ++i) {
      const std::byte* e = at(kHeaderSize + std::uint64_t(i) * kEntrySize);
      SectionInfo s;
      s.name = read_name(i, e);
      for (const SectionInfo& other : sections)
        if (other.name == s.name) fail_section(s.name, "appears twice in the section table");

      const std::uint32_t type = load_u32(e + entry_at::element_type);
      s.type = ElementType(type);
      if (element_size(s.type) == 0)
        fail_section(s.name, "unknown element type " + std::to_string(type));
      const std::uint32_t rank = load_u32(e + entry_at::rank);
      if (rank > kMaxRank)
        fail_section(s.name, "rank " + std::to_string(rank) + " exceeds " + std::to_string(kMaxRank));
      if (s.type == ElementType::Json && rank != 1)
        fail_section(s.name, "a json section must have rank 1");
      std::uint64_t elements = 1;
      for (std::uint32_t d = 0; d < kMaxRank; ++d) {
        const std::uint64_t extent = load_u64(e + entry_at::shape + 8 * d);
        if (d >= rank) {
          if (extent != 0) fail_section(s.name, "shape has a non-zero extent beyond its rank");
          continue;
        }
        s.shape.push_back(extent);
        if (!multiply(elements, extent, elements))
          fail_section(s.name, "shape overflows 64 bits");
      }
      std::uint64_t bytes = 0;
      if (!multiply(elements, element_size(s.type), bytes))
        fail_section(s.name, "byte size overflows 64 bits");
      s.offset = load_u64(e + entry_at::offset);
      s.size = load_u64(e + entry_at::size);
      s.crc = load_u32(e + entry_at::crc);
      if (s.size != bytes)
        fail_section(s.name, "size " + std::to_string(s.size) + " bytes does not match its shape (" +
                                 std::to_string(bytes) + " bytes of " +
                                 std::string(element_type_name(s.type)) + ")");
      if (load_u32(e + entry_at::reserved) != 0) fail_section(s.name, "reserved field is not zero");
      const std::uint64_t expected = align_up(end, kAlignment);
      if (s.offset != expected)
        fail_section(s.name, "offset " + std::to_string(s.offset) + ", expected " +
                                 std::to_string(expected) +
                                 " (payloads follow the table in order, each 64-byte aligned)");
      if (s.offset > total_ || s.size > total_ - s.offset)
        fail_section(s.name, "bytes [" + std::to_string(s.offset) + ", " +
                                 std::to_string(s.offset + s.size) +
                                 ") lie beyond the bundle's end at " + std::to_string(total_));
      end = s.offset + s.size;
      sections.push_back(std::move(s));
    }
    if (end != total_)
      fail_header("total size " + std::to_string(total_) + " bytes, but the sections end at " +
                  std::to_string(end));
    return sections;
  }

  std::string read_name(std::uint32_t i, const std::byte* e) const {
    const char* name = reinterpret_cast<const char*>(e + entry_at::name);
    const std::size_t len = ::strnlen(name, kNameBytes);
    if (len == kNameBytes) fail_entry(i, "name is not NUL-terminated");
    const std::string_view sv(name, len);
    if (!is_valid_section_name(sv)) fail_entry(i, "name is empty or has characters outside [A-Za-z0-9_.:/-]");
    if (!all_zero(e + entry_at::name + len, kNameBytes - len))
      fail_entry(i, "name '" + std::string(sv) + "' is followed by non-zero bytes");
    return std::string(sv);
  }

  void check_file_size(const std::vector<SectionInfo>& sections) const {
    const std::uint64_t n = f_.size();
    if (n < total_) {
      for (const SectionInfo& s : sections)
        if (s.offset + s.size > n)
          fail_section(s.name, "truncated: the file ends at byte " + std::to_string(n) +
                                   ", the section needs bytes [" + std::to_string(s.offset) + ", " +
                                   std::to_string(s.offset + s.size) + ")");
      fail("file", "", "truncated: " + std::to_string(n) + " of " + std::to_string(total_) + " bytes");
    }
    if (n > total_)
      fail("file", "", std::to_string(n - total_) + " unexpected bytes after the last section (file " +
                           std::to_string(n) + " bytes, header says " + std::to_string(total_) + ")");
  }

  // Padding is part of the file, so it must be zero: then every byte is covered by a check.
  void check_padding(const std::vector<SectionInfo>& sections) const {
    std::uint64_t end = table_end_;
    for (std::size_t i = 0; i < sections.size(); ++i) {
      if (!all_zero(at(end), sections[i].offset - end)) {
        if (i == 0) fail_table("the padding after the table is not zero");
        fail_section(sections[i - 1].name, "the padding after it is not zero");
      }
      end = sections[i].offset + sections[i].size;
    }
  }

  void check_payload_crcs(const std::vector<SectionInfo>& sections) const {
    for (const SectionInfo& s : sections) {
      const std::uint32_t computed = crc32c_extend(0, at(s.offset), s.size);
      if (computed != s.crc)
        fail_section(s.name, "checksum mismatch (stored " + hex32(s.crc) + ", computed " +
                                 hex32(computed) + "): the section is corrupt");
    }
  }

  std::span<const std::byte> f_;
  const std::string& origin_;
  std::uint32_t count_ = 0;
  std::uint64_t total_ = 0;
  std::uint64_t table_end_ = 0;
};

// Unmaps on destruction of the last reader sharing it.
struct Mapping {
  void* address = nullptr;
  std::size_t length = 0;
  ~Mapping() {
    if (address != nullptr) ::munmap(address, length);
  }
};

// A file's bytes in memory, 64-byte aligned like a mapping's sections.
struct OwnedBytes {
  std::byte* data = nullptr;
  std::size_t capacity = 0, length = 0;
  explicit OwnedBytes(std::size_t n)
      : data(static_cast<std::byte*>(::operator new(std::max<std::size_t>(n, 64), std::align_val_t{64}))),
        capacity(std::max<std::size_t>(n, 64)) {}
  ~OwnedBytes() { ::operator delete(data, std::align_val_t{64}); }
  OwnedBytes(const OwnedBytes&) = delete;
  OwnedBytes& operator=(const OwnedBytes&) = delete;
  void grow() {
    OwnedBytes bigger(capacity * 2);
    std::memcpy(bigger.data, data, length);
    std::swap(data, bigger.data);
    std::swap(capacity, bigger.capacity);
  }
};

// A regular file opened for reading, with its size at opening; closed when it goes.
struct RegularFile {
  std::string origin;
  int fd = -1;
  std::size_t size = 0;

  explicit RegularFile(const std::filesystem::path& file) : origin(file.string()) {
    fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw os_error("cannot open");
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw closing(os_error("cannot stat"));
    if (!S_ISREG(st.st_mode)) throw closing(BundleError(origin, "file", "", "not a regular file"));
    size = std::size_t(st.st_size);
  }
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;
  ~RegularFile() {
    if (fd >= 0) ::close(fd);
  }

  BundleError os_error(const std::string& what) const {
    return BundleError(origin, "file", "", what + ": " + std::strerror(errno));
  }

 private:
  // A constructor that throws runs no destructor: close here.
  BundleError closing(BundleError e) {
    ::close(fd);
    fd = -1;
    return e;
  }
};

}  // namespace

std::uint64_t SectionInfo::element_count() const {
  std::uint64_t n = 1;
  for (std::uint64_t e : shape) n *= e;  // cannot overflow: verified when the bundle was opened
  return n;
}

BundleReader BundleReader::view(std::span<const std::byte> bytes, std::string origin) {
  BundleReader r;
  r.origin_ = std::move(origin);
  r.sections_ = Verifier(bytes, r.origin_).run();
  r.bytes_ = bytes;
  return r;
}

BundleReader BundleReader::open(const std::filesystem::path& file) {
  const RegularFile f(file);
  auto mapping = std::make_shared<Mapping>();
  mapping->length = f.size;
  if (mapping->length > 0) {
    void* p = ::mmap(nullptr, mapping->length, PROT_READ, MAP_PRIVATE, f.fd, 0);
    if (p == MAP_FAILED) throw f.os_error("cannot mmap");
    mapping->address = p;
  }
  // Closing the file leaves the mapping, which keeps its contents reachable.
  const std::span<const std::byte> bytes(static_cast<const std::byte*>(mapping->address),
                                         mapping->length);
  BundleReader r = view(bytes, f.origin);
  r.keep_alive_ = std::move(mapping);
  return r;
}

const SectionInfo* BundleReader::find(std::string_view name) const {
  for (const SectionInfo& s : sections_)
    if (s.name == name) return &s;
  return nullptr;
}

BundleError BundleReader::error(std::string_view section, const std::string& detail) const {
  return BundleError(origin_, section_part(section), std::string(section), detail);
}

const SectionInfo& BundleReader::section(std::string_view name) const {
  if (const SectionInfo* s = find(name)) return *s;
  throw error(name, "missing from the bundle");
}

const SectionInfo& BundleReader::expect_type(std::string_view name, ElementType type,
                                             std::size_t align) const {
  const SectionInfo& s = section(name);
  if (s.type != type)
    throw error(name, "holds " + std::string(element_type_name(s.type)) + ", read as " +
                          std::string(element_type_name(type)));
  if (reinterpret_cast<std::uintptr_t>(bytes_.data() + s.offset) % align != 0)
    throw error(name, "payload is not aligned in memory for its element type");
  return s;
}

std::string_view BundleReader::json(std::string_view name) const {
  const SectionInfo& s = expect_type(name, ElementType::Json, 1);
  return {reinterpret_cast<const char*>(bytes_.data() + s.offset), s.size};
}

std::span<const std::byte> BundleReader::raw(std::string_view name) const {
  const SectionInfo& s = section(name);
  return bytes_.subspan(s.offset, s.size);
}

BundleReader BundleReader::read(const std::filesystem::path& file) {
  const RegularFile f(file);
  // Up to the end of file as it is while reading: a file that shrinks or grows meanwhile reads
  // as what was there, and the verifier judges that.
  auto owned = std::make_shared<OwnedBytes>(f.size + 1);
  for (;;) {
    if (owned->length == owned->capacity) owned->grow();
    const ssize_t n = ::read(f.fd, owned->data + owned->length, owned->capacity - owned->length);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw f.os_error("cannot read");
    if (n == 0) break;
    owned->length += std::size_t(n);
  }
  BundleReader r = view({owned->data, owned->length}, f.origin);
  r.keep_alive_ = std::move(owned);
  return r;
}

}  // namespace weft::bundle
