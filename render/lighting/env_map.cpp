#include "lighting/env_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <limits>
#include <numbers>

#include <OpenEXR/openexr.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfCompression.h>
#include <Imath/half.h>

#include "files/atomic_file.h"

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
// Larger maps than this are refused rather than risking an out-of-memory crash.
constexpr long long kMaxTexels = 1LL << 25;  // 8192 × 4096: far more than a 10-SG fit can use
// No OpenEXR compression packs more than ~520 texels into a file byte (one half channel at
// deflate's 1:1032 peak), so a data window of more than 1024 texels per byte is a corrupt header,
// refused before the texels are allocated.
constexpr long long kMaxTexelsPerFileByte = 1024;

// Maps are read through OpenEXRCore, the C reader OpenEXR hardened against corrupt files. The
// C++ Imf reader of OpenEXR 3.1 allocates an attribute's declared size before reading it, so a
// few corrupt header bytes made it ask for gigabytes (found by tests/fuzz/exr_fuzz).
class ExrReadContext {
public:
  explicit ExrReadContext(const std::filesystem::path& path) : path_(path) {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &message_;
    init.error_handler_fn = [](exr_const_context_t ctxt, exr_result_t, const char* msg) {
      void* user = nullptr;
      if (exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user && msg) {
        auto& m = *static_cast<std::string*>(user);
        if (m.empty()) m = msg;  // the first complaint is the cause
      }
    };
    init.max_image_width = init.max_image_height = 1 << 16;
    init.max_tile_width = init.max_tile_height = 1 << 12;
    check(exr_start_read(&ctxt_, path.c_str(), &init), "corrupt or unreadable OpenEXR file");
  }
  ~ExrReadContext() {
    if (decoding_) exr_decoding_destroy(ctxt_, &decoder_);
    exr_finish(&ctxt_);
  }
  ExrReadContext(const ExrReadContext&) = delete;
  ExrReadContext& operator=(const ExrReadContext&) = delete;

  exr_context_t get() const { return ctxt_; }
  void check(exr_result_t rc, const char* what) {
    if (rc == EXR_ERR_SUCCESS) return;
    throw EnvMapError(path_, std::string(what) + ": " + (message_.empty() ? exr_get_error_code_as_string(rc) : message_));
  }
  // Decodes one chunk's R,G,B (or Y into R) as float into `map` at texel (x0, y0).
  void decode(const exr_chunk_info_t& chunk, EnvMap& map, int x0, int y0, bool rgb) {
    if (chunk.width <= 0 || chunk.height <= 0 || x0 < 0 || y0 < 0 || x0 + chunk.width > map.width ||
        y0 + chunk.height > map.height)
      throw EnvMapError(path_, "corrupt OpenEXR file: a pixel block lies outside the data window");
    if (!decoding_) {
      check(exr_decoding_initialize(ctxt_, 0, &chunk, &decoder_), "cannot decode OpenEXR pixels");
      decoding_ = true;
    } else {
      check(exr_decoding_update(ctxt_, 0, &chunk, &decoder_), "cannot decode OpenEXR pixels");
    }
    for (int16_t c = 0; c < decoder_.channel_count; ++c) {
      exr_coding_channel_info_t& ch = decoder_.channels[c];
      const std::string name = ch.channel_name ? ch.channel_name : "";
      const int component = rgb ? (name == "R" ? 0 : name == "G" ? 1 : name == "B" ? 2 : -1) : (name == "Y" ? 0 : -1);
      if (component < 0 || ch.height != chunk.height || ch.width != chunk.width) {
        ch.decode_to_ptr = nullptr;  // not wanted (A, others) or subsampled (refused earlier)
        continue;
      }
      ch.decode_to_ptr = reinterpret_cast<uint8_t*>(&map.at(x0, y0)[component]);
      ch.user_pixel_stride = sizeof(glm::vec3);
      ch.user_line_stride = static_cast<int32_t>(sizeof(glm::vec3)) * map.width;
      ch.user_data_type = EXR_PIXEL_FLOAT;
      ch.user_bytes_per_element = sizeof(float);
    }
    check(exr_decoding_choose_default_routines(ctxt_, 0, &decoder_), "cannot decode OpenEXR pixels");
    check(exr_decoding_run(ctxt_, 0, &decoder_), "corrupt OpenEXR pixel data");
  }

private:
  std::filesystem::path path_;
  std::string message_;
  exr_context_t ctxt_ = nullptr;
  exr_decode_pipeline_t decoder_ = EXR_DECODE_PIPELINE_INITIALIZER;
  bool decoding_ = false;
};


