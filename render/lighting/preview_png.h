#pragma once
// A picture a person can look at: environment maps side by side, tone mapped to 8-bit sRGB PNG.
#include <filesystem>
#include <span>

#include "lighting/env_map.h"

namespace weft {

// Writes the maps left to right (each resampled to width × width/2, 4-pixel grey gaps) with one
// exposure for all, chosen from the first map (its mean luminance maps to 0.25 before the
// 1 − e^{−x} shoulder), then the sRGB transfer curve. Throws EnvMapError on failure.
void write_preview_png(const std::filesystem::path& path, std::span<const EnvMap> maps, int width = 512);

}  // namespace weft
