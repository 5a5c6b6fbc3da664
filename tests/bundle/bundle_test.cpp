// The scene bundle format: round trips of every section type, the documented byte layout, and
// clean BundleErrors naming the right part for truncation at every byte, a flipped bit anywhere,
// wrong versions and structural damage behind valid checksums.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <numeric>
#include <sstream>

#include "bundle/bundle_reader.h"
#include "bundle/bundle_writer.h"
#include "bundle/crc32c.h"
#include "support/bundle_reseal.h"
#include "core/fabric.h"

namespace wb = weft::bundle;
using wb::BundleError;
using wb::BundleReader;
using wb::BundleWriter;
using wb::ElementType;

namespace {

std::filesystem::path temp_file(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("weft_bundle_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

// The bitwise definition of CRC-32C, one bit at a time: the independent check of the table code.
std::uint32_t crc32c_bitwise(const std::vector<std::uint8_t>& data) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::uint8_t byte : data) {
    c ^= byte;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0x82F63B78u & (0u - (c & 1u)));
  }
  return ~c;
}

// A small bundle with one section of each kind; payload sizes chosen to leave padding.
struct Small {
  std::vector<float> positions{0.f, 1.f, 2.f, 3.5f, -4.f, 5.f};  // 2 x 3
  std::vector<std::uint32_t> indices{0, 1, 2};
  std::vector<double> scalar{2.5};
  std::vector<std::uint8_t> mask{1, 0, 1, 1, 0};
  std::string meta = R"({"camera":{"fov":40}})";
  std::vector<std::byte> bytes() const {
    BundleWriter w;
    w.add_array<float>("mesh.positions", positions, {2, 3});
    w.add_array<std::uint32_t>("mesh.indices", indices);
    w.add_array<double>("settings.exposure", scalar, {});
    w.add_array<std::uint8_t>("visibility.mask", mask);
    w.add_json("camera", meta);
    return w.to_bytes();
  }
};

// Which part a byte of a valid bundle belongs to, as the reader names it.
std::string owner_of(const BundleReader& r, std::uint64_t byte) {
  if (byte < wb::kHeaderSize) return "header";
  const auto& s = r.sections();
  const std::uint64_t table_end = wb::kHeaderSize + s.size() * wb::kEntrySize;
  if (byte < table_end) return "section table";
  if (s.empty() || byte < s[0].offset) return "section table";  // padding after the table
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool last = i + 1 == s.size();
    if (byte < s[i].offset + s[i].size || last || byte < s[i + 1].offset)
      return "section '" + s[i].name + "'";  // its payload or the padding after it
  }
  return "?";
}