// OpenEXRCore 3.1 cannot decompress DWAA/DWAB (Blender's and many studios' choice), so such maps
// are read with the C++ reader once Core has vetted the header. The C++ reader parses some
// attributes by their content rather than their declared size; where the two disagree it reads
// the rest of the header out of step and can allocate gigabytes. This walk over the raw header
// refuses exactly those files. Returns why, or empty.
std::string imf_header_out_of_step(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string b(1 << 16, '\0');  // headers of real maps are a few hundred bytes
  in.read(b.data(), static_cast<std::streamsize>(b.size()));
  b.resize(static_cast<size_t>(in.gcount()));
  if (b.size() < 8) return "file is truncated";
  const bool long_names = (static_cast<unsigned char>(b[5]) & 0x04) != 0;
  if ((static_cast<unsigned char>(b[5]) & 0x10) != 0) return "multi-part files are not supported for DWA maps";
  const size_t longest = long_names ? 255 : 31;
  size_t at = 8;
  auto name = [&](std::string& out) {
    const size_t end = b.find('\0', at);
    if (end == std::string::npos || end - at > longest) return false;
    out = b.substr(at, end - at);
    at = end + 1;
    return true;
  };
  for (;;) {
    std::string attr, type;
    if (!name(attr)) return "malformed header";
    if (attr.empty()) return {};
    if (!name(type) || at + 4 > b.size()) return "malformed header at '" + attr + "'";
    int32_t size;
    std::memcpy(&size, b.data() + at, 4);
    at += 4;
    if (size < 0 || static_cast<size_t>(size) > b.size() - at) return "attribute '" + attr + "' overruns the header";
    const size_t end = at + static_cast<size_t>(size);
    static const std::map<std::string, int32_t> fixed = {
        {"box2i", 16}, {"box2f", 16}, {"compression", 1}, {"lineOrder", 1}, {"envmap", 1}, {"deepImageState", 1},
        {"int", 4}, {"float", 4}, {"double", 8}, {"rational", 8}, {"timecode", 8}, {"v2i", 8}, {"v2f", 8},
        {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64},
        {"m44d", 128}, {"chromaticities", 32}, {"keycode", 28}, {"tiledesc", 9}};
    if (const auto f = fixed.find(type); f != fixed.end() && f->second != size)
      return "attribute '" + attr + "' of type " + type + " has size " + std::to_string(size) + ", not " +
             std::to_string(f->second);
    if (type == "chlist") {  // read by content: names, then 16 bytes each, up to an empty name
      size_t p = at;
      for (;;) {
        const size_t z = b.find('\0', p);
        if (z == std::string::npos || z >= end) return "channel list overruns its attribute";
        if (z == p) {
          p = z + 1;
          break;
        }
        p = z + 1 + 16;
      }
      if (p != end) return "channel list disagrees with its declared size";
    } else if (type == "preview") {  // read by content: width, height, RGBA8 pixels
      if (size < 8) return "preview overruns its attribute";
      uint32_t pw, ph;
      std::memcpy(&pw, b.data() + at, 4);
      std::memcpy(&ph, b.data() + at + 4, 4);
      if (8 + 4ull * pw * ph != static_cast<unsigned long long>(size)) return "preview disagrees with its declared size";
    }
    at = end;
  }
}

void read_with_imf(const std::filesystem::path& path, EnvMap& map, const exr_attr_box2i_t& dw, bool rgb) {
  if (const std::string why = imf_header_out_of_step(path); !why.empty())
    throw EnvMapError(path, "corrupt OpenEXR header: " + why);
  try {
    Imf::InputFile file(path.c_str());
    // Slices point at a virtual origin so that the data window's first texel lands at texels[0]
    // (OpenEXR's convention). Computed on integers: that origin lies outside the array.
    const std::uintptr_t origin =
        reinterpret_cast<std::uintptr_t>(map.texels.data()) -
        static_cast<std::uintptr_t>((static_cast<long long>(dw.min.x) + static_cast<long long>(dw.min.y) * map.width) *
                                    static_cast<long long>(sizeof(glm::vec3)));
    char* base = reinterpret_cast<char*>(origin);
    const size_t xs = sizeof(glm::vec3), ys = sizeof(glm::vec3) * static_cast<size_t>(map.width);
    Imf::FrameBuffer fb;
    for (int c = 0; c < (rgb ? 3 : 1); ++c)
      fb.insert(rgb ? std::string(1, "RGB"[c]) : std::string("Y"),
                Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys, 1, 1, 0.0));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
  } catch (const std::exception& e) {
    throw EnvMapError(path, std::string("cannot read OpenEXR: ") + e.what());
  }
}

}  // namespace

