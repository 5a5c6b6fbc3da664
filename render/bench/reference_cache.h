#pragma once
// Cached reference renders for the bench. A render is stored under a key that hashes
// everything that produced it (scene file and the mesh data it reads, fabric file, SGs,
// render settings and kReferenceCodeVersion), so changed inputs miss and stale files are
// never read; bump kReferenceCodeVersion when the reference or the model changes.
// File: "WEFTREF1", width, height (int32), then width·height RGB float64 and kind bytes.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "reference/scene_render.h"

namespace weft::bench {

inline constexpr const char* kReferenceCodeVersion = "weft-reference-2026-11-27";

// FNV-1a 64 over a sequence of byte strings (each length-prefixed, so boundaries count).
class InputHash {
public:
  InputHash& add(std::string_view bytes);
  InputHash& add_file(const std::filesystem::path& file);  // its contents; throws if unreadable
  InputHash& add_number(double x);
  std::string hex() const;

private:
  uint64_t h_ = 1469598103934665603ull;
  void mix(const void* p, size_t n);
};

struct CachedReference {
  Image image;
  std::vector<PixelKind> kinds;
};

std::optional<CachedReference> load_reference(const std::filesystem::path& file);
void store_reference(const std::filesystem::path& file, const CachedReference& r);  // atomic rename

}  // namespace weft::bench