std::string error_of(std::span<const std::byte> bytes, std::string* part = nullptr) {
  // A heap copy of exactly these bytes, so that a read past the end is an ASan error.
  std::vector<std::byte> exact(bytes.begin(), bytes.end());
  try {
    BundleReader::view(exact, "test");
  } catch (const BundleError& e) {
    if (part) *part = e.part();
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Crc32c, MatchesTheCheckValueAndTheBitwiseDefinition) {
  const std::string check = "123456789";
  EXPECT_EQ(wb::crc32c_extend(0, check.data(), check.size()), 0xE3069283u);
  std::vector<std::uint8_t> data;
  for (int n = 0; n < 200; ++n) {
    EXPECT_EQ(wb::crc32c_extend(0, data.data(), data.size()), crc32c_bitwise(data)) << "length " << n;
    // Continuing over two pieces equals one pass.
    const std::size_t half = data.size() / 3;
    EXPECT_EQ(wb::crc32c_extend(wb::crc32c_extend(0, data.data(), half), data.data() + half, data.size() - half),
              crc32c_bitwise(data));
    data.push_back(std::uint8_t(n * 37 + 11));
  }
}

TEST(Bundle, RoundTripsEveryElementTypeThroughAMappedFile) {
  std::vector<std::uint8_t> u8{1, 2, 255};
  std::vector<std::uint16_t> u16{0, 65535, 7};
  std::vector<std::uint32_t> u32{4000000000u, 1};
  std::vector<std::int32_t> i32{-5, 0, 2147483647, -2147483647 - 1};
  std::vector<float> f32(2 * 3 * 4 * 5);
  std::iota(f32.begin(), f32.end(), -10.f);
  std::vector<double> f64{3.141592653589793, -1e300, 0.0};
  std::vector<float> empty;
  const std::string json = R"({"sgs":[{"axis":[0,0,1],"sharpness":20,"amplitude":[1,1,1]}]})";

  BundleWriter w;
  w.add_array<std::uint8_t>("u8", u8);
  w.add_array<std::uint16_t>("u16", u16);
  w.add_array<std::uint32_t>("u32", u32);
  w.add_array<std::int32_t>("i32", i32, {2, 2});
  w.add_array<float>("T/rank4", f32, {2, 3, 4, 5});
  w.add_array<double>("f64", f64);
  w.add_array<float>("empty", empty);
  w.add_json("lighting.default_sgs", json);
  const auto file = temp_file("roundtrip.weftbundle");
  w.write_file(file);

  const BundleReader r = BundleReader::open(file);
  ASSERT_EQ(r.sections().size(), 8u);
  auto eq = [](auto got, const auto& want) {
    return std::equal(got.begin(), got.end(), want.begin(), want.end());
  };
  EXPECT_TRUE(eq(r.array<std::uint8_t>("u8"), u8));
  EXPECT_TRUE(eq(r.array<std::uint16_t>("u16"), u16));
  EXPECT_TRUE(eq(r.array<std::uint32_t>("u32"), u32));
  EXPECT_TRUE(eq(r.array<std::int32_t>("i32"), i32));
  EXPECT_TRUE(eq(r.array<float>("T/rank4"), f32));
  EXPECT_TRUE(eq(r.array<double>("f64"), f64));
  EXPECT_TRUE(r.array<float>("empty").empty());
  EXPECT_EQ(r.json("lighting.default_sgs"), json);
  EXPECT_EQ(r.section("T/rank4").shape, (std::vector<std::uint64_t>{2, 3, 4, 5}));
  EXPECT_EQ(r.section("i32").shape, (std::vector<std::uint64_t>{2, 2}));
  EXPECT_EQ(r.section("lighting.default_sgs").type, ElementType::Json);
  for (const auto& s : r.sections()) {
    EXPECT_EQ(s.offset % 64, 0u) << s.name;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(r.raw(s.name).data()) % 64, 0u) << s.name;
  }
  EXPECT_EQ(r.bytes().size(), std::filesystem::file_size(file));
  // Spans point into the mapping: the file's bytes, not a copy.
  EXPECT_EQ(static_cast<const void*>(r.array<float>("T/rank4").data()),
            static_cast<const void*>(r.bytes().data() + r.section("T/rank4").offset));
  // A copy of the reader keeps the mapping alive after the original is gone.
  std::span<const double> kept;
  {
    const BundleReader copy = r;
    kept = copy.array<double>("f64");
  }
  EXPECT_EQ(kept[0], f64[0]);
}

// read() copies the file into memory: the same sections and values as open(), 64-byte aligned,
// and a file rewritten in place (truncated, then half written, as an interrupted copy leaves
// it) afterwards changes nothing already read; reading it then is a clean "truncated" error.
TEST(Bundle, ReadKeepsItsOwnCopyWhileTheFileIsRewrittenInPlace) {
  const Small small;
  const std::vector<std::byte> bytes = small.bytes();
  const auto file = temp_file("read_copy.weftbundle");
  const auto write = [&](std::size_t n) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(n));
  };
  write(bytes.size());
  const BundleReader r = BundleReader::read(file);
  const BundleReader mapped = BundleReader::open(file);
  ASSERT_EQ(r.sections().size(), mapped.sections().size());
  EXPECT_TRUE(std::equal(r.bytes().begin(), r.bytes().end(), bytes.begin(), bytes.end()));
  EXPECT_NE(static_cast<const void*>(r.bytes().data()), static_cast<const void*>(mapped.bytes().data()));
  for (const auto& s : r.sections()) EXPECT_EQ(reinterpret_cast<std::uintptr_t>(r.raw(s.name).data()) % 64, 0u) << s.name;

  write(bytes.size() / 2);
  const auto positions = r.array<float>("mesh.positions");
  EXPECT_TRUE(std::equal(positions.begin(), positions.end(), small.positions.begin(), small.positions.end()));
  EXPECT_EQ(r.json("camera"), small.meta);
  try {
    BundleReader::read(file);
    ADD_FAILURE() << "a half-written file was accepted";
  } catch (const BundleError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(BundleReader::read(file.string() + ".missing"), BundleError);
}