EnvMapError::EnvMapError(const std::filesystem::path& path, const std::string& what)
    : std::runtime_error("environment map '" + path.string() + "': " + what), path_(path) {}

EnvMap::EnvMap(int w, int h) : width(w), height(h), texels(static_cast<size_t>(w) * h, glm::vec3(0.0f)) {}

glm::dvec2 direction_to_uv(const glm::dvec3& d) {
  return {std::atan2(d.y, -d.x) / (2.0 * kPi) + 0.5, std::atan2(d.z, std::hypot(d.x, d.y)) / kPi + 0.5};
}

glm::dvec3 uv_to_direction(const glm::dvec2& uv) {
  const double phi = 2.0 * kPi * (uv.x - 0.5);   // atan2(d.y, -d.x)
  const double elevation = kPi * (uv.y - 0.5);    // atan2(d.z, hypot(d.x, d.y))
  const double c = std::cos(elevation);
  return {-c * std::cos(phi), c * std::sin(phi), std::sin(elevation)};
}

glm::dvec2 direction_to_pixel(const glm::dvec3& d, int width, int height) {
  const glm::dvec2 uv = direction_to_uv(d);
  return {uv.x * width, (1.0 - uv.y) * height};
}

glm::dvec3 EnvMap::direction(int x, int y) const {
  return uv_to_direction({(x + 0.5) / width, 1.0 - (y + 0.5) / height});
}

double EnvMap::solid_angle(int y) const {
  // Row y spans elevations [π(0.5 − (y+1)/H), π(0.5 − y/H)]; the band's area is 2π Δsin(E).
  const double top = kPi * (0.5 - static_cast<double>(y) / height);
  const double bottom = kPi * (0.5 - static_cast<double>(y + 1) / height);
  return 2.0 * kPi / width * (std::sin(top) - std::sin(bottom));
}

glm::dvec3 EnvMap::lookup(const glm::dvec3& d) const {
  const glm::dvec2 p = direction_to_pixel(d, width, height) - 0.5;
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const double tx = p.x - fx, ty = p.y - fy;
  auto wrap_x = [&](long long x) { return static_cast<int>(((x % width) + width) % width); };
  auto clamp_y = [&](long long y) { return static_cast<int>(std::clamp<long long>(y, 0, height - 1)); };
  const long long x0 = static_cast<long long>(fx), y0 = static_cast<long long>(fy);
  const glm::dvec3 a(at(wrap_x(x0), clamp_y(y0))), b(at(wrap_x(x0 + 1), clamp_y(y0)));
  const glm::dvec3 c(at(wrap_x(x0), clamp_y(y0 + 1))), e(at(wrap_x(x0 + 1), clamp_y(y0 + 1)));
  return (1 - ty) * ((1 - tx) * a + tx * b) + ty * ((1 - tx) * c + tx * e);
}

namespace {
bool names_env_file(const std::string& name) {
  const std::filesystem::path p(name);
  return p.has_parent_path() || p.extension() == ".exr";
}
}  // namespace

std::filesystem::path env_map_file(const std::string& name, const std::filesystem::path& dir) {
  return names_env_file(name) ? std::filesystem::path(name) : dir / (name + ".exr");
}

std::string env_map_label(const std::string& name) {
  return names_env_file(name) ? std::filesystem::path(name).stem().string() : name;
}

