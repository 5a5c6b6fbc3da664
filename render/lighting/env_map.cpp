#include "lighting/env_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCheckFile.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <Imath/half.h>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
// Larger maps than this are refused rather than risking an out-of-memory crash.
constexpr long long kMaxTexels = 1LL << 27;  // e.g. 16384 × 8192
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

EnvMap load_env_map(const std::filesystem::path& path, NonFinitePolicy policy, EnvMapRepairs* repairs) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw EnvMapError(path, "file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw EnvMapError(path, "not a regular file");

  EnvMap map;
  try {
    // OpenEXR's own robustness check (the one its fuzzers use) first: a truncated or corrupt file
    // is reported here rather than half-read.
    if (Imf::checkOpenEXRFile(path.c_str(), /*reduceMemory=*/true, /*reduceTime=*/true))
      throw EnvMapError(path, "corrupt or truncated OpenEXR file");
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i dw = header.dataWindow();
    const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
    const long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
    if (w < 2 || h < 1) throw EnvMapError(path, "image is empty (" + std::to_string(w) + "×" + std::to_string(h) + ")");
    if (w * h > kMaxTexels)
      throw EnvMapError(path, "image " + std::to_string(w) + "×" + std::to_string(h) + " is too large");
    const Imf::ChannelList& channels = header.channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool grey = channels.findChannel("Y") != nullptr;
    if (!rgb && !grey) throw EnvMapError(path, "no R,G,B (or Y) channels");

    map = EnvMap(static_cast<int>(w), static_cast<int>(h));
    // Slices point at a virtual origin so that the data window's first texel lands at texels[0].
    char* base = reinterpret_cast<char*>(map.texels.data()) -
                 (static_cast<ptrdiff_t>(dw.min.x) + static_cast<ptrdiff_t>(dw.min.y) * w) *
                     static_cast<ptrdiff_t>(sizeof(glm::vec3));
    const size_t xs = sizeof(glm::vec3), ys = sizeof(glm::vec3) * static_cast<size_t>(w);
    Imf::FrameBuffer fb;
    if (rgb) {
      fb.insert("R", Imf::Slice(Imf::FLOAT, base + 0 * sizeof(float), xs, ys, 1, 1, 0.0));
      fb.insert("G", Imf::Slice(Imf::FLOAT, base + 1 * sizeof(float), xs, ys, 1, 1, 0.0));
      fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys, 1, 1, 0.0));
    } else {
      fb.insert("Y", Imf::Slice(Imf::FLOAT, base, xs, ys, 1, 1, 0.0));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    if (!rgb)
      for (auto& t : map.texels) t = glm::vec3(t.r);
  } catch (const EnvMapError&) {
    throw;
  } catch (const std::exception& e) {
    throw EnvMapError(path, std::string("cannot read OpenEXR: ") + e.what());
  }

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
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(map.height);
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
