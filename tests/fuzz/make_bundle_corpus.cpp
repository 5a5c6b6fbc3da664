// Writes the kept seed corpus for the bundle fuzz target (tests/fuzz/corpus/bundle/):
//   make_bundle_corpus <dir>
// Small valid bundles of every section type, plus a few near misses.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bundle/bundle_writer.h"

namespace wb = weft::bundle;

namespace {

void save(const std::filesystem::path& dir, const std::string& name, const std::vector<std::byte>& b) {
  std::ofstream(dir / name, std::ios::binary)
      .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);

  save(dir, "empty_bundle", wb::BundleWriter().to_bytes());

  wb::BundleWriter all;
  const std::vector<std::uint8_t> u8{1, 2, 3};
  const std::vector<std::uint16_t> u16{4, 5};
  const std::vector<std::uint32_t> u32{0, 1, 2, 2, 3, 0};
  const std::vector<std::int32_t> i32{-1, 7};
  const std::vector<float> f32{0.f, 0.5f, 1.f, 0.f, 0.f, 1.f};
  const std::vector<double> f64{2.5};
  all.add_array<std::uint8_t>("visibility.mask", u8);
  all.add_array<std::uint16_t>("u16", u16);
  all.add_array<std::uint32_t>("mesh.indices", u32, {2, 3});
  all.add_array<std::int32_t>("i32", i32);
  all.add_array<float>("mesh.positions", f32, {2, 3});
  all.add_array<double>("settings.exposure", f64, {});
  all.add_json("fabric", R"({"name":"linen_plain","threads":[]})");
  const auto every = all.to_bytes();
  save(dir, "every_type", every);

  wb::BundleWriter json;
  json.add_json("camera", R"({"fov":40,"eye":[0,-2,1]})");
  save(dir, "json_only", json.to_bytes());

  wb::BundleWriter t;
  std::vector<float> table(2 * 2 * 3 * 2, 0.25f);
  t.add_array<float>("T/u", table, {2, 2, 3, 2});
  t.add_array<float>("empty", std::vector<float>{});
  save(dir, "rank4_and_empty", t.to_bytes());

  auto cut = every;
  cut.resize(every.size() - 7);
  save(dir, "truncated", cut);

  auto future = every;
  wb::store_u32(future.data() + wb::header_at::format_version, 2);
  save(dir, "future_version", future);
  return 0;
}