TEST(Bundle, FabricParametersAreReadIntoAnEditableStruct) {
  std::ifstream in(std::string(WEFT_SOURCE_ASSETS) + "/fabrics/linen_plain.json");
  std::stringstream text;
  text << in.rdbuf();
  BundleWriter w;
  w.add_json("fabric", text.str());
  const auto bytes = w.to_bytes();
  const BundleReader r = BundleReader::view(bytes, "memory");
  weft::Fabric fabric = weft::parse_fabric(std::string(r.json("fabric")), "bundle fabric");
  const weft::Fabric preset = weft::load_fabric_preset("linen_plain", std::string(WEFT_SOURCE_ASSETS) + "/fabrics");
  EXPECT_EQ(fabric.threads[0].eta, preset.threads[0].eta);
  EXPECT_EQ(fabric.threads[1].gamma_s, preset.threads[1].gamma_s);
  fabric.threads[0].eta = 1.6;  // a knob edit changes the struct; the mapped bundle is untouched
  EXPECT_EQ(weft::parse_fabric(std::string(r.json("fabric")), "again").threads[0].eta, preset.threads[0].eta);
}

TEST(Bundle, BytesFollowTheDocumentedLayout) {
  const std::vector<float> v{1.f, 2.f, 3.f};
  BundleWriter w;
  w.add_array<float>("a", v, {3});
  w.add_json("b", "{}");
  const auto f = w.to_bytes();
  // BUNDLE_FORMAT.md: 64-byte header, 2 x 96-byte entries = table ends at 256; payloads at 256
  // (12 bytes) and 320 (2 bytes); the file ends at the last payload's end.
  ASSERT_EQ(f.size(), 322u);
  EXPECT_EQ(std::memcmp(f.data(), "WEFTBNDL", 8), 0);
  EXPECT_EQ(wb::load_u32(&f[8]), 1u);     // version
  EXPECT_EQ(wb::load_u32(&f[12]), 64u);   // header size
  EXPECT_EQ(wb::load_u32(&f[16]), 2u);    // section count
  EXPECT_EQ(wb::load_u32(&f[20]), 96u);   // entry size
  EXPECT_EQ(wb::load_u64(&f[24]), 64u);   // table offset
  EXPECT_EQ(wb::load_u64(&f[32]), 322u);  // total size
  std::vector<std::uint8_t> table(reinterpret_cast<const std::uint8_t*>(&f[64]),
                                  reinterpret_cast<const std::uint8_t*>(&f[256]));
  EXPECT_EQ(wb::load_u32(&f[40]), crc32c_bitwise(table));
  std::vector<std::uint8_t> header(reinterpret_cast<const std::uint8_t*>(&f[0]),
                                   reinterpret_cast<const std::uint8_t*>(&f[60]));
  EXPECT_EQ(wb::load_u32(&f[60]), crc32c_bitwise(header));
  const std::byte* e0 = &f[64];
  EXPECT_STREQ(reinterpret_cast<const char*>(e0), "a");
  EXPECT_EQ(wb::load_u32(e0 + 32), 5u);   // f32
  EXPECT_EQ(wb::load_u32(e0 + 36), 1u);   // rank
  EXPECT_EQ(wb::load_u64(e0 + 40), 3u);   // shape[0]
  EXPECT_EQ(wb::load_u64(e0 + 72), 256u); // offset
  EXPECT_EQ(wb::load_u64(e0 + 80), 12u);  // size
  float first;
  std::memcpy(&first, &f[256], 4);
  EXPECT_EQ(first, 1.f);
  const std::byte* e1 = &f[160];
  EXPECT_EQ(wb::load_u32(e1 + 32), 7u);   // json
  EXPECT_EQ(wb::load_u64(e1 + 72), 320u);
  EXPECT_EQ(char(f[320]), '{');
}