EnvMap load_env_map(const std::filesystem::path& path, NonFinitePolicy policy, EnvMapRepairs* repairs) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw EnvMapError(path, "file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw EnvMapError(path, "not a regular file");

  EnvMap map;
  ExrReadContext exr(path);
  exr_storage_t storage;
  exr.check(exr_get_storage(exr.get(), 0, &storage), "corrupt OpenEXR file");
  if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
    throw EnvMapError(path, "deep OpenEXR images are not environment maps");
  exr_attr_box2i_t dw;
  exr.check(exr_get_data_window(exr.get(), 0, &dw), "corrupt OpenEXR file");
  const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
  const long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
  if (w < 2 || h < 1) throw EnvMapError(path, "image is empty (" + std::to_string(w) + "×" + std::to_string(h) + ")");
  if (w * h > kMaxTexels)
    throw EnvMapError(path, "image " + std::to_string(w) + "×" + std::to_string(h) + " is too large");
  std::error_code size_error;
  const auto file_bytes = static_cast<long long>(std::filesystem::file_size(path, size_error));
  if (size_error || w * h > file_bytes * kMaxTexelsPerFileByte)
    throw EnvMapError(path, "corrupt OpenEXR header: a " + std::to_string(w) + "×" + std::to_string(h) +
                                " image cannot fit in " + std::to_string(file_bytes) + " bytes");
  const exr_attr_chlist_t* channels = nullptr;
  exr.check(exr_get_channels(exr.get(), 0, &channels), "corrupt OpenEXR file");
  bool has[4] = {};  // R, G, B, Y
  for (int i = 0; i < channels->num_channels; ++i) {
    const exr_attr_chlist_entry_t& e = channels->entries[i];
    const std::string name(e.name.str, static_cast<size_t>(e.name.length));
    const int k = name == "R" ? 0 : name == "G" ? 1 : name == "B" ? 2 : name == "Y" ? 3 : -1;
    if (k < 0) continue;
    if (e.x_sampling != 1 || e.y_sampling != 1)
      throw EnvMapError(path, "channel " + name + " is subsampled; environment maps need full-resolution channels");
    has[k] = true;
  }
  const bool rgb = has[0] && has[1] && has[2];
  if (!rgb && !has[3]) throw EnvMapError(path, "no R,G,B (or Y) channels");

  map = EnvMap(static_cast<int>(w), static_cast<int>(h));
  exr_compression_t compression;
  exr.check(exr_get_compression(exr.get(), 0, &compression), "corrupt OpenEXR file");
  exr_chunk_info_t chunk;
  if (compression == EXR_COMPRESSION_DWAA || compression == EXR_COMPRESSION_DWAB) {
    read_with_imf(path, map, dw, rgb);
  } else if (storage == EXR_STORAGE_SCANLINE) {
    int32_t lines = 0;
    exr.check(exr_get_scanlines_per_chunk(exr.get(), 0, &lines), "corrupt OpenEXR file");
    if (lines < 1) throw EnvMapError(path, "corrupt OpenEXR file: no scanlines per block");
    for (long long y = dw.min.y; y <= dw.max.y; y += lines) {
      exr.check(exr_read_scanline_chunk_info(exr.get(), 0, static_cast<int>(y), &chunk), "corrupt OpenEXR file");
      exr.decode(chunk, map, 0, static_cast<int>(static_cast<long long>(chunk.start_y) - dw.min.y), rgb);
    }
  } else {
    uint32_t tw = 0, th = 0;
    exr_tile_level_mode_t levels;
    exr_tile_round_mode_t round;
    exr.check(exr_get_tile_descriptor(exr.get(), 0, &tw, &th, &levels, &round), "corrupt OpenEXR file");
    if (tw < 1 || th < 1) throw EnvMapError(path, "corrupt OpenEXR file: empty tiles");
    // Level 0 (full resolution) only: mip levels are not needed for a light probe.
    for (long long ty = 0; ty * th < h; ++ty)
      for (long long tx = 0; tx * tw < w; ++tx) {
        exr.check(exr_read_tile_chunk_info(exr.get(), 0, static_cast<int>(tx), static_cast<int>(ty), 0, 0, &chunk),
                  "corrupt OpenEXR file");
        exr.decode(chunk, map, static_cast<int>(tx * tw), static_cast<int>(ty * th), rgb);
      }
  }
  if (!rgb)
    for (auto& t : map.texels) t = glm::vec3(t.r);

  // Non-finite and negative values: count them, then repair or refuse.
  EnvMapRepairs found;
  float largest = 0.0f;
  for (const auto& t : map.texels)
    for (int c = 0; c < 3; ++c) {
      const float v = t[c];
      if (std::isnan(v)) ++found.nan;
      else if (std::isinf(v)) ++found.infinite;
      else if (v < 0.0f) ++found.negative;
      else largest = std::max(largest, v);
    }
  if (repairs) *repairs = found;
  if (found.total() > 0) {
    if (policy == NonFinitePolicy::fail)
      throw EnvMapError(path, std::to_string(found.nan) + " NaN, " + std::to_string(found.infinite) + " infinite and " +
                                  std::to_string(found.negative) +
                                  " negative channel values (use the clamp policy to repair them)");
    for (auto& t : map.texels)
      for (int c = 0; c < 3; ++c) {
        float& v = t[c];
        if (std::isnan(v) || v < 0.0f) v = 0.0f;  // also -Inf
        else if (std::isinf(v)) v = largest;
      }
  }
  return map;
}

