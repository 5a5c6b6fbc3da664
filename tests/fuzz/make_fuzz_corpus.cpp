// Writes the kept seed corpora of the fuzz targets (tests/fuzz/corpus/<target>/):
//   make_fuzz_corpus <dir>
// Small valid inputs of every format the loaders take, plus a few near misses.
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "bundle/bundle_writer.h"
#include "firmware/hid_report.h"
#include "lighting/env_map.h"
#include "panel/knob_state_file.h"

namespace wb = weft::bundle;

namespace {

void save(const std::filesystem::path& dir, const std::string& name, const std::vector<std::byte>& b) {
  std::ofstream(dir / name, std::ios::binary)
      .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

void save_text(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name, std::ios::binary) << text;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void bundle_corpus(const std::filesystem::path& dir);

void exr_corpus(const std::filesystem::path& dir) {
  weft::EnvMap map(8, 4);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) map.at(x, y) = {0.1f * x, 0.2f * y, 1.0f};
  using weft::ExrCompression;
  using weft::ExrPixel;
  const struct {
    const char* name;
    weft::EnvMapWriteOptions options;
  } kinds[] = {{"float_zip.exr", {ExrPixel::full_float, ExrCompression::zip, false}},
               {"half_piz.exr", {ExrPixel::half, ExrCompression::piz, false}},
               {"half_rle_alpha.exr", {ExrPixel::half, ExrCompression::rle, true}},
               {"float_none.exr", {ExrPixel::full_float, ExrCompression::none, false}},
               {"half_dwab.exr", {ExrPixel::half, ExrCompression::dwab, false}}};  // the C++ reader's path
  for (const auto& k : kinds) weft::write_env_map(dir / k.name, map, k.options);
  map.at(1, 1) = {std::numeric_limits<float>::quiet_NaN(), -1.0f, std::numeric_limits<float>::infinity()};
  weft::write_env_map(dir / "non_finite.exr", map, {ExrPixel::full_float, ExrCompression::none, false});
  const std::string whole = read_text(dir / "float_zip.exr");
  save_text(dir, "truncated.exr", whole.substr(0, whole.size() / 2));
}

void fabric_corpus(const std::filesystem::path& dir, const std::filesystem::path& presets) {
  for (const auto& e : std::filesystem::directory_iterator(presets))
    if (e.path().extension() == ".json") save_text(dir, e.path().filename().string(), read_text(e.path()));
  save_text(dir, "not_an_object.json", "[1, 2, 3]");
  save_text(dir, "truncated.json", read_text(presets / "linen_plain.json").substr(0, 40));
}

void panel_config_corpus(const std::filesystem::path& dir) {
  // First byte even: panel config; odd: knob state file.
  save_text(dir, "config_full", std::string(1, '\0') +
                                    R"({"sources":["hid","gpio","keyboard"],"hid":{"vendor_id":"0x1209","product_id":"0x57ef"},)"
                                    R"("gpio":{"chip":"gpiochip0","encoder_a":[5,13,19,20],"encoder_b":[6,16,26,21],)"
                                    R"("buttons":[12,17,22,23,24],"debounce_ms":5},"state_file":"/var/lib/weft/knobs.json"})");
  save_text(dir, "config_empty", std::string(1, '\0') + "{}");
  const std::vector<weft::input::PresetLook> presets = {
      {"linen_plain", {{{0.06, 0.24, 0.3}, {0.06, 0.24, 0.3}}}},
      {"velvet", {{{0.015, 0.006, 0.0}, {0.015, 0.006, 0.0}}}},
  };
  weft::input::KnobPositions k;
  k.preset = 1;
  k.hue_steps = {3, -7};
  k.brightness_steps = {-2, 4};
  k.gloss_steps = {5, -16};
  k.env_steps = 12;
  save_text(dir, "state_edited", std::string(1, '\1') + weft::input::knob_state_text(k, presets));
  save_text(dir, "state_default", std::string(1, '\1') + weft::input::knob_state_text({}, presets));
}

void hid_report_corpus(const std::filesystem::path& dir) {
  // A stream: [length][report bytes]…, as the harness splits it.
  namespace fw = weft::firmware;
  std::string stream;
  for (int i = 0; i < 6; ++i) {
    fw::PanelReport r;
    r.sequence = static_cast<std::uint8_t>(250 + i);  // wraps
    r.dial[i % fw::kDialCount] = static_cast<std::int8_t>(i % 2 ? -3 : 5);
    r.buttons = static_cast<std::uint8_t>(i == 4 ? 0x10 : (i == 2 ? 0x04 : 0));
    r.time_ms = static_cast<std::uint16_t>(65530 + 7 * i);
    std::uint8_t bytes[fw::kReportSize];
    const size_t n = fw::encode_report(r, bytes, sizeof bytes);
    stream += static_cast<char>(n);
    stream.append(reinterpret_cast<const char*>(bytes), n);
  }
  save_text(dir, "turns_and_buttons", stream);
  save_text(dir, "short_and_garbage", std::string("\x03\x01\x02\x03\x09\x02\x00\x00\x00\x00\x00\x00\x00\x00", 14));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_fuzz_corpus <corpus dir> <fabric presets dir>\n");
    return 2;
  }
  const std::filesystem::path root = argv[1];
  for (const char* name : {"bundle", "exr", "fabric", "panel_config", "hid_report"})
    std::filesystem::create_directories(root / name);
  bundle_corpus(root / "bundle");
  exr_corpus(root / "exr");
  fabric_corpus(root / "fabric", argv[2]);
  panel_config_corpus(root / "panel_config");
  hid_report_corpus(root / "hid_report");
  return 0;
}

namespace {

void bundle_corpus(const std::filesystem::path& dir) {

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
}

}  // namespace