TEST(Bundle, TruncationAtEveryByteIsACleanErrorNamingThePart) {
  const auto full = Small().bytes();
  const BundleReader r = BundleReader::view(full, "full");
  for (std::size_t n = 0; n < full.size(); ++n) {
    std::string part;
    const std::string what = error_of(std::span(full).first(n), &part);
    ASSERT_FALSE(what.empty()) << "accepted a bundle cut at " << n << " bytes";
    if (n < wb::kHeaderSize) {
      EXPECT_EQ(part, "header") << n;
    } else if (n < wb::kHeaderSize + r.sections().size() * wb::kEntrySize) {
      EXPECT_EQ(part, "section table") << n;
    } else {
      // The first section that does not fit entirely is named.
      const auto& s = r.sections();
      const auto cut = std::find_if(s.begin(), s.end(), [&](auto& x) { return x.offset + x.size > n; });
      ASSERT_NE(cut, s.end());
      EXPECT_EQ(part, "section '" + cut->name + "'") << n << ": " << what;
      EXPECT_NE(what.find("truncated"), std::string::npos) << what;
    }
  }
  // And from disk: an empty file and a cut file.
  const auto file = temp_file("cut.weftbundle");
  for (std::size_t n : {std::size_t(0), std::size_t(3), full.size() - 1}) {
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(full.data()), std::streamsize(n));
    EXPECT_THROW(BundleReader::open(file), BundleError) << n;
  }
}

TEST(Bundle, AFlippedBitAnywhereIsAnErrorNamingItsPart) {
  const auto good = Small().bytes();
  const BundleReader r = BundleReader::view(good, "good");
  std::set<std::string> sections_named;
  for (std::size_t i = 0; i < good.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      auto bad = good;
      bad[i] ^= std::byte(1u << bit);
      std::string part;
      const std::string what = error_of(bad, &part);
      ASSERT_FALSE(what.empty()) << "byte " << i << " bit " << bit << " went unnoticed";
      EXPECT_EQ(part, owner_of(r, i)) << "byte " << i << " bit " << bit << ": " << what;
      sections_named.insert(part);
    }
  }
  for (const auto& s : r.sections()) EXPECT_TRUE(sections_named.count("section '" + s.name + "'")) << s.name;
}

TEST(Bundle, ACorruptSectionSaysWhichAndThatItIsCorrupt) {
  auto bytes = Small().bytes();
  const BundleReader r = BundleReader::view(bytes, "good");
  const auto& s = r.section("mesh.indices");
  auto bad = bytes;
  bad[s.offset + 1] ^= std::byte{0x40};
  try {
    BundleReader::view(bad, "scene.weftbundle");
    FAIL();
  } catch (const BundleError& e) {
    EXPECT_EQ(e.section(), "mesh.indices");
    EXPECT_NE(std::string(e.what()).find("bundle scene.weftbundle: section 'mesh.indices': checksum mismatch"),
              std::string::npos)
        << e.what();
  }
}

TEST(Bundle, WrongVersionIsRefusedEvenWithValidChecksums) {
  for (std::uint32_t version : {0u, 2u, 0xFFFFFFFFu}) {
    auto bytes = Small().bytes();
    wb::store_u32(&bytes[wb::header_at::format_version], version);
    wb::testing::reseal(bytes);
    std::string part;
    const std::string what = error_of(bytes, &part);
    EXPECT_EQ(part, "header");
    EXPECT_NE(what.find("format version " + std::to_string(version)), std::string::npos) << what;
    EXPECT_NE(what.find("reads version 1"), std::string::npos) << what;
  }
}

TEST(Bundle, NotABundleAndTrailingBytesAreRefused) {
  const std::string text = "this is a PNG, honest";
  std::string part;
  EXPECT_NE(error_of(std::as_bytes(std::span(text)), &part).find("not a Weft bundle"), std::string::npos);
  EXPECT_EQ(part, "header");
  auto bytes = Small().bytes();
  bytes.push_back(std::byte{0});
  EXPECT_NE(error_of(bytes, &part).find("unexpected bytes after the last section"), std::string::npos);
  EXPECT_EQ(part, "file");
  EXPECT_THROW(BundleReader::open(temp_file("does-not-exist.weftbundle")), BundleError);
}