void write_env_map(const std::filesystem::path& path, const EnvMap& map, const EnvMapWriteOptions& options) {
  if (map.width < 1 || map.height < 1 || map.texels.size() != static_cast<size_t>(map.width) * map.height)
    throw EnvMapError(path, "cannot write an empty or inconsistent map");
  try {
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    switch (options.compression) {
      case ExrCompression::none: compression = Imf::NO_COMPRESSION; break;
      case ExrCompression::rle: compression = Imf::RLE_COMPRESSION; break;
      case ExrCompression::zip: compression = Imf::ZIP_COMPRESSION; break;
      case ExrCompression::piz: compression = Imf::PIZ_COMPRESSION; break;
      case ExrCompression::dwab: compression = Imf::DWAB_COMPRESSION; break;
    }
    Imf::Header header(map.width, map.height, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, compression);
    const size_t n = map.texels.size();
    const int channels = options.alpha ? 4 : 3;
    const char* names[4] = {"R", "G", "B", "A"};
    Imf::FrameBuffer fb;
    std::vector<float> full;
    std::vector<half> halves;
    if (options.pixel == ExrPixel::half) {
      halves.resize(n * channels);
      for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < channels; ++c) halves[i * channels + c] = half(c < 3 ? map.texels[i][c] : 1.0f);
    } else {
      full.resize(n * channels);
      for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < channels; ++c) full[i * channels + c] = c < 3 ? map.texels[i][c] : 1.0f;
    }
    for (int c = 0; c < channels; ++c) {
      if (options.pixel == ExrPixel::half) {
        header.channels().insert(names[c], Imf::Channel(Imf::HALF));
        fb.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.data() + c), sizeof(half) * channels,
                                       sizeof(half) * channels * map.width));
      } else {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        fb.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(full.data() + c), sizeof(float) * channels,
                                       sizeof(float) * channels * map.width));
      }
    }
    write_file_atomically(path, [&](const std::filesystem::path& temporary) {
      Imf::OutputFile file(temporary.c_str(), header);
      file.setFrameBuffer(fb);
      file.writePixels(map.height);
    });
  } catch (const std::exception& e) {
    throw EnvMapError(path, std::string("cannot write OpenEXR: ") + e.what());
  }
}

EnvMap resample(const EnvMap& map, int width, int height) {
  EnvMap out(width, height);
  std::vector<glm::dvec3> sum(out.texels.size(), glm::dvec3(0.0));
  std::vector<double> weight(out.texels.size(), 0.0);
  for (int y = 0; y < map.height; ++y) {
    const int ty = std::min(height - 1, static_cast<int>((y + 0.5) * height / map.height));
    const double omega = map.solid_angle(y);
    for (int x = 0; x < map.width; ++x) {
      const int tx = std::min(width - 1, static_cast<int>((x + 0.5) * width / map.width));
      const size_t t = static_cast<size_t>(ty) * width + tx;
      sum[t] += omega * glm::dvec3(map.at(x, y));
      weight[t] += omega;
    }
  }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t t = static_cast<size_t>(y) * width + x;
      out.texels[t] = weight[t] > 0.0 ? glm::vec3(sum[t] / weight[t]) : glm::vec3(map.lookup(out.direction(x, y)));
    }
  return out;
}

glm::dvec3 mean_radiance(const EnvMap& map) {
  glm::dvec3 sum(0.0);
  double total = 0.0;
  for (int y = 0; y < map.height; ++y) {
    glm::dvec3 row(0.0);
    for (int x = 0; x < map.width; ++x) row += glm::dvec3(map.at(x, y));
    sum += map.solid_angle(y) * row;
    total += map.solid_angle(y) * map.width;
  }
  return sum / total;
}

}  // namespace weft