TEST(Bundle, StructuralDamageBehindValidChecksumsNamesTheSection) {
  const auto good = Small().bytes();
  const BundleReader r = BundleReader::view(good, "good");
  const std::uint64_t e1 = wb::kHeaderSize + 1 * wb::kEntrySize;  // mesh.indices
  auto expect = [&](auto edit, const std::string& part, const std::string& detail) {
    auto bad = good;
    edit(bad);
    wb::testing::reseal(bad);
    std::string got;
    const std::string what = error_of(bad, &got);
    EXPECT_EQ(got, part) << what;
    EXPECT_NE(what.find(detail), std::string::npos) << what;
  };
  expect([&](auto& b) { wb::store_u64(&b[e1 + wb::entry_at::offset], r.section("mesh.indices").offset + 4); },
         "section 'mesh.indices'", "64-byte aligned");
  expect([&](auto& b) { wb::store_u64(&b[e1 + wb::entry_at::shape], 1000); }, "section 'mesh.indices'",
         "does not match its shape");
  expect([&](auto& b) { wb::store_u32(&b[e1 + wb::entry_at::element_type], 99); }, "section 'mesh.indices'",
         "unknown element type 99");
  expect([&](auto& b) { wb::store_u32(&b[e1 + wb::entry_at::rank], 5); }, "section 'mesh.indices'", "rank 5");
  expect([&](auto& b) { std::memcpy(&b[e1], "mesh.positions", 15); }, "section 'mesh.positions'", "twice");
  expect([&](auto& b) { b[e1 + 3] = std::byte{' '}; }, "section table", "entry 1: name");
  expect([&](auto& b) { wb::store_u64(&b[wb::header_at::total_size], 1u << 30); }, "header", "total size");
  expect([&](auto& b) { wb::store_u32(&b[wb::header_at::section_count], 4000); }, "section table", "truncated");
  expect([&](auto& b) { wb::store_u32(&b[wb::header_at::section_count], 100000); }, "header", "limit");
  expect([&](auto& b) { wb::store_u64(&b[e1 + wb::entry_at::shape], 1ull << 62); wb::store_u64(&b[e1 + wb::entry_at::size], 0); },
         "section 'mesh.indices'", "overflows");
}

TEST(Bundle, TypedAccessChecksNameAndType) {
  const auto bytes = Small().bytes();
  const BundleReader r = BundleReader::view(bytes, "s");
  try {
    (void)r.array<double>("mesh.positions");
    FAIL();
  } catch (const BundleError& e) {
    EXPECT_EQ(e.section(), "mesh.positions");
    EXPECT_NE(std::string(e.what()).find("holds f32, read as f64"), std::string::npos);
  }
  try {
    (void)r.array<float>("sdf.d");
    FAIL();
  } catch (const BundleError& e) {
    EXPECT_EQ(e.section(), "sdf.d");
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
  }
  EXPECT_THROW((void)r.json("mesh.indices"), BundleError);
  EXPECT_EQ(r.array<double>("settings.exposure").size(), 1u);
  EXPECT_TRUE(r.section("settings.exposure").shape.empty());
}

TEST(Bundle, WriterRejectsBadSections) {
  BundleWriter w;
  const std::vector<float> v{1, 2, 3, 4};
  EXPECT_THROW(w.add_array<float>("", v), std::invalid_argument);
  EXPECT_THROW(w.add_array<float>("has space", v), std::invalid_argument);
  EXPECT_THROW(w.add_array<float>(std::string(32, 'x'), v), std::invalid_argument);
  EXPECT_NO_THROW(w.add_array<float>(std::string(31, 'x'), v));
  EXPECT_THROW(w.add_array<float>(std::string(31, 'x'), v), std::invalid_argument);  // duplicate
  EXPECT_THROW(w.add_array<float>("shape", v, {3}), std::invalid_argument);
  EXPECT_THROW(w.add_array<float>("rank5", v, {1, 1, 1, 1, 4}), std::invalid_argument);
  EXPECT_THROW(w.add_array<float>("overflow", v, {1ull << 32, 1ull << 32, 4}), std::invalid_argument);
  EXPECT_NO_THROW(w.add_array<float>("ok", v, {2, 2}));
  EXPECT_EQ(w.section_count(), 2u);
}
